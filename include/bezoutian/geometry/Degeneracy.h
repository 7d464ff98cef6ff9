// Warnings about degenerate input: curves and patches that are points, collapsed rows/columns of a
// control net, repeated control points, weights of mixed sign and control points at infinity.
//
// These are not errors: a collapsed boundary row is how the Utah teapot closes its lid and bottom, and
// mixed-sign weights are legal. But each of them breaks an assumption of some algorithm (a regular
// parametrization, a well-defined normal, the convex hull property, a denominator without zeros), so
// callers report them. Points are compared projectively, exactly: homogeneous control points are equal
// when proportional, so equal Cartesian points with different weights count as equal.
#ifndef BEZOUTIAN_GEOMETRY_DEGENERACY_H
#define BEZOUTIAN_GEOMETRY_DEGENERACY_H

#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/arithmetic/exact_text.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/number_utils.h>

#include <cstddef>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace bezoutian {

namespace internal {

/// Exact text of a number: "p/q" for Rational, the number type's own output otherwise.
template <class FT>
std::string number_text(const FT& x) {
  if constexpr (std::is_same<FT, Rational>::value) {
    return io::to_exact_string(x);
  } else {
    std::ostringstream s;
    s << x;
    return s.str();
  }
}

/// True if the homogeneous points a and b are proportional (the same projective point).
template <class H>
bool same_projective_point(const H& a, const H& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j)
      if (a[i] * b[j] != a[j] * b[i]) return false;
  return true;
}

/// "(x, y, z)" of a homogeneous point (w, wx, wy, wz), or "infinity in direction (wx, wy, wz)" if w = 0.
template <class H>
std::string point_text(const H& h) {
  const bool infinite = CGAL::is_zero(h[0]);
  std::string r = infinite ? "infinity in direction (" : "(";
  for (std::size_t k = 1; k < h.size(); ++k)
    r += (k > 1 ? ", " : "") + number_text(infinite ? h[k] : h[k] / h[0]);
  return r + ")";
}

template <class Range>
void weight_sign_warnings(const Range& weights, const std::string& object, std::vector<std::string>& out) {
  std::size_t positive = 0, negative = 0, zero = 0;
  for (const auto& w : weights) {
    const int s = CGAL::sign(w);
    positive += s > 0;
    negative += s < 0;
    zero += s == 0;
  }
  if (positive > 0 && negative > 0)
    out.push_back("the weights of the " + object + " have mixed signs (" + std::to_string(positive) + " positive, " +
                  std::to_string(negative) + " negative): check for poles, the denominator may vanish inside the domain");
  if (zero > 0)
    out.push_back(std::to_string(zero) + " control point" + (zero > 1 ? "s" : "") + " of the " + object +
                  " at infinity (weight 0): check for poles; the convex hull property does not hold");
}

} // namespace internal

/// \brief Warnings about a degenerate curve (empty if none); never throws.
///
/// Reported: all control points equal (the curve is a point), consecutive equal control points (the
/// derivative vanishes at an end if the pair is at that end: C'(0) = n w_1/w_0 (P_1 - P_0)), weights of
/// mixed signs (check for poles) and control points at infinity.
template <class FT, int D>
std::vector<std::string> degeneracy_warnings(const Rational_bezier_curve<FT, D>& c) {
  std::vector<std::string> out;
  try {
    const auto& h = c.homogeneous_control_points();
    bool all_equal = true;
    for (std::size_t i = 1; i < h.size(); ++i) all_equal = all_equal && internal::same_projective_point(h[0], h[i]);
    if (all_equal) {
      out.push_back("the curve is a single point: all " + std::to_string(h.size()) + " control points equal " +
                    internal::point_text(h[0]));
    } else {
      for (std::size_t i = 0; i + 1 < h.size(); ++i)
        if (internal::same_projective_point(h[i], h[i + 1])) {
          std::string w = "control points " + std::to_string(i) + " and " + std::to_string(i + 1) + " coincide at " +
                          internal::point_text(h[i]);
          if (i == 0) w += "; the derivative vanishes at t = 0";
          if (i + 2 == h.size()) w += "; the derivative vanishes at t = 1";
          out.push_back(w);
        }
    }
    internal::weight_sign_warnings(c.weights(), "curve", out);
  } catch (const std::exception& e) {
    out.push_back(std::string("the degeneracy check of the curve did not complete: ") + e.what());
  }
  return out;
}

/// Indices i of the rows of the control net whose control points are all equal (row i runs along v at u = i/m).
template <class FT>
std::vector<std::size_t> collapsed_rows(const Rational_bezier_patch<FT>& p) {
  std::vector<std::size_t> r;
  const auto& net = p.homogeneous_net();
  for (std::size_t i = 0; i < net.size(); ++i) {
    bool equal = net[i].size() > 1;
    for (std::size_t j = 1; j < net[i].size() && equal; ++j) equal = internal::same_projective_point(net[i][0], net[i][j]);
    if (equal) r.push_back(i);
  }
  return r;
}

/// Indices j of the columns of the control net whose control points are all equal.
template <class FT>
std::vector<std::size_t> collapsed_columns(const Rational_bezier_patch<FT>& p) {
  std::vector<std::size_t> r;
  const auto& net = p.homogeneous_net();
  for (std::size_t j = 0; j < net[0].size(); ++j) {
    bool equal = net.size() > 1;
    for (std::size_t i = 1; i < net.size() && equal; ++i) equal = internal::same_projective_point(net[0][j], net[i][j]);
    if (equal) r.push_back(j);
  }
  return r;
}

/// \brief Warnings about a degenerate patch (empty if none); never throws.
///
/// Reported: all control points equal (the patch is a point); collapsed rows and columns, naming the
/// index and the point (a collapsed boundary row/column is a boundary edge shrunk to a point, where the
/// normal is undefined -- e.g. the teapot lid rows 0 and 2 and bottom row 0); rows all equal (the patch
/// does not depend on u) or columns all equal; consecutive equal control points in a row or column
/// outside collapsed rows/columns; weights of mixed signs (check for poles); control points at infinity.
template <class FT>
std::vector<std::string> degeneracy_warnings(const Rational_bezier_patch<FT>& p) {
  std::vector<std::string> out;
  try {
    const auto& net = p.homogeneous_net();
    const std::size_t m = net.size() - 1, n = net[0].size() - 1;
    bool all_equal = true;
    for (const auto& row : net)
      for (const auto& h : row) all_equal = all_equal && internal::same_projective_point(net[0][0], h);
    if (all_equal) {
      out.push_back("the patch is a single point: all " + std::to_string((m + 1) * (n + 1)) + " control points equal " +
                    internal::point_text(net[0][0]));
    } else {
      const std::vector<std::size_t> rows = collapsed_rows(p), columns = collapsed_columns(p);
      std::vector<bool> row_collapsed(m + 1, false), column_collapsed(n + 1, false);
      for (std::size_t i : rows) {
        row_collapsed[i] = true;
        std::string w = "row " + std::to_string(i) + " of the control net is collapsed to the point " +
                        internal::point_text(net[i][0]);
        if (i == 0 || i == m)
          w += std::string(": the boundary u = ") + (i == 0 ? "0" : "1") + " is a single point (the normal is undefined there)";
        else
          w += " (an interior row)";
        out.push_back(w);
      }
      for (std::size_t j : columns) {
        column_collapsed[j] = true;
        std::string w = "column " + std::to_string(j) + " of the control net is collapsed to the point " +
                        internal::point_text(net[0][j]);
        if (j == 0 || j == n)
          w += std::string(": the boundary v = ") + (j == 0 ? "0" : "1") + " is a single point (the normal is undefined there)";
        else
          w += " (an interior column)";
        out.push_back(w);
      }
      // every row proportional to row 0 with one factor per row: Phi does not depend on u (columns: on v)
      auto lines_equal = [&](bool rows_of_net) {
        const std::size_t count = rows_of_net ? m : n, length = rows_of_net ? n : m;
        auto at = [&](std::size_t line, std::size_t k) -> const auto& { return rows_of_net ? net[line][k] : net[k][line]; };
        if (count == 0) return false;
        std::size_t pivot = 0;  // a nonzero homogeneous coordinate of line 0 fixes the factor
        int coordinate = -1;
        for (std::size_t k = 0; k <= length && coordinate < 0; ++k)
          for (int c = 0; c < 4 && coordinate < 0; ++c)
            if (!CGAL::is_zero(at(0, k)[c])) {
              pivot = k;
              coordinate = c;
            }
        for (std::size_t a = 1; a <= count; ++a) {
          const FT x0 = at(0, pivot)[coordinate], xa = at(a, pivot)[coordinate];
          for (std::size_t k = 0; k <= length; ++k)
            for (int c = 0; c < 4; ++c)
              if (at(a, k)[c] * x0 != at(0, k)[c] * xa) return false;
        }
        return true;
      };
      if (lines_equal(true)) out.push_back("all rows of the control net are equal: the patch does not depend on u (it is a curve)");
      if (lines_equal(false)) out.push_back("all columns of the control net are equal: the patch does not depend on v (it is a curve)");
      auto name = [](std::size_t i, std::size_t j) { return "[" + std::to_string(i) + "][" + std::to_string(j) + "]"; };
      for (std::size_t i = 0; i <= m; ++i)
        for (std::size_t j = 0; j <= n; ++j) {
          if (j < n && !row_collapsed[i] && internal::same_projective_point(net[i][j], net[i][j + 1]))
            out.push_back("control points " + name(i, j) + " and " + name(i, j + 1) + " coincide at " +
                          internal::point_text(net[i][j]));
          if (i < m && !column_collapsed[j] && internal::same_projective_point(net[i][j], net[i + 1][j]))
            out.push_back("control points " + name(i, j) + " and " + name(i + 1, j) + " coincide at " +
                          internal::point_text(net[i][j]));
        }
    }
    std::vector<FT> weights;
    for (const auto& row : net)
      for (const auto& h : row) weights.push_back(h[0]);
    internal::weight_sign_warnings(weights, "patch", out);
  } catch (const std::exception& e) {
    out.push_back(std::string("the degeneracy check of the patch did not complete: ") + e.what());
  }
  return out;
}

} // namespace bezoutian

#endif // BEZOUTIAN_GEOMETRY_DEGENERACY_H

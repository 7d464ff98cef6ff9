// Exact pole detection for rational patches: a rational patch is valid on its parameter box only if its
// weight polynomial W = Phi_0 does not vanish there (buse-elkadi-galligo-2008 eq. (1) divides by Phi_0).
#ifndef BEZOUTIAN_GEOMETRY_WEIGHT_VALIDITY_H
#define BEZOUTIAN_GEOMETRY_WEIGHT_VALIDITY_H

#include <bezoutian/geometry/Bernstein_basis.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/arithmetic/exact_text.h>

#include <CGAL/number_utils.h>

#include <sstream>
#include <string>
#include <vector>

namespace bezoutian {

/// Result of the pole search on a parameter box.
template <class FT>
struct Pole_report {
  bool has_pole = false;       ///< a zero of W in the box is proved (or could not be excluded, see `proved`)
  bool proved = true;          ///< false: W could not be shown nonzero at the resolution limit (rejected anyway)
  FT u0, u1, v0, v1;           ///< a box containing a zero of W (meaningful when has_pole)
  std::string describe() const {
    std::ostringstream s;
    s << (proved ? "the weight polynomial vanishes in the parameter box [" : "the weight polynomial may vanish (could not be excluded) in [")
      << u0 << ", " << u1 << "] x [" << v0 << ", " << v1 << "]";
    return s.str();
  }
};

namespace internal {

template <class FT>
using Grid = std::vector<std::vector<FT>>;

// Bernstein grid of W restricted to [0,1/2] or [1/2,1] along the rows (u) direction.
template <class FT>
std::pair<Grid<FT>, Grid<FT>> split_rows_half(const Grid<FT>& g) {
  Grid<FT> a(g.size(), std::vector<FT>(g[0].size())), b = a;
  for (std::size_t j = 0; j < g[0].size(); ++j) {
    std::vector<FT> col;
    for (const auto& row : g) col.push_back(row[j]);
    auto lr = de_casteljau_split(col, FT(1, 2));
    for (std::size_t i = 0; i < g.size(); ++i) {
      a[i][j] = lr.first[i];
      b[i][j] = lr.second[i];
    }
  }
  return {a, b};
}

template <class FT>
std::pair<Grid<FT>, Grid<FT>> split_columns_half(const Grid<FT>& g) {
  Grid<FT> a, b;
  for (const auto& row : g) {
    auto lr = de_casteljau_split(row, FT(1, 2));
    a.push_back(lr.first);
    b.push_back(lr.second);
  }
  return {a, b};
}

// Recursive exclusion: all Bernstein coefficients of one strict sign => W has no zero on the box
// (W is a convex combination of them). A zero corner value or two corner values of opposite signs prove a
// zero (intermediate value theorem on the box, which is connected).
template <class FT>
bool find_pole(const Grid<FT>& g, const FT& u0, const FT& u1, const FT& v0, const FT& v1, int depth,
               Pole_report<FT>& out) {
  int pos = 0, neg = 0;
  for (const auto& row : g)
    for (const FT& c : row) {
      const int s = CGAL::sign(c);
      pos += s > 0;
      neg += s < 0;
    }
  const std::size_t total = g.size() * g[0].size();
  if (std::size_t(pos) == total || std::size_t(neg) == total) return false;
  const int corners[4] = {CGAL::sign(g.front().front()), CGAL::sign(g.front().back()), CGAL::sign(g.back().front()),
                          CGAL::sign(g.back().back())};
  bool zero_proved = false;
  for (int s : corners) zero_proved |= (s == 0);
  for (int s : corners)
    for (int t : corners) zero_proved |= (s * t < 0);
  if (zero_proved || depth == 0) {
    out.has_pole = true;
    out.proved = zero_proved;
    out.u0 = u0, out.u1 = u1, out.v0 = v0, out.v1 = v1;
    return true;
  }
  const FT um = (u0 + u1) / FT(2), vm = (v0 + v1) / FT(2);
  auto rows = split_rows_half(g);
  for (int a = 0; a < 2; ++a) {
    auto cols = split_columns_half(a == 0 ? rows.first : rows.second);
    const FT& ua = a == 0 ? u0 : um;
    const FT& ub = a == 0 ? um : u1;
    if (find_pole(cols.first, ua, ub, v0, vm, depth - 1, out)) return true;
    if (find_pole(cols.second, ua, ub, vm, v1, depth - 1, out)) return true;
  }
  return false;
}

} // namespace internal

/// Searches the zero set of the weight polynomial of `patch` on [u0,u1] x [v0,v1] (default [0,1]^2) by exact
/// Bernstein subdivision. Either proves W != 0 on the box (has_pole == false), or returns a sub-box where W
/// provably vanishes, or (proved == false) a sub-box of width (u1-u0) 2^-max_depth on which W could not be
/// shown nonzero (a tangential zero such as W = (u - 1/3)^2 + (v - 1/3)^2 ends here).
template <class FT>
Pole_report<FT> find_weight_zero(const Rational_bezier_patch<FT>& patch, const FT& u0 = FT(0), const FT& u1 = FT(1),
                                 const FT& v0 = FT(0), const FT& v1 = FT(1), int max_depth = 12) {
  Pole_report<FT> report;
  if (!patch.is_rational() && !CGAL::is_zero(patch.weight(0, 0))) return report;
  Rational_bezier_patch<FT> sub = patch.restriction(u0, u1, v0, v1);
  internal::Grid<FT> g;
  for (const auto& row : sub.homogeneous_net()) {
    g.emplace_back();
    for (const auto& h : row) g.back().push_back(h[0]);
  }
  internal::find_pole(g, u0, u1, v0, v1, max_depth, report);
  return report;
}

/// Throws Invalid_input naming the box if the weight of `patch` vanishes (or cannot be excluded to vanish)
/// on [0,1]^2.
template <class FT>
void check_no_pole(const Rational_bezier_patch<FT>& patch) {
  Pole_report<FT> r = find_weight_zero(patch);
  if (r.has_pole) throw Invalid_input("pole in the patch domain: " + r.describe());
}

/// Throws Invalid_input if the weight polynomial W(t) of `curve` has a real root in [0,1], naming the root by an
/// isolating interval (exact rationals, proved to contain exactly that root). Weights of one strict sign prove
/// W != 0 at once (W is a convex combination of them); otherwise the roots of W on [0,1] are isolated exactly.
inline void check_no_pole(const Rational_bezier_curve<Rational, 2>& curve);
inline void check_no_pole(const Rational_bezier_curve<Rational, 3>& curve);

namespace internal {
template <int D>
void check_curve_pole(const Rational_bezier_curve<Rational, D>& curve) {
  const auto w = curve.weights();
  bool pos = true, neg = true;
  for (const Rational& x : w) {
    pos = pos && CGAL::sign(x) > 0;
    neg = neg && CGAL::sign(x) < 0;
  }
  if (pos || neg) return;
  const Polynomial_1<Rational> W = curve.power_form()[0];
  std::vector<Isolated_root> roots = isolate_real_roots(W, Rational(0), Rational(1));
  if (roots.empty()) return;
  const Algebraic_real& r = roots.front().root;
  std::ostringstream s;
  s << "pole in the curve domain: the weight polynomial W(t) = " << io::polynomial_to_string(W, "t") << " vanishes at t ";
  if (r.is_rational())
    s << "= " << r.rational_value();
  else
    s << "in the isolating interval [" << r.lower() << ", " << r.upper() << "] (t ~ " << r.to_double() << ")";
  if (roots.size() > 1) s << " (and at " << roots.size() - 1 << " more parameters in [0,1])";
  throw Invalid_input(s.str());
}
} // namespace internal

inline void check_no_pole(const Rational_bezier_curve<Rational, 2>& curve) { internal::check_curve_pole(curve); }
inline void check_no_pole(const Rational_bezier_curve<Rational, 3>& curve) { internal::check_curve_pole(curve); }

} // namespace bezoutian

#endif // BEZOUTIAN_GEOMETRY_WEIGHT_VALIDITY_H

// A proof that a patch has no self-intersection, without elimination: its projection to a plane is injective.
//
// Theorem. Let Phi : [0,1]^2 -> R^3 be a rational patch with positive weights, pi a linear map R^3 -> R^2, and
// f = pi o Phi. Suppose (a) the Jacobian determinant of f does not vanish on the open square, and (b) f restricted to
// the boundary of the square is injective, except that each side which Phi collapses to one point (a pole edge, as on
// a sphere octant) is one point. Then f, and so Phi, is injective on the square, the points of a collapsed side
// excepted. Proof: contracting the collapsed sides, the square stays a closed disk Q and f(dQ) is a Jordan curve C.
// For p not on C, every preimage of p is interior, where det df has one sign, so the number of preimages is the
// degree of f over p: the winding number of C about p, 0 or 1. An interior point q with f(q) on C is impossible: f
// is open at q, so points near f(q) outside C (winding number 0) would have a preimage. Hence f is injective on Q.
//
// Both hypotheses are decided exactly. (a) With f = (X/W, Y/W) for the homogeneous projected coordinates, det df =
// J / W^3 with J = det [W X Y; W_u X_u Y_u; W_v X_v Y_v]. The factors u, 1 - u, v, 1 - v of J (a side where J
// vanishes identically: a collapsed side, or a side along which the surface is parallel to the projection
// direction) are divided out in the Bernstein basis, and the rest is proved to have one strict sign on the closed
// square from its Bernstein coefficients, on sub-squares of a de Casteljau subdivision if need be. (b) The
// projected sides are plane rational Bezier curves: each is proved free of self-intersections
// (self_intersections, or strict monotonicity along a straight side), two sides that do not share a corner are
// proved disjoint and two that do are proved to meet only there (intersect_curves, du-1989 ch. 4).
//
// Several projections are tried: along the patch's mean normal (the cross product of its mean u and v directions),
// then along the coordinate axes (a height field z = f(x, y) is proved by the projection to the xy-plane).
#ifndef BEZOUTIAN_INTERSECTION_PATCH_INJECTIVITY_H
#define BEZOUTIAN_INTERSECTION_PATCH_INJECTIVITY_H

#include <bezoutian/arithmetic/exact_text.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/geometry/Bernstein_basis.h>
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/intersection/Curve_intersection.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <exception>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {

/// Outcome of prove_injective().
struct Injectivity_proof {
  bool proved = false;
  /// The direction along which the patch was projected (when proved).
  std::array<Rational, 3> direction{};
  /// Sides (0: v = 0, 1: u = 1, 2: v = 1, 3: u = 0) that the patch collapses to one point: their points are the
  /// only distinct parameter points with one image.
  std::vector<int> collapsed_sides;
  /// When proved, the proof in one line; otherwise why each projection failed.
  std::string reason;
};

namespace internal {

using Rational_grid = std::vector<std::vector<Rational>>;  // g[i][j]: coefficient of u^i v^j (or Bernstein i, j)

inline Rational_grid grid_of(const Polynomial_2<Rational>& p, int m, int n) {
  Rational_grid g(std::size_t(m + 1), std::vector<Rational>(std::size_t(n + 1), Rational(0)));
  if (CGAL::is_zero(p)) return g;
  for (int j = 0; j <= p.degree() && j <= n; ++j)
    for (int i = 0; i <= p[j].degree() && i <= m; ++i) g[std::size_t(i)][std::size_t(j)] = p[j][i];
  return g;
}

inline Rational_grid grid_product(const Rational_grid& a, const Rational_grid& b) {
  const std::size_t m = a.size() + b.size() - 1, n = a[0].size() + b[0].size() - 1;
  Rational_grid c(m, std::vector<Rational>(n, Rational(0)));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < a[0].size(); ++j) {
      if (CGAL::is_zero(a[i][j])) continue;
      for (std::size_t k = 0; k < b.size(); ++k)
        for (std::size_t l = 0; l < b[0].size(); ++l) c[i + k][j + l] += a[i][j] * b[k][l];
    }
  return c;
}

inline void grid_add(Rational_grid& acc, const Rational_grid& g, const Rational& factor) {
  for (std::size_t i = 0; i < g.size(); ++i)
    for (std::size_t j = 0; j < g[0].size(); ++j) acc[i][j] += factor * g[i][j];
}

// Partial derivative of a power-basis grid in u (direction 0) or v (direction 1), same shape.
inline Rational_grid grid_derivative(const Rational_grid& g, int direction) {
  Rational_grid d(g.size(), std::vector<Rational>(g[0].size(), Rational(0)));
  for (std::size_t i = 0; i < g.size(); ++i)
    for (std::size_t j = 0; j < g[0].size(); ++j) {
      if (direction == 0 && i + 1 < g.size()) d[i][j] = Rational(int(i + 1)) * g[i + 1][j];
      if (direction == 1 && j + 1 < g[0].size()) d[i][j] = Rational(int(j + 1)) * g[i][j + 1];
    }
  return d;
}

// Bernstein coefficients on [0,1]^2 of a power-basis grid (its own bi-degree).
inline Rational_grid bernstein_grid(const Rational_grid& g) {
  const int m = int(g.size()) - 1, n = int(g[0].size()) - 1;
  Rational_grid a = g;
  for (int j = 0; j <= n; ++j) {
    std::vector<Rational> col(std::size_t(m + 1));
    for (int i = 0; i <= m; ++i) col[std::size_t(i)] = g[std::size_t(i)][std::size_t(j)];
    const std::vector<Rational> b = power_to_bernstein(Polynomial_1<Rational>(col.begin(), col.end()), m);
    for (int i = 0; i <= m; ++i) a[std::size_t(i)][std::size_t(j)] = b[std::size_t(i)];
  }
  for (int i = 0; i <= m; ++i) {
    const std::vector<Rational>& row = a[std::size_t(i)];
    a[std::size_t(i)] = power_to_bernstein(Polynomial_1<Rational>(row.begin(), row.end()), n);
  }
  return a;
}

// Divides the Bernstein grid b by the factors u, 1 - u, v, 1 - v of its polynomial, as often as they divide it (a
// factor divides iff the boundary row or column of coefficients is zero). B_{i,p} = (p/i) u B_{i-1,p-1} and
// B_{i,p} = (p/(p-i)) (1-u) B_{i,p-1} give the quotient's coefficients exactly.
inline void divide_side_factors(Rational_grid& b) {
  auto zero_row = [&](std::size_t i) {
    for (const Rational& x : b[i])
      if (!CGAL::is_zero(x)) return false;
    return true;
  };
  auto zero_column = [&](std::size_t j) {
    for (const auto& row : b)
      if (!CGAL::is_zero(row[j])) return false;
    return true;
  };
  for (bool again = true; again;) {
    again = false;
    const std::size_t p = b.size() - 1, q = b[0].size() - 1;
    if (p >= 1 && (zero_row(0) || zero_row(p))) {
      const bool low = zero_row(0);
      Rational_grid c(p, std::vector<Rational>(q + 1));
      for (std::size_t i = 0; i < p; ++i)
        for (std::size_t j = 0; j <= q; ++j)
          c[i][j] = low ? b[i + 1][j] * Rational(int(p)) / Rational(int(i + 1)) : b[i][j] * Rational(int(p)) / Rational(int(p - i));
      b = std::move(c);
      again = true;
      continue;
    }
    if (q >= 1 && (zero_column(0) || zero_column(q))) {
      const bool low = zero_column(0);
      Rational_grid c(p + 1, std::vector<Rational>(q));
      for (std::size_t i = 0; i <= p; ++i)
        for (std::size_t j = 0; j < q; ++j)
          c[i][j] = low ? b[i][j + 1] * Rational(int(q)) / Rational(int(j + 1)) : b[i][j] * Rational(int(q)) / Rational(int(q - j));
      b = std::move(c);
      again = true;
    }
  }
}

// One strict sign of the polynomial with Bernstein grid b on the closed square, proved on the sub-squares of a
// de Casteljau subdivision down to `depth` levels; 0 if not proved.
inline int strict_sign_on_square(const Rational_grid& b, int depth) {
  int pos = 0, neg = 0;
  for (const auto& row : b)
    for (const Rational& x : row) {
      const int s = CGAL::sign(x);
      if (s > 0) ++pos;
      if (s < 0) ++neg;
    }
  const std::size_t total = b.size() * b[0].size();
  if (std::size_t(pos) == total) return 1;
  if (std::size_t(neg) == total) return -1;
  const int corner = CGAL::sign(b[0][0]);  // the value at (0, 0): a sign change inside is possible
  if (depth == 0 || corner == 0) return 0;
  // split in u at 1/2 (rows), then each half in v at 1/2 (columns): four sub-squares
  auto split_rows = [](const Rational_grid& g) {
    std::vector<std::vector<Rational>> lo(g.size()), hi(g.size());
    Rational_grid w = g;
    const std::size_t p = g.size() - 1;
    for (std::size_t r = 0; r <= p; ++r) {
      lo[r] = w[0];
      hi[p - r] = w[p - r];
      for (std::size_t i = 0; i + r < p; ++i)
        for (std::size_t j = 0; j < g[0].size(); ++j) w[i][j] = (w[i][j] + w[i + 1][j]) / Rational(2);
    }
    return std::make_pair(lo, hi);
  };
  auto transpose = [](const Rational_grid& g) {
    Rational_grid t(g[0].size(), std::vector<Rational>(g.size()));
    for (std::size_t i = 0; i < g.size(); ++i)
      for (std::size_t j = 0; j < g[0].size(); ++j) t[j][i] = g[i][j];
    return t;
  };
  const auto halves = split_rows(b);
  int sign = 0;
  for (const Rational_grid* h : {&halves.first, &halves.second}) {
    const auto quarters = split_rows(transpose(*h));
    for (const Rational_grid* q : {&quarters.first, &quarters.second}) {
      const int s = strict_sign_on_square(transpose(*q), depth - 1);
      if (s == 0 || (sign != 0 && s != sign)) return 0;
      sign = s;
    }
  }
  return sign;
}

// The parameter corners of side k of the square at its curve parameter 0 and 1 (boundary_curve order).
inline std::array<std::array<int, 2>, 2> side_corners(int k) {
  switch (k) {
    case 0: return {{{0, 0}, {1, 0}}};
    case 1: return {{{1, 0}, {1, 1}}};
    case 2: return {{{0, 1}, {1, 1}}};
    default: return {{{0, 0}, {0, 1}}};
  }
}

// A side of the patch that is one 3D point: its affine control points are all equal.
inline bool side_collapsed(const Rational_bezier_patch<Rational>& P, int k) {
  const auto c = P.boundary_curve<Rational_bezier_curve_3<Rational>>(k);
  for (std::size_t i = 1; i < c.number_of_control_points(); ++i)
    if (c.control_point(i) != c.control_point(0)) return false;
  return true;
}

// A straight plane curve (all control points on one line) that is injective: its coordinate along the line is
// strictly monotone, i.e. the numerator N' W - N W' of its derivative has Bernstein coefficients of one sign, not
// all zero. Returns 1 if proved, 0 if the curve is straight but not proved, -1 if it is not straight.
inline int straight_curve_injective(const Rational_bezier_curve_2<Rational>& c) {
  const auto p0 = c.control_point(0);
  std::size_t far = 0;
  for (std::size_t i = 1; i < c.number_of_control_points(); ++i)
    if (c.control_point(i) != p0) far = i;
  if (far == 0) return 0;
  const auto p1 = c.control_point(far);
  const Rational dx = p1[0] - p0[0], dy = p1[1] - p0[1];
  for (std::size_t i = 0; i < c.number_of_control_points(); ++i) {
    const auto p = c.control_point(i);
    if (!CGAL::is_zero(dx * (p[1] - p0[1]) - dy * (p[0] - p0[0]))) return -1;
  }
  const auto f = c.power_form();  // (W, X, Y)
  const Polynomial_1<Rational> N = f[1] * dx + f[2] * dy;
  const Polynomial_1<Rational> d = CGAL::differentiate(N) * f[0] - N * CGAL::differentiate(f[0]);
  if (CGAL::is_zero(d)) return 0;
  const std::vector<Rational> b = power_to_bernstein(d, std::max(d.degree(), 0));
  bool pos = false, neg = false;
  for (const Rational& x : b) pos = pos || CGAL::is_positive(x), neg = neg || CGAL::is_negative(x);
  return pos && neg ? 0 : 1;
}

// Is the projected side curve free of self-intersections (proved)?
inline bool side_curve_simple(const Rational_bezier_curve_2<Rational>& c, std::string& why) {
  const int straight = straight_curve_injective(c);
  if (straight >= 0) {
    if (straight == 0) why = "a straight side is not proved monotone";
    return straight == 1;
  }
  try {
    const Curve_intersection_result r = self_intersections(c);
    if (r.points.empty() && r.overlaps.empty()) return true;
    why = "a side crosses itself in the projection";
  } catch (const std::exception& e) {
    why = std::string("the self-intersections of a side are not decided (") + e.what() + ")";
  }
  return false;
}

inline std::string direction_text(const std::array<Rational, 3>& d) {
  return "(" + io::to_exact_string(d[0]) + ", " + io::to_exact_string(d[1]) + ", " + io::to_exact_string(d[2]) + ")";
}

inline std::array<Rational, 3> cross(const std::array<Rational, 3>& a, const std::array<Rational, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Tries the projection along d; on failure `why` says which hypothesis failed.
inline bool injective_along(const Rational_bezier_patch<Rational>& P, const std::array<Rational, 3>& d,
                            const std::vector<int>& collapsed, std::string& why) {
  // a basis (e1, e2) of the plane orthogonal to d: e1 = d x (the axis least aligned with d), e2 = d x e1
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (CGAL::abs(d[std::size_t(k)]) < CGAL::abs(d[std::size_t(axis)])) axis = k;
  std::array<Rational, 3> a{Rational(0), Rational(0), Rational(0)};
  a[std::size_t(axis)] = Rational(1);
  const std::array<Rational, 3> e1 = cross(d, a), e2 = cross(d, e1);

  // (a) the Jacobian J of the projection, side factors divided out, has one strict sign on the square
  const auto f = P.power_form();
  const int m = P.degree_u(), n = P.degree_v();
  const Rational_grid W = grid_of(f[0], m, n);
  Rational_grid X(std::size_t(m + 1), std::vector<Rational>(std::size_t(n + 1), Rational(0))), Y = X;
  for (int k = 0; k < 3; ++k) {
    grid_add(X, grid_of(f[std::size_t(k + 1)], m, n), e1[std::size_t(k)]);
    grid_add(Y, grid_of(f[std::size_t(k + 1)], m, n), e2[std::size_t(k)]);
  }
  const std::array<Rational_grid, 3> F{W, X, Y};
  std::array<Rational_grid, 3> Fu, Fv;
  for (int k = 0; k < 3; ++k) Fu[std::size_t(k)] = grid_derivative(F[std::size_t(k)], 0), Fv[std::size_t(k)] = grid_derivative(F[std::size_t(k)], 1);
  Rational_grid J(std::size_t(3 * m + 1), std::vector<Rational>(std::size_t(3 * n + 1), Rational(0)));
  static const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (int p = 0; p < 6; ++p)  // det [F; Fu; Fv] by the Leibniz formula
    grid_add(J, grid_product(grid_product(F[std::size_t(perm[p][0])], Fu[std::size_t(perm[p][1])]), Fv[std::size_t(perm[p][2])]),
             Rational(p < 3 ? 1 : -1));
  bool zero = true;
  for (const auto& row : J)
    for (const Rational& x : row) zero = zero && CGAL::is_zero(x);
  if (zero) {
    why = "the projection is degenerate (the Jacobian vanishes identically)";
    return false;
  }
  Rational_grid B = bernstein_grid(J);
  divide_side_factors(B);
  if (strict_sign_on_square(B, 4) == 0) {
    why = "the Jacobian of the projection is not proved nonzero inside the square";
    return false;
  }

  // (b) the projected boundary is a Jordan curve (collapsed sides contracted to their point)
  std::array<Rational_bezier_curve_2<Rational>, 4> side;
  std::array<bool, 4> live{};
  for (int k = 0; k < 4; ++k) {
    const auto c3 = P.boundary_curve<Rational_bezier_curve_3<Rational>>(k);
    std::vector<Rational_bezier_curve_2<Rational>::Homogeneous_point> h;
    for (const auto& q : c3.homogeneous_control_points()) {
      Rational_bezier_curve_2<Rational>::Homogeneous_point r;
      r[0] = q[0];
      r[1] = e1[0] * q[1] + e1[1] * q[2] + e1[2] * q[3];
      r[2] = e2[0] * q[1] + e2[1] * q[2] + e2[2] * q[3];
      h.push_back(r);
    }
    side[std::size_t(k)] = Rational_bezier_curve_2<Rational>::from_homogeneous(h);
    live[std::size_t(k)] = std::find(collapsed.begin(), collapsed.end(), k) == collapsed.end();
    if (live[std::size_t(k)] && !side_curve_simple(side[std::size_t(k)], why)) return false;
  }
  // two parameter corners are one point of the contracted square if equal or joined by collapsed sides
  auto same_point = [&](std::array<int, 2> a, std::array<int, 2> b) {
    for (int step = 0; step < 4 && a != b; ++step) {
      bool moved = false;
      for (int k : collapsed) {
        const auto c = side_corners(k);
        if (c[0] == a && c[1] != a) a = c[1], moved = true;
        else if (c[1] == a && c[0] != a) a = c[0], moved = true;
        if (a == b) return true;
      }
      if (!moved) break;
    }
    return a == b;
  };
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) {
      if (!live[std::size_t(a)] || !live[std::size_t(b)]) continue;
      Curve_intersection_result r;
      try {
        r = intersect_curves(side[std::size_t(a)], side[std::size_t(b)]);
      } catch (const std::exception& e) {
        why = std::string("the intersections of two sides are not decided (") + e.what() + ")";
        return false;
      }
      if (!r.overlaps.empty()) {
        why = "two sides overlap in the projection";
        return false;
      }
      for (const Curve_intersection_point& x : r.points) {
        bool allowed = false;
        for (int i = 0; i < 2 && !allowed; ++i)
          for (int j = 0; j < 2 && !allowed; ++j)
            allowed = x.s == Algebraic_real(Rational(i)) && x.t == Algebraic_real(Rational(j)) &&
                      same_point(side_corners(a)[std::size_t(i)], side_corners(b)[std::size_t(j)]);
        if (!allowed) {
          why = "two sides of the square meet in the projection away from a common corner";
          return false;
        }
      }
    }
  return true;
}

}  // namespace internal

/// \brief Proves that the rational patch (positive weights) has no self-intersection on [0,1]^2, without
/// elimination: some linear projection of it to a plane has a Jacobian without zeros inside the square and is
/// injective on the boundary (the header's theorem). Sides collapsed to one point (poles) are allowed; their
/// points are the only distinct parameter points with one image. Everything is decided exactly; a failure only
/// means "not proved".
inline Injectivity_proof prove_injective(const Rational_bezier_patch<Rational>& P) {
  Injectivity_proof out;
  if (!P.has_positive_weights()) {
    out.reason = "not all weights are positive";
    return out;
  }
  if (P.degree_u() < 1 || P.degree_v() < 1) {
    out.reason = "the patch has degree 0 in u or v";
    return out;
  }
  for (int k = 0; k < 4; ++k)
    if (internal::side_collapsed(P, k)) out.collapsed_sides.push_back(k);
  if (out.collapsed_sides.size() > 2) {
    out.reason = "more than two sides are collapsed";
    return out;
  }
  const int m = P.degree_u(), n = P.degree_v();
  auto corner = [&](std::size_t i, std::size_t j) { return P.control_point(i, j); };
  auto diff = [](const std::array<Rational, 3>& a, const std::array<Rational, 3>& b) {
    return std::array<Rational, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  auto sum = [](const std::array<Rational, 3>& a, const std::array<Rational, 3>& b) {
    return std::array<Rational, 3>{a[0] + b[0], a[1] + b[1], a[2] + b[2]};
  };
  const std::size_t M = std::size_t(m), N = std::size_t(n);
  const auto du = sum(diff(corner(M, 0), corner(0, 0)), diff(corner(M, N), corner(0, N)));
  const auto dv = sum(diff(corner(0, N), corner(0, 0)), diff(corner(M, N), corner(M, 0)));
  std::vector<std::array<Rational, 3>> directions;
  const auto normal = internal::cross(du, dv);
  if (normal != std::array<Rational, 3>{Rational(0), Rational(0), Rational(0)}) directions.push_back(normal);
  directions.push_back({Rational(0), Rational(0), Rational(1)});
  directions.push_back({Rational(1), Rational(0), Rational(0)});
  directions.push_back({Rational(0), Rational(1), Rational(0)});
  std::string failures;
  for (const auto& d : directions) {
    std::string why;
    if (internal::injective_along(P, d, out.collapsed_sides, why)) {
      out.proved = true;
      out.direction = d;
      out.reason = "the projection along " + internal::direction_text(d) +
                   " has a Jacobian without zeros inside the square and is injective on its boundary" +
                   (out.collapsed_sides.empty() ? std::string() : std::string(" (collapsed sides contracted)")) +
                   ", so the patch has no self-intersection";
      return out;
    }
    failures += (failures.empty() ? "" : "; ") + internal::direction_text(d) + ": " + why;
  }
  out.reason = "no projection proved injective: " + failures;
  return out;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_PATCH_INJECTIVITY_H

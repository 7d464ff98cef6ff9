// The complete fibre over an arc of D = 0 that lies on a rational line of the parameter plane, exactly.
//
// Structured patches put whole arcs of D = 0 on iso-lines: the double line of a fold, the phantom line along which a
// patch is even about u = a, the iso-curves two extrusions share. There the partner equations are often not
// simple (the folded patch ((u - a)^2, v^2, (u - a)(v - b)) on u = a: the first equation is (u' - a)^2 = 0, a double
// root), so the interval proofs of partner_sheets.h cannot follow or exclude its partners. On the line the
// partners are algebraic functions of one variable, and the fibre can be computed exactly.
//
// Notation. The line is x_c = r (rational), x_g = t, t in [t0, t1]. P and Q are the two patch points of a pair
// (x, y) (Partner_equations::points): for a self-intersection P = (x1, x2 + y2), Q = (x1 + y1, x2); for two patches
// P = (x1, y1), Q = (y2, x2). Their free coordinates w = (w1, w2) (self: w1 = Q_u, w2 = P_v; two patches:
// w1 = P_v, w2 = Q_s) range over the partner domain's rectangle W, and x plus w fix P and Q. The three equations
// E_i = A_i(P) B_0(Q) - B_i(Q) A_0(P) become polynomials in Q[t, w1, w2].
//  1. Every solution (t, w1, w2) has w1 a zero of R(t, .), R the gcd of the resultants Res_w2(E_i, E_j) over the
//     pairs of equations of positive degree in w2 and of the equations free of w2 (a common root makes each of
//     them vanish; identically vanishing ones are skipped; if all vanish the route is refused).
//  2. The factors w1 - (a1 + b1 t) of R with rational a1, b1 are found from the rational roots of R at two
//     rational values of t (a candidate through one root of each is kept when it divides R exactly) and divided
//     out with their multiplicities. The cofactor is proved nonzero on [t0, t1] x W_1 (interval evaluation on a
//     subdivision): so every solution with w1 in W_1 has w1 = a1 + b1 t for one of the factors.
//  3. For each such factor, E_i(t, a1 + b1 t, w2) are bivariate; their gcd G(t, w2) is split likewise into factors
//     w2 - (a2 + b2 t) and a cofactor proved nonzero on [t0, t1] x W_2.
// So every solution over [t0, t1] with w in W lies on one of the affine components w(t) = a + b t found, each of
// which solves E identically (it divides every E_i restricted to the line). Which components lie in W, and where,
// is exact (they are affine). A component is a genuine partner where it lies in W, differs from the trivial
// partner (self-intersection: w = x, i.e. y = 0) and the weights A_0(P), B_0(Q) do not vanish; a point of the line
// with no such component has no partner in the domain: phantom, proved.
//
// This decides the fibre of every point of the line over [t0, t1]; that the arc's traced points are points of
// the line is the topology's (exact_line_of_arc below): each graph piece runs along t with r
// strictly inside its cell, and a half-branch leaves its singular point's cell at a crossing on the line.
// What it cannot do: components that are not affine in t with rational coefficients (a conic of partners) stay
// in the cofactor, whose test then fails where they meet W; the route then reports nothing.
#ifndef BEZOUTIAN_LIFTING_EXACT_LINE_FIBRES_H
#define BEZOUTIAN_LIFTING_EXACT_LINE_FIBRES_H

#include <bezoutian/algebraic/Root_isolation.h>
#include <bezoutian/algebraic/bivariate_real_solutions.h>
#include <bezoutian/arithmetic/double_interval.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/linear_partner_lines.h>
#include <bezoutian/topology/Curve_topology.h>

#include <CGAL/Polynomial.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace bezoutian {
namespace internal {

/// Polynomials in (t, w1, w2): outer variable w2, then w1, inner t.
using Line_polynomial = CGAL::Polynomial<Polynomial_2<Rational>>;

/// An affine component w(t) = a + b t of the fibre over a line (partner coordinates w of the header comment).
struct Affine_fibre_component {
  std::array<Rational, 2> a, b;
  std::array<Rational, 2> at(const Rational& t) const { return {a[0] + b[0] * t, a[1] + b[1] * t}; }
};

/// The fibre over the line x_c = r, t in [t0, t1]: when `proved`, every solution with w in the partner domain's
/// rectangle lies on one of `components` (see the header comment); otherwise `reason` says why not.
struct Exact_line_fibre {
  bool proved = false;
  std::vector<Affine_fibre_component> components;
  std::string reason;
};

/// The rectangle W of the partner coordinates: W_1 (d = 0) and W_2 (d = 1).
inline std::array<Rational, 2> partner_coordinate_range(const Partner_equations& eq, const Parameter_box& domain, int d) {
  // self: w1 = Q_u, w2 = P_v; two patches: w1 = P_v, w2 = Q_s
  const bool u_range = eq.self_intersection() ? d == 0 : d == 1;
  return u_range ? std::array<Rational, 2>{domain.u0, domain.u1} : std::array<Rational, 2>{domain.v0, domain.v1};
}

/// The partner y of the point x with partner coordinates w (y = w - x for a self-intersection, y = w otherwise).
inline std::array<Rational, 2> partner_of_coordinates(const Partner_equations& eq, const std::array<Rational, 2>& x,
                                                      const std::array<Rational, 2>& w) {
  if (!eq.self_intersection()) return w;
  return {w[0] - x[0], w[1] - x[1]};
}

// The partner equations on the line x_c = r as polynomials in (t, w1, w2).
inline std::array<Line_polynomial, 3> line_partner_equations(const Partner_equations& eq, int c, const Rational& r) {
  using P1 = Polynomial_1<Rational>;
  using P2 = Polynomial_2<Rational>;
  using P3 = Line_polynomial;
  const P3 constant = P3(P2(P1(r))), T = P3(P2(P1(Rational(0), Rational(1)))),
           W1 = P3(P2(P1(Rational(0)), P1(Rational(1)))), W2 = P3(P2(P1(Rational(0))), P2(P1(Rational(1))));
  const P3 x1 = c == 0 ? constant : T, x2 = c == 1 ? constant : T;
  // P = (P_u, P_v), Q = (Q_u, Q_v) in these variables
  const std::array<P3, 2> P = eq.self_intersection() ? std::array<P3, 2>{x1, W2} : std::array<P3, 2>{x1, W1};
  const std::array<P3, 2> Q = eq.self_intersection() ? std::array<P3, 2>{W1, x2} : std::array<P3, 2>{W2, x2};
  auto form_at = [&](int which, int k, const std::array<P3, 2>& X) {
    const std::vector<std::vector<Rational>>& f = eq.form(which, k);  // [j][i]: u^i v^j
    P3 s(P2(P1(Rational(0))));
    for (std::size_t j = f.size(); j-- > 0;) {
      P3 row(P2(P1(Rational(0))));
      for (std::size_t i = f[j].size(); i-- > 0;) row = row * X[0] + P3(P2(P1(f[j][i])));
      s = s * X[1] + row;
    }
    return s;
  };
  const P3 a0 = form_at(0, 0, P), b0 = form_at(1, 0, Q);
  std::array<P3, 3> E;
  for (int i = 1; i <= 3; ++i) E[std::size_t(i - 1)] = form_at(0, i, P) * b0 - form_at(1, i, Q) * a0;
  return E;
}

// f divided by (outer variable - c(t)) when it divides exactly (synthetic division over Q[t]).
inline bool divide_by_affine_root(const Polynomial_2<Rational>& f, const Polynomial_1<Rational>& c,
                                  Polynomial_2<Rational>& quotient) {
  using P1 = Polynomial_1<Rational>;
  const int n = f.degree();
  if (n < 1) return false;
  std::vector<P1> q(std::size_t(n), P1(Rational(0)));
  q[std::size_t(n - 1)] = f[n];
  for (int j = n - 1; j >= 1; --j) q[std::size_t(j - 1)] = f[j] + c * q[std::size_t(j)];
  if (!CGAL::is_zero(P1(f[0] + c * q[0]))) return false;
  quotient = Polynomial_2<Rational>(q.begin(), q.end());
  return true;
}

// Is f (outer variable s, inner t) nonzero on [t0, t1] x [s0, s1]? Interval evaluation on a subdivision of at
// most `max_boxes` boxes.
inline bool proved_nonzero_on(const Polynomial_2<Rational>& f, const std::array<Rational, 2>& T,
                              const std::array<Rational, 2>& S, std::size_t max_boxes = 4096) {
  using D = Double_interval;
  if (CGAL::is_zero(f)) return false;
  std::vector<std::vector<D>> c;
  for (int j = 0; j <= f.degree(); ++j) {
    c.emplace_back();
    for (int i = 0; i <= f[j].degree(); ++i) c.back().push_back(D::of(f[j][i]));
  }
  std::vector<std::array<D, 2>> todo{{D::hull(T[0], T[1]), D::hull(S[0], S[1])}};
  std::size_t boxes = 0;
  while (!todo.empty()) {
    const std::array<D, 2> b = todo.back();
    todo.pop_back();
    if (++boxes > max_boxes) return false;
    if (!interval_horner(c, b[0], b[1]).contains_zero()) continue;
    // (halve the side that is wider relative to its range)
    const double rt = CGAL::to_double(T[1] - T[0]), rs = CGAL::to_double(S[1] - S[0]);
    const int s = (b[0].hi - b[0].lo) * (rs > 0 ? rs : 1) >= (b[1].hi - b[1].lo) * (rt > 0 ? rt : 1) ? 0 : 1;
    const double m = b[std::size_t(s)].mid();
    if (!(b[std::size_t(s)].lo < m && m < b[std::size_t(s)].hi)) return false;  // (a zero, or no more width)
    std::array<D, 2> lo = b, hi = b;
    lo[std::size_t(s)] = D{b[std::size_t(s)].lo, m};
    hi[std::size_t(s)] = D{m, b[std::size_t(s)].hi};
    todo.push_back(lo);
    todo.push_back(hi);
  }
  return true;
}

// Step 2 of the header comment for f (outer variable s, inner t): the affine factors s - (a + b t) with rational
// coefficients, and whether the cofactor is proved nonzero on [t0, t1] x S.
inline bool split_affine_factors(Polynomial_2<Rational> f, const std::array<Rational, 2>& T,
                                 const std::array<Rational, 2>& S, std::vector<std::array<Rational, 2>>& factors,
                                 std::string& reason) {
  using P1 = Polynomial_1<Rational>;
  const Rational ta = T[0] + (T[1] - T[0]) * Rational(2, 7), tb = T[0] + (T[1] - T[0]) * Rational(5, 7);
  auto rational_roots = [&](const Rational& t) {
    std::vector<Rational> out;
    const P1 g = with_inner_fixed(f, t);
    if (CGAL::is_zero(g)) return out;
    for (const Isolated_root& x : isolate_real_roots(g))
      if (x.root.is_rational()) out.push_back(x.root.rational_value());
    return out;
  };
  if (f.degree() >= 1 && (CGAL::is_zero(with_inner_fixed(f, ta)) || CGAL::is_zero(with_inner_fixed(f, tb)))) {
    reason = "every partner coordinate solves the equations at a sample of the line";
    return false;
  }
  const std::vector<Rational> ra = rational_roots(ta), rb = rational_roots(tb);
  for (const Rational& x : ra)
    for (const Rational& y : rb) {
      const Rational b = (y - x) / (tb - ta), a = x - b * ta;
      const P1 c(a, b);
      bool found = false;
      Polynomial_2<Rational> q;
      while (divide_by_affine_root(f, c, q)) {
        f = q;
        found = true;
      }
      if (found) factors.push_back({a, b});
    }
  if (!(f.degree() == 0 && f[0].degree() == 0 && !CGAL::is_zero(f[0][0]))) {  // (a nonzero constant is nonzero)
    if (!proved_nonzero_on(f, T, S)) {
      reason = "a factor of the partner equations that is not affine in the line's parameter meets the partner domain";
      return false;
    }
  }
  return true;
}

/// The fibre over the line x_c = r, t in T = [t0, t1] (see the header comment).
inline Exact_line_fibre exact_line_fibre(const Partner_equations& eq, const Parameter_box& domain, int c,
                                         const Rational& r, const std::array<Rational, 2>& T) {
  using P1 = Polynomial_1<Rational>;
  using P2 = Polynomial_2<Rational>;
  Exact_line_fibre out;
  if (!(T[0] < T[1])) {
    out.reason = "the line's range of t is a point";
    return out;
  }
  const std::array<Line_polynomial, 3> E = line_partner_equations(eq, c, r);
  // 1. eliminate w2
  std::vector<P2> eliminants;
  for (int i = 0; i < 3; ++i) {
    if (CGAL::is_zero(E[std::size_t(i)])) continue;
    if (E[std::size_t(i)].degree() == 0) {
      eliminants.push_back(E[std::size_t(i)][0]);
      continue;
    }
    for (int j = i + 1; j < 3; ++j)
      if (!CGAL::is_zero(E[std::size_t(j)]) && E[std::size_t(j)].degree() >= 1) {
        const P2 res = CGAL::resultant(E[std::size_t(i)], E[std::size_t(j)]);
        if (!CGAL::is_zero(res)) eliminants.push_back(res);
      }
  }
  P2 R(P1(Rational(0)));
  for (const P2& f : eliminants) R = CGAL::is_zero(R) ? f : P2(CGAL::gcd(R, f));
  if (CGAL::is_zero(R)) {
    out.reason = "the partner equations on the line have a common factor";
    return out;
  }
  // 2. the affine factors in w1
  std::vector<std::array<Rational, 2>> first;
  const std::array<Rational, 2> W1 = partner_coordinate_range(eq, domain, 0), W2 = partner_coordinate_range(eq, domain, 1);
  if (!split_affine_factors(R, T, W1, first, out.reason)) return out;
  // 3. per factor, the affine factors in w2
  for (const auto& f1 : first) {
    const P1 c1(f1[0], f1[1]);
    // (an affine w1 meets W1 over T iff it does at an end of T or crosses it: compare both ends)
    const Rational e0 = f1[0] + f1[1] * T[0], e1 = f1[0] + f1[1] * T[1];
    if (std::max(e0, e1) < W1[0] || std::min(e0, e1) > W1[1]) continue;
    P2 G(P1(Rational(0)));
    for (const Line_polynomial& e : E) {
      std::vector<P1> coefficients;
      for (int k = 0; k <= e.degree(); ++k) {
        P1 s(Rational(0));
        for (int j = e[k].degree(); j >= 0; --j) s = s * c1 + e[k][j];
        coefficients.push_back(s);
      }
      const P2 g(coefficients.begin(), coefficients.end());
      if (!CGAL::is_zero(g)) G = CGAL::is_zero(G) ? g : P2(CGAL::gcd(G, g));
    }
    if (CGAL::is_zero(G)) {
      out.reason = "the partner equations vanish on a whole plane of partners over the line";
      return out;
    }
    std::vector<std::array<Rational, 2>> second;
    if (!split_affine_factors(G, T, W2, second, out.reason)) return out;
    for (const auto& f2 : second) out.components.push_back(Affine_fibre_component{{f1[0], f2[0]}, {f1[1], f2[1]}});
  }
  out.proved = true;
  return out;
}

/// An arc of D = 0 proved to lie on the line x_c = r: its graph coordinate t runs in T.
struct Line_arc {
  int c = 0;
  Rational r;
  std::array<Rational, 2> T;
};

/// Is the arc `e` of the topology of D = 0 (D square-free) the line x_c = r over the graph coordinate of its cells?
/// D(x) vanishes on the whole line (exactly), and every piece of the arc is on the line: a graph piece along t with
/// r strictly inside its cell's range of x_c (in the cell D = 0 is one graph over t, and the line is a graph on
/// D = 0 there), or a half-branch whose crossing of its cell's side, isolated on that side, is where the line
/// crosses it (the half-branch is the one branch of D = 0 in the cell through that crossing, and the line is a
/// branch through it). T is the hull of the pieces' cells along t, so it holds the arc's range.
inline std::optional<Line_arc> exact_line_of_arc(const Curve_topology_edge& e, const Polynomial_2<Integer>& D) {
  const std::size_t n = e.polyline.size();
  if (n < 2 || e.pieces.empty()) return std::nullopt;
  for (int c = 0; c < 2; ++c) {
    const double mid = e.polyline[n / 2][std::size_t(c)];
    bool constant = true;
    for (const auto& x : e.polyline) constant = constant && std::fabs(x[std::size_t(c)] - mid) <= 1e-9;
    if (!constant) continue;
    const auto r = rational_near(mid);
    if (!r) return std::nullopt;
    // D(x) = 0 on the line: c = 0 (u = r, D's inner variable) every coefficient of v^j vanishes at r; c = 1
    // (v = r) every coefficient of u^i of D(u, r)
    int du = 0;
    for (int j = 0; j <= D.degree(); ++j) du = std::max(du, D[j].degree());
    for (int k = 0; k <= (c == 0 ? D.degree() : du); ++k) {
      Rational s(0);
      if (c == 0) {
        for (int i = D[k].degree(); i >= 0; --i) s = s * *r + Rational(D[k][i]);
      } else {
        for (int j = D.degree(); j >= 0; --j) s = s * *r + (k <= D[j].degree() ? Rational(D[j][k]) : Rational(0));
      }
      if (!CGAL::is_zero(s)) return std::nullopt;
    }
    const int g = 1 - c;
    Line_arc out{c, *r, {}};
    bool first = true;
    for (const Curve_topology_piece& pc : e.pieces) {
      const Rational &lo = c == 0 ? pc.cell.u0 : pc.cell.v0, &hi = c == 0 ? pc.cell.u1 : pc.cell.v1;
      if (pc.graph_axis >= 0) {
        if (pc.graph_axis != g || !(lo < *r && *r < hi)) return std::nullopt;
      } else {
        // the crossing lies on a side across the line (a horizontal side for u = r), its interval holding r
        if (pc.crossing_on_vertical_line != (c == 1)) return std::nullopt;
        const Rational &clo = c == 0 ? pc.crossing.u0 : pc.crossing.v0, &chi = c == 0 ? pc.crossing.u1 : pc.crossing.v1;
        if (!(clo <= *r && *r <= chi) || !(lo <= *r && *r <= hi)) return std::nullopt;
      }
      const Rational &tlo = g == 0 ? pc.cell.u0 : pc.cell.v0, &thi = g == 0 ? pc.cell.u1 : pc.cell.v1;
      out.T = first ? std::array<Rational, 2>{tlo, thi}
                    : std::array<Rational, 2>{std::min(out.T[0], tlo), std::max(out.T[1], thi)};
      first = false;
    }
    return out;
  }
  return std::nullopt;
}

/// The closed range of t in `range` where the component's partner coordinates lie in the rectangle W and the line's
/// point x(t) (x_c = r) in the domain, exactly (the conditions are affine in t); empty if there is none.
inline std::optional<std::array<Rational, 2>> component_in_domain(const Partner_equations& eq, const Parameter_box& domain,
                                                                  const Affine_fibre_component& k, int c, const Rational& r,
                                                                  std::array<Rational, 2> range) {
  const std::array<Rational, 2> X_c = c == 0 ? std::array<Rational, 2>{domain.u0, domain.u1}
                                             : std::array<Rational, 2>{domain.v0, domain.v1},
                                X_g = c == 0 ? std::array<Rational, 2>{domain.v0, domain.v1}
                                             : std::array<Rational, 2>{domain.u0, domain.u1};
  if (r < X_c[0] || r > X_c[1]) return std::nullopt;
  range = {std::max(range[0], X_g[0]), std::min(range[1], X_g[1])};
  for (int d = 0; d < 2; ++d) {  // lo <= a + b t <= hi
    const std::array<Rational, 2> W = partner_coordinate_range(eq, domain, d);
    const Rational &a = k.a[std::size_t(d)], &b = k.b[std::size_t(d)];
    if (CGAL::is_zero(b)) {
      if (a < W[0] || a > W[1]) return std::nullopt;
      continue;
    }
    Rational t0 = (W[0] - a) / b, t1 = (W[1] - a) / b;
    if (t0 > t1) std::swap(t0, t1);
    range = {std::max(range[0], t0), std::min(range[1], t1)};
  }
  if (range[0] > range[1]) return std::nullopt;
  return range;
}

/// The genuine partners y of the point x of the line (exact): the components in the partner domain, other than
/// the trivial partner, with nonzero weights. `decided` is false where a component in the domain has a zero
/// weight (the equations hold without a double point there).
inline std::vector<std::array<Rational, 2>> genuine_line_partners(const Partner_equations& eq, const Parameter_box& domain,
                                                                  const Exact_line_fibre& F, const std::array<Rational, 2>& x,
                                                                  const Rational& t, bool& decided) {
  std::vector<std::array<Rational, 2>> out;
  // (P_u = x1 and Q's second coordinate x2 are fixed by x)
  if (x[0] < domain.u0 || x[0] > domain.u1 || x[1] < domain.v0 || x[1] > domain.v1) return out;
  const std::array<Rational, 2> W1 = partner_coordinate_range(eq, domain, 0), W2 = partner_coordinate_range(eq, domain, 1);
  for (const Affine_fibre_component& k : F.components) {
    const std::array<Rational, 2> w = k.at(t);
    if (w[0] < W1[0] || w[0] > W1[1] || w[1] < W2[0] || w[1] > W2[1]) continue;
    const std::array<Rational, 2> y = partner_of_coordinates(eq, x, w);
    if (eq.self_intersection() && CGAL::is_zero(y[0]) && CGAL::is_zero(y[1])) continue;
    std::array<Rational, 2> weights;
    eq.exact_values({x[0], x[1], y[0], y[1]}, weights);
    if (CGAL::is_zero(weights[0]) || CGAL::is_zero(weights[1])) {
      decided = false;
      continue;
    }
    if (std::find(out.begin(), out.end(), y) == out.end()) out.push_back(y);
  }
  return out;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_EXACT_LINE_FIBRES_H

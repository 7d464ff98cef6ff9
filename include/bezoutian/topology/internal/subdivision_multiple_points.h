// Multiple points of D = 0 in the subdivision (Curve_topology_by_subdivision.h): points where D vanishes to order
// k >= 2 with a degenerate or vanishing Hessian, which the Morse analysis of subdivision_singular_boxes.h cannot
// resolve. They are given by the caller (options.multiple_points), found at the domain's corners and inside its sides
// (exact gcds of D, D_u, D_v there: add_singular_corners, add_singular_edge_points), or at small rationals inside a
// box (exact Taylor coefficients: rational_multiple_point). A box around such a point p is resolved by the argument
// of the header comment of Curve_topology_by_subdivision.h: a blow-up proves 2L (or H) half-branches at p and
// grad D != 0 on a rectangle around p minus p (internal/multiple_point_blowup.h for an ordinary tangent cone,
// internal/corner_blowup.h for the quadrants of a corner, of a side point, or of a point with a multiple tangent);
// grad D != 0 on the rest of the box (no_critical_point_outside); and D = 0 crosses the box's edges exactly that
// many times. A box that holds p but cannot be resolved is cut 3 x 3 around it (cut_around), so that p stays far
// from the edges of the boxes that hold it.
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_MULTIPLE_POINTS_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_MULTIPLE_POINTS_H

// the class Subdivision_topology, whose member functions this header defines (it is included at the end of that one)
#include <bezoutian/topology/Curve_topology_by_subdivision.h>
#include <bezoutian/topology/internal/corner_blowup.h>
#include <bezoutian/topology/internal/interval_bernstein_grid.h>
#include <bezoutian/topology/internal/multiple_point_blowup.h>
#include <bezoutian/arithmetic/binomial.h>
#include <bezoutian/arithmetic/simplest_rational.h>

#include <mpfi.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

// The domain's corners where D = 0 is singular (D, D_u, D_v vanish exactly), with the order of D there: where
// two patches of one smooth surface touch at a corner, D = 0 is singular at that corner of the (u, t) box.
inline void Subdivision_topology::add_singular_corners() {
  for (const Rational* cu : {&box_.u0, &box_.u1})
    for (const Rational* cv : {&box_.v0, &box_.v1}) {
      const auto e = exact_jet(*cu, *cv);
      if (e[0] != 0 || e[1] != 0 || e[2] != 0) continue;
      // the exact Taylor coefficients once: the order of D at the corner and the blow-up both come from them
      std::vector<std::vector<Rational>> c = taylor_coefficients(*cu, *cv);
      int order = INT_MAX;
      for (std::size_t i = 0; i < c.size(); ++i)
        for (std::size_t j = 0; j < c[i].size(); ++j)
          if (!CGAL::is_zero(c[i][j])) order = std::min(order, int(i + j));
      if (order == INT_MAX) continue;  // D == 0: not a curve
      Multiple_point m{Known_multiple_point{Parameter_box{*cu, *cu, *cv, *cv}, order}, nullptr, false};
      m.corner = true;
      m.corner_blowup =
          std::make_shared<const Corner_blowup>(std::move(c), *cu == box_.u0 ? 1 : -1, *cv == box_.v0 ? 1 : -1);
      multiple_.push_back(m);
    }
}

// The singular points of D = 0 strictly inside the sides of the domain: the roots of gcd(P, P', Q), P = D on the
// side and Q = D across it (exact). Two patches of one surface glued along an edge give them on the side where
// the rest of D meets the shared curve (teapot spout 16 x 17: a triple point with one real tangent).
inline void Subdivision_topology::add_singular_edge_points() {
  for (int side = 0; side < 4; ++side) {
    const bool vertical = side == 1 || side == 3;
    const Rational& c = side == 0 ? box_.v0 : (side == 1 ? box_.u1 : (side == 2 ? box_.v1 : box_.u0));
    const Rational& lo = vertical ? box_.v0 : box_.u0;
    const Rational& hi = vertical ? box_.v1 : box_.u1;
    if ((side == 2 && box_.v1 == box_.v0) || (side == 1 && box_.u1 == box_.u0) || !(lo < hi)) continue;
    Polynomial_1<Rational> P, Q;
    restriction(vertical, c, P, &Q);
    if (CGAL::is_zero(P)) continue;  // the side lies on D = 0: not a curve there (box_edge_lines removes it)
    const Polynomial_1<Integer> p = internal::integer_multiple(P), q = internal::integer_multiple(Q);
    Polynomial_1<Integer> g = CGAL::gcd(p, CGAL::differentiate(p));
    if (!CGAL::is_zero(q)) g = CGAL::gcd(g, q);
    if (g.degree() < 1) continue;
    for (const Isolated_root& r : isolate_real_roots(g, lo, hi)) {
      if (r.root.compare(lo) == 0 || r.root.compare(hi) == 0) continue;  // a corner: add_singular_corners
      r.root.refine_to_width((hi - lo) / Rational(Integer(1) << 40));
      const Parameter_box K = vertical ? Parameter_box{c, c, r.root.lower(), r.root.upper()}
                                       : Parameter_box{r.root.lower(), r.root.upper(), c, c};
      Multiple_point m{Known_multiple_point{K, 2}, nullptr, false};
      m.edge = true;
      m.edge_vertical = vertical;
      m.edge_c = c;
      m.edge_position = r.root;
      multiple_.push_back(m);
    }
  }
}

// The Taylor coefficients of D at an edge point: exact at a rational point; otherwise enclosures at every point
// of its isolating interval (refined to 2^-prec), a coefficient whose enclosure holds 0 decided exactly (the sign
// of the exact derivative polynomial along the side at the algebraic point).
inline std::vector<std::vector<Corner_blowup::Enclosed_coefficient>> Subdivision_topology::edge_taylor_coefficients(
    Multiple_point& mp) const {
  using Coefficient = Corner_blowup::Enclosed_coefficient;
  std::vector<std::vector<Coefficient>> out(std::size_t(a_ + 1), std::vector<Coefficient>(std::size_t(b_ + 1)));
  const Algebraic_real& x0 = mp.edge_position;
  if (x0.is_rational()) {
    const Rational q = x0.rational_value();
    const auto c = mp.edge_vertical ? taylor_coefficients(mp.edge_c, q) : taylor_coefficients(q, mp.edge_c);
    for (int i = 0; i <= a_; ++i)
      for (int j = 0; j <= b_; ++j) out[i][j] = Coefficient{c[i][j], c[i][j], CGAL::is_zero(c[i][j])};
    return out;
  }
  const mpfr_prec_t prec = root_prec_ + mpfr_prec_t(bits_) + 128;
  Rational width(1);
  for (mpfr_prec_t k = 0; k < prec; ++k) width /= 2;
  x0.refine_to_width(width);
  mp.known.enclosure = mp.edge_vertical ? Parameter_box{mp.edge_c, mp.edge_c, x0.lower(), x0.upper()}
                                        : Parameter_box{x0.lower(), x0.upper(), mp.edge_c, mp.edge_c};
  const std::vector<Mpfi_interval> c = internal::taylor_enclosures(D_, mp.known.enclosure, prec);
  // exact: D(u, v) = sum_ij t_ij (u - cu)^i (v - cv)^j with the side's own coordinate shifted (cu or cv = c)
  // and the other not (0); c_ij is then the i-th (j-th) derivative along the side of one row, over i! (j!)
  const auto t = mp.edge_vertical ? taylor_coefficients(mp.edge_c, Rational(0)) : taylor_coefficients(Rational(0), mp.edge_c);
  mpfr_t l, h;
  mpfr_init2(l, prec);
  mpfr_init2(h, prec);
  for (int i = 0; i <= a_; ++i)
    for (int j = 0; j <= b_; ++j) {
      const Mpfi_interval& e = c[std::size_t(i) * (b_ + 1) + j];
      Coefficient& o = out[i][j];
      o.zero = false;
      mpfi_get_left(l, e.get());
      mpfi_get_right(h, e.get());
      mpq_t ql, qh;
      mpq_init(ql);
      mpq_init(qh);
      mpfr_get_q(ql, l);
      mpfr_get_q(qh, h);
      o.lo = Rational(ql);
      o.hi = Rational(qh);
      mpq_clear(ql);
      mpq_clear(qh);
      if (!e.contains_zero()) continue;
      std::vector<Rational> row;  // along the side: u for v = c (column j of t), v for u = c (row i)
      if (mp.edge_vertical)
        for (int k = 0; k <= b_; ++k) row.push_back(t[i][k]);
      else
        for (int k = 0; k <= a_; ++k) row.push_back(t[k][j]);
      Polynomial_1<Rational> f(row.begin(), row.end());
      for (int k = 0; k < (mp.edge_vertical ? j : i) && !CGAL::is_zero(f); ++k) f = CGAL::differentiate(f);
      if (CGAL::is_zero(f) || x0.sign_of(f) == 0) o = Coefficient{Rational(0), Rational(0), true};
    }
  mpfr_clear(l);
  mpfr_clear(h);
  return out;
}

// A multiple point of D (order >= 3) at the simplest rational point of B (denominators below 2^20), proved by
// exact Taylor coefficients, added to the known multiple points; its index, or -1. Symmetric and constructed
// inputs put such points at small rationals (three lines through (1/2, 1/2)); each point is tested once.
inline int Subdivision_topology::rational_multiple_point(const Box& B) {
  Rational ru, rv;
  if (!simplest_rational_in(B.u0, B.u1, ru) || !simplest_rational_in(B.v0, B.v1, rv)) return -1;
  if (ru.denominator().bit_size() > 20 || rv.denominator().bit_size() > 20) return -1;
  if (!(B.u0 < ru && ru < B.u1 && B.v0 < rv && rv < B.v1)) return -1;
  if (!rational_points_tested_.insert(std::make_pair(ru, rv)).second) return -1;
  const int max_order = std::min(8, a_ + b_);
  for (int order = 0; order <= max_order; ++order)
    for (int i = 0; i <= order; ++i)
      if (!CGAL::is_zero(taylor_coefficient(ru, rv, i, order - i))) {
        if (order < 2) return -1;  // not on the curve, or smooth
        if (order == 2) {  // a node or an acnode is resolve_singular's case; a double tangent (a cusp) is not
          const Rational c20 = taylor_coefficient(ru, rv, 2, 0), c11 = taylor_coefficient(ru, rv, 1, 1),
                         c02 = taylor_coefficient(ru, rv, 0, 2);
          if (!CGAL::is_zero(c11 * c11 - 4 * c20 * c02)) return -1;
        }
        multiple_.push_back(Multiple_point{Known_multiple_point{Parameter_box{ru, ru, rv, rv}, order}, nullptr, false});
        return int(multiple_.size()) - 1;
      }
  return -1;
}

// All the coefficients c[i][j] of (u - ru)^i (v - rv)^j in D, exactly (Taylor shift by Horner steps).
inline std::vector<std::vector<Rational>> Subdivision_topology::taylor_coefficients(const Rational& ru,
                                                                                    const Rational& rv) const {
  std::vector<std::vector<Rational>> c(std::size_t(a_ + 1), std::vector<Rational>(std::size_t(b_ + 1), Rational(0)));
  for (int j = 0; j <= b_; ++j)
    for (int i = 0; !CGAL::is_zero(D_[j]) && i <= D_[j].degree(); ++i) c[i][j] = Rational(D_[j][i]);
  for (int j = 0; j <= b_; ++j)
    for (int s = 0; s < a_; ++s)
      for (int i = a_ - 1; i >= s; --i) c[i][j] += ru * c[i + 1][j];
  for (int i = 0; i <= a_; ++i)
    for (int s = 0; s < b_; ++s)
      for (int j = b_ - 1; j >= s; --j) c[i][j] += rv * c[i][j + 1];
  return c;
}

// The coefficient of (u - ru)^i (v - rv)^j in D, exactly.
inline Rational Subdivision_topology::taylor_coefficient(const Rational& ru, const Rational& rv, int i, int j) const {
  if (i > a_ || j > b_) return Rational(0);
  Rational r(0);
  for (int J = D_.degree(); J >= j; --J) {  // Horner in rv over the j-th Taylor coefficients in v
    Rational c(0);
    if (!CGAL::is_zero(D_[J]))
      for (int I = D_[J].degree(); I >= i; --I) c = c * ru + Rational(D_[J][I] * bezoutian::binomial<Integer>(I, i));
    r = r * rv + c * Rational(bezoutian::binomial<Integer>(J, j));
  }
  return r;
}

// The known multiple point whose enclosure lies strictly inside B (or a singular domain corner that is a corner of
// B), or -1.
inline int Subdivision_topology::multiple_point_in(const Box& B) const {
  for (std::size_t m = 0; m < multiple_.size(); ++m) {
    const Parameter_box& K = multiple_[m].known.enclosure;
    if (multiple_[m].corner) {  // a domain corner: in B iff it is a corner of B
      if ((K.u0 == B.u0 || K.u0 == B.u1) && (K.v0 == B.v0 || K.v0 == B.v1)) return int(m);
      continue;
    }
    if (multiple_[m].edge) {  // on a side of the domain: in B iff on B's edge along that side, ends included
      if (edge_point_side_of(multiple_[m], B) >= 0) return int(m);
      continue;
    }
    if (B.u0 < K.u0 && K.u1 < B.u1 && B.v0 < K.v0 && K.v1 < B.v1) return int(m);
  }
  return -1;
}

// Resolves box B around the known multiple point p (enclosure K strictly inside B): the tangent cone has L real
// lines, all simple, and grad D != 0 on (p + [-r, r]^2) \ {p} (internal/multiple_point_blowup.h); grad D != 0
// on the rest of B (the Bernstein coefficients of D_u or of D_v keep a sign on every sub-box outside that
// square); D = 0 crosses the edges of B exactly 2L times. Then D = 0 in B is the 2L half-branches from p to the
// crossings (the argument of the header comment of Curve_topology_by_subdivision.h). Returns false (B is split)
// otherwise.
inline bool Subdivision_topology::resolve_multiple(Box& B, std::size_t index) {
  Multiple_point& mp = multiple_[index];
  if (mp.refuted) return false;
  const Parameter_box& K = mp.known.enclosure;
  if (mp.corner) return resolve_corner(B, mp);
  if (mp.edge) return resolve_edge_point(B, mp);
  if (!mp.blowup) {
    mp.blowup = std::make_shared<const Multiple_point_blowup>(D_, K, mp.known.multiplicity,
                                                              root_prec_ + mpfr_prec_t(bits_) + 128);
    mp.refuted = !mp.blowup->consistent();
    if (mp.refuted) return false;
  }
  // first a square around p that covers B (then (2') has nothing left to prove), else the largest power of two
  // r <= half the distance from K to the edges of B for which the cone is proved
  const Rational reach = std::max(std::max(K.u1 - B.u0, B.u1 - K.u0), std::max(K.v1 - B.v0, B.v1 - K.v0));
  Rational r(1);
  while (r < reach) r *= 2;
  while (r / 2 >= reach) r /= 2;
  int lines = mp.blowup->tangent_lines(r);
  if (lines < 0) {
    const Rational dist = std::min(std::min(K.u0 - B.u0, B.u1 - K.u1), std::min(K.v0 - B.v0, B.v1 - K.v1));
    while (r > dist / 2) r /= 2;
    for (int attempt = 0; attempt < 3 && lines < 0; ++attempt) {
      lines = mp.blowup->tangent_lines(r);
      if (lines < 0) r /= 8;
    }
  }
  if (lines < 0) return resolve_quadrants(B, mp);  // not ordinary (or r too large): at a rational point, quadrants
  std::vector<Crossing> cr;
  std::vector<std::size_t> isolated_corners;
  if (!crossings_around(B, cr, isolated_corners)) return false;
  if (cr.size() != 2 * std::size_t(lines)) return false;
  if (!no_critical_point_outside(B, Parameter_box{K.u1 - r, K.u0 + r, K.v1 - r, K.v0 + r})) return false;
  singular_.push_back(Singular_point{K.u0, K.u1, K.v0, K.v1, lines == 0, 2 * lines});
  for (std::size_t n : isolated_corners) touch_[n] = 0;
  const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
  connect_to_point(B, cr, node_singular(singular_.size() - 1),
                   CGAL::to_double(((K.u0 + K.u1) / 2 - B.u0) / wu), CGAL::to_double(((K.v0 + K.v1) / 2 - B.v0) / wv));
  return true;
}

// Box B at a singular domain corner p (a corner of B): the same argument in the quadrant B of p. The weighted
// blow-up (internal/corner_blowup.h) proves H half-branches of D = 0 leaving p into B and grad D != 0 on the
// rectangle R = [0, L0^w] x [0, L0^v] of the quadrant minus p; grad D != 0 on the rest of B; D = 0 crosses
// the edges of B (p excluded) exactly H times. Components of (D = 0) \ {p} in B are arcs with ends on the edges
// of B or at p (no closed curve: the disc it bounds, inside B, would hold an extremum of D; neither a loop
// through p, for the same reason), so the H half-branches end at H distinct crossings and use them all: D = 0 in
// B is the H arcs from p. p is a point of the locus on the domain's boundary with H branches into the domain
// (H = 0: the curve passes p from outside, an isolated point of the locus in the domain).
inline bool Subdivision_topology::resolve_corner(Box& B, Multiple_point& mp) {
  const Parameter_box& K = mp.known.enclosure;
  if (!mp.corner_blowup->valid()) return false;
  const int sx = K.u0 == B.u0 ? 1 : -1, sy = K.v0 == B.v0 ? 1 : -1;
  const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
  Rational rx, ry;
  const int half = quadrant_half_branches({mp.corner_blowup.get()}, wu, wv, rx, ry);
  if (half < 0) return false;
  std::vector<Crossing> cr;
  std::vector<std::size_t> isolated_corners;
  const Excluded_point corner{Algebraic_real(K.u0), Algebraic_real(K.v0)};
  if (!crossings_around(B, cr, isolated_corners, &corner) || cr.size() != std::size_t(half)) return false;
  if ((rx < wu || ry < wv) && !no_critical_point_outside(B, Parameter_box{K.u0 - rx, K.u0 + rx, K.v0 - ry, K.v0 + ry}))
    return false;
  Singular_point p{K.u0, K.u1, K.v0, K.v1, half == 0, half};
  p.on_boundary = true;
  singular_.push_back(p);
  for (std::size_t n : isolated_corners) touch_[n] = 0;
  connect_to_point(B, cr, node_singular(singular_.size() - 1), sx > 0 ? 0 : 1, sy > 0 ? 0 : 1);
  return true;
}

// Box B around a known multiple point p at an exact rational point (K a point, strictly inside B) whose tangent
// cone is not ordinary (a cusp, a tacnode: a multiple line of the cone): the four quadrants at p blown up each
// (internal/corner_blowup.h, on exact Taylor coefficients; valid when D(x, 0) and D(0, y) are not identically
// zero at p, i.e. no branch along the axis lines through p, so none of the half-branches lies on an axis). The
// germ of D = 0 at p is the sum H of their half-branches, grad D != 0 on the rectangle around p minus p; grad
// D != 0 on the rest of B and exactly H crossings of B's edges: then D = 0 in B is the H arcs from p.
inline bool Subdivision_topology::resolve_quadrants(Box& B, Multiple_point& mp) {
  const Parameter_box& K = mp.known.enclosure;
  if (!(K.u0 == K.u1 && K.v0 == K.v1)) return false;
  if (!mp.quadrants[0]) {
    const auto c = taylor_coefficients(K.u0, K.v0);
    for (int q = 0; q < 4; ++q)
      mp.quadrants[q] = std::make_shared<const Corner_blowup>(c, q % 2 == 0 ? 1 : -1, q < 2 ? 1 : -1);
  }
  for (const auto& q : mp.quadrants)
    if (!q->valid()) return false;
  Rational rx, ry;
  const int half = quadrant_half_branches(
      {mp.quadrants[0].get(), mp.quadrants[1].get(), mp.quadrants[2].get(), mp.quadrants[3].get()},
      std::max(K.u0 - B.u0, B.u1 - K.u0), std::max(K.v0 - B.v0, B.v1 - K.v0), rx, ry);
  if (half < 0) return false;
  std::vector<Crossing> cr;
  std::vector<std::size_t> isolated_corners;
  if (!crossings_around(B, cr, isolated_corners) || cr.size() != std::size_t(half)) return false;
  const Parameter_box S{K.u0 - rx, K.u0 + rx, K.v0 - ry, K.v0 + ry};
  const bool covers = S.u0 <= B.u0 && B.u1 <= S.u1 && S.v0 <= B.v0 && B.v1 <= S.v1;
  if (!covers && !no_critical_point_outside(B, S)) return false;
  singular_.push_back(Singular_point{K.u0, K.u1, K.v0, K.v1, half == 0, half});
  for (std::size_t n : isolated_corners) touch_[n] = 0;
  const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
  connect_to_point(B, cr, node_singular(singular_.size() - 1), CGAL::to_double((K.u0 - B.u0) / wu),
                   CGAL::to_double((K.v0 - B.v0) / wv));
  return true;
}

// The blow-ups q of quadrants at one point (they share the Newton polygon, so the weights wx, wy): the sum of
// their half-branches H on the rectangles [0, rx] x [0, ry], rx = 2^(e wx), ry = 2^(e wy), for the first e that
// reaches (ru, rv), else e - 1, e - 3, e - 5; -1 if none is proved.
inline int Subdivision_topology::quadrant_half_branches(const std::vector<const Corner_blowup*>& q, const Rational& ru,
                                                        const Rational& rv, Rational& rx, Rational& ry) {
  const int wx = q.front()->weight_x(), wy = q.front()->weight_y();
  auto extent = [](int e, int weight) {  // 2^(e weight), exactly
    Rational r(1);
    for (int i = 0; i < std::abs(e * weight); ++i) r = e > 0 ? r * 2 : r / 2;
    return r;
  };
  // the first guess from the bit lengths (log2 r within 1; not log2 of a double, which is -inf for radii below
  // 2^-1074 and whose conversion to int would be undefined), lowered by 2 so that the loop finds the first e
  auto log2_below = [](const Rational& r, int weight) {  // at most log2(r) / weight + 1 (r > 0; a radius of 0 any e)
    if (!CGAL::is_positive(r)) return LONG_MIN / 2;
    return (long(mpz_sizeinbase(r.numerator().mpz(), 2)) - long(mpz_sizeinbase(r.denominator().mpz(), 2)) - 1) / weight;
  };
  const long below = std::max(log2_below(ru, wx), log2_below(rv, wy));
  int e = below == LONG_MIN / 2 ? 0 : int(std::max(-1000000L, below)) - 2;
  while (extent(e, wx) < ru || extent(e, wy) < rv) ++e;
  int half = -1;
  for (int attempt = 0; attempt < 4 && half < 0; ++attempt) {
    half = 0;
    for (std::size_t k = 0; k < q.size() && half >= 0; ++k) {
      const int n = q[k]->half_branches(e);
      half = n < 0 ? -1 : half + n;
    }
    if (half < 0) e -= attempt == 0 ? 1 : 2;
  }
  rx = extent(e, wx);
  ry = extent(e, wy);
  return half;
}

// Where the edge point mp lies on B: -1 not on B; 0 strictly inside B's edge along the side; 1 at that edge's
// lower end (B's corner), 2 at its upper end (a rational point on a grid line). A box with the point inside that
// edge is cut around it (cut_around_edge_point), so that grid lines do not pass through it.
inline int Subdivision_topology::edge_point_side_of(const Multiple_point& mp, const Box& B) const {
  const bool on_line = mp.edge_vertical ? (B.u0 == mp.edge_c || B.u1 == mp.edge_c) : (B.v0 == mp.edge_c || B.v1 == mp.edge_c);
  if (!on_line) return -1;
  const int l = mp.edge_position.compare(mp.edge_vertical ? B.v0 : B.u0);
  const int h = mp.edge_position.compare(mp.edge_vertical ? B.v1 : B.u1);
  return l < 0 || h > 0 ? -1 : (l == 0 ? 1 : (h == 0 ? 2 : 0));
}

// Box B at a singular point p inside a side of the domain, on B's edge along that side: the argument of
// resolve_corner, with the two quadrants of the domain at p (along the side below and above p) blown up each
// (internal/corner_blowup.h; they share the Newton polygon, so the weights). They prove H = H- + H+ half-branches
// leaving p into the domain (none along the normal to the side at p: D has order b0 there, the chart B's form is
// nonzero at n = 0) and grad D != 0 on [p - L0^w, p + L0^w] x [0, L0^v] minus p (side coordinates); grad D != 0 on
// the rest of B; D = 0 crosses the edges of B (p excluded) exactly H times.
inline bool Subdivision_topology::resolve_edge_point(Box& B, Multiple_point& mp) {
  if (edge_point_side_of(mp, B) != 0) return false;  // at a corner of B: not handled (the boxes are cut around it)
  const bool vertical = mp.edge_vertical;
  // inward: +1 if the domain lies on the side of larger coordinate across the side
  const int inward = mp.edge_c == (vertical ? box_.u0 : box_.v0) ? 1 : -1;
  if (!mp.halves[0]) {
    const auto c = edge_taylor_coefficients(mp);
    for (int h = 0; h < 2; ++h) {
      const int along = h == 0 ? -1 : 1;
      mp.halves[h] = std::make_shared<const Corner_blowup>(c, vertical ? inward : along, vertical ? along : inward);
    }
  }
  if (!mp.halves[0]->valid() || !mp.halves[1]->valid()) return false;
  const Parameter_box& K = mp.known.enclosure;
  // B's edge along the side runs over [lo, hi]
  const Rational& lo = vertical ? B.v0 : B.u0;
  const Rational& hi = vertical ? B.v1 : B.u1;
  const Rational& klo = vertical ? K.v0 : K.u0;
  const Rational& khi = vertical ? K.v1 : K.u1;
  const Rational along_reach = std::max(khi - lo, hi - klo);
  const Rational across_reach = vertical ? B.u1 - B.u0 : B.v1 - B.v0;
  Rational rx, ry;
  const int half = quadrant_half_branches({mp.halves[0].get(), mp.halves[1].get()}, vertical ? across_reach : along_reach,
                                          vertical ? along_reach : across_reach, rx, ry);
  if (half < 0) return false;
  const Rational& ra = vertical ? ry : rx;
  const Rational& rc = vertical ? rx : ry;
  std::vector<Crossing> cr;
  std::vector<std::size_t> isolated_corners;
  const Excluded_point point = vertical ? Excluded_point{Algebraic_real(mp.edge_c), mp.edge_position}
                                        : Excluded_point{mp.edge_position, Algebraic_real(mp.edge_c)};
  if (!crossings_around(B, cr, isolated_corners, &point) || cr.size() != std::size_t(half)) return false;
  // the proved rectangle, shrunk by the enclosure of p (it holds p's exact rectangle)
  const Parameter_box S = vertical ? Parameter_box{mp.edge_c - rc, mp.edge_c + rc, khi - ra, klo + ra}
                                   : Parameter_box{khi - ra, klo + ra, mp.edge_c - rc, mp.edge_c + rc};
  const bool covers = S.u0 <= B.u0 && B.u1 <= S.u1 && S.v0 <= B.v0 && B.v1 <= S.v1;
  if (!covers && !no_critical_point_outside(B, S)) return false;
  Singular_point p{K.u0, K.u1, K.v0, K.v1, half == 0, half};
  p.on_boundary = true;
  singular_.push_back(p);
  for (std::size_t n : isolated_corners) touch_[n] = 0;
  const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
  const double px = CGAL::to_double(((K.u0 + K.u1) / 2 - B.u0) / wu), py = CGAL::to_double(((K.v0 + K.v1) / 2 - B.v0) / wv);
  connect_to_point(B, cr, node_singular(singular_.size() - 1), px, py);
  return true;
}

// A box B holding a known multiple point p (enclosure K strictly inside) that resolve_multiple could not
// resolve is cut into 3 x 3 boxes: a square [c - h, c + h]^2 around p (c a short rational within h/8 of K, h a
// power of two at most half the distance from K to B's edges) and the eight boxes around it, all at a distance
// >= 7h/8 from p. A plain split leaves p next to an edge as often as not, and the boxes beside p are then never
// resolved: D = 0 near a multiple point looks the same at every scale (its tangent cone), so a box whose
// distance to p is not large against its size fails the monotonicity tests at every depth. Here only the
// square touches p, and it is resolve_multiple's case, with p central; the boxes around it are at a fixed
// distance from p, and their sub-boxes become simple. False if B holds no such point.
inline bool Subdivision_topology::split_around_multiple(Box& B, std::vector<Box>& stack) {
  const int m = multiple_point_in(B);
  if (m < 0 || multiple_[std::size_t(m)].refuted) return false;
  if (multiple_[std::size_t(m)].edge) return cut_around_edge_point(B, multiple_[std::size_t(m)], stack);
  return cut_around(B, multiple_[std::size_t(m)].known.enclosure, stack, true);
}
// The same cut for a point p strictly inside B's edge along a side of the domain: 3 x 2 boxes, the middle one
// [c - h, c + h] along the side by h across it holding p, the others at a distance >= 7h/8 from p.
inline bool Subdivision_topology::cut_around_edge_point(Box& B, const Multiple_point& mp,
                                                        std::vector<Box>& stack) {
  if (edge_point_side_of(mp, B) != 0) return false;
  const bool vertical = mp.edge_vertical;
  const Parameter_box& K = mp.known.enclosure;
  const Rational& lo = vertical ? B.v0 : B.u0;
  const Rational& hi = vertical ? B.v1 : B.u1;
  const Rational& klo = vertical ? K.v0 : K.u0;
  const Rational& khi = vertical ? K.v1 : K.u1;
  const Rational across = vertical ? B.u1 - B.u0 : B.v1 - B.v0;
  if (!(lo < klo && khi < hi)) return false;
  const Rational dist = std::min(std::min(klo - lo, hi - khi), across);
  Rational h(1);
  while (h > dist / 2) h /= 2;
  while (h * 2 <= dist / 2) h *= 2;
  Rational m;
  if (!simplest_rational_in(klo - h / 8, khi + h / 8, m)) return false;
  const Rational al[4] = {lo, m - h, m + h, hi};
  const bool low_side = mp.edge_c == (vertical ? B.u0 : B.v0);
  const Rational ac[3] = {vertical ? B.u0 : B.v0, low_side ? mp.edge_c + h : (vertical ? B.u1 : B.v1) - h,
                          vertical ? B.u1 : B.v1};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      Box C = vertical ? Box{ac[j], ac[j + 1], al[i], al[i + 1], B.depth + 1, nullptr, nullptr}
                       : Box{al[i], al[i + 1], ac[j], ac[j + 1], B.depth + 1, nullptr, nullptr};
      C.fast = interval_bernstein::double_grid_of(mpfi_grid(C), prec_);
      stack.push_back(C);
    }
  return true;
}
// The 3 x 3 cut of B around the box K strictly inside it (above), with MPFI grids (`exact`) or double-double
// ones when available; false if K is not strictly inside B.
inline bool Subdivision_topology::cut_around(Box& B, const Parameter_box& K, std::vector<Box>& stack, bool exact) {
  if (!(B.u0 < K.u0 && K.u1 < B.u1 && B.v0 < K.v0 && K.v1 < B.v1)) return false;
  const Rational dist = std::min(std::min(K.u0 - B.u0, B.u1 - K.u1), std::min(K.v0 - B.v0, B.v1 - K.v1));
  Rational h(1);
  while (h > dist / 2) h /= 2;
  while (h * 2 <= dist / 2) h *= 2;
  Rational cu, cv;
  if (!simplest_rational_in(K.u0 - h / 8, K.u1 + h / 8, cu) || !simplest_rational_in(K.v0 - h / 8, K.v1 + h / 8, cv))
    return false;
  const Rational us[4] = {B.u0, cu - h, cu + h, B.u1}, vs[4] = {B.v0, cv - h, cv + h, B.v1};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Box C{us[i], us[i + 1], vs[j], vs[j + 1], B.depth + 1, nullptr, nullptr};
      C.fast = exact || !dd_root_ ? interval_bernstein::double_grid_of(mpfi_grid(C), prec_) : double_double_grid(C);
      stack.push_back(C);
    }
  return true;
}

// grad D != 0 on B outside the box S: sub-boxes where D_u or D_v keeps a sign, or that lie inside S. The signs
// come from the Bernstein grids of D_u and D_v themselves (forward differences of B's MPFI grid, exact up to
// its rounding), split in double with the proved radius. Differences of a split grid of D would not do: on a
// piece of relative size h they are h times smaller than the derivative while their error is not, and near a
// multiple point with two almost equal tangents the gradient is small along a whole sector, where the pieces
// must be small (two random (2,2) self-intersections failed there at every depth).
inline bool Subdivision_topology::no_critical_point_outside(Box& B, const Parameter_box& S) {
  using Grid = std::shared_ptr<const Double_bernstein_grid>;
  struct Piece {
    Grid gu, gv;            // Bernstein grids of D_u and D_v on the piece (null when that degree is 0)
    double x0, x1, y0, y1;  // local coordinates in B (dyadic: exact)
    int depth;
  };
  const Rational wu = B.u1 - B.u0, wv = B.v1 - B.v0;
  const Rational sx0 = (S.u0 - B.u0) / wu, sx1 = (S.u1 - B.u0) / wu, sy0 = (S.v0 - B.v0) / wv,
                 sy1 = (S.v1 - B.v0) / wv;
  const double aspect = CGAL::to_double(wu) / CGAL::to_double(wv);
  const Interval_grid& g = mpfi_grid(B);
  auto derivative = [&](bool along_u) -> Grid {
    if ((along_u ? a_ : b_) < 1) return nullptr;
    Interval_grid d(along_u ? a_ - 1 : a_, along_u ? b_ : b_ - 1, prec_);
    for (int i = 0; i <= d.a(); ++i)
      for (int j = 0; j <= d.b(); ++j) mpfi_sub(d.at(i, j), along_u ? g.at(i + 1, j) : g.at(i, j + 1), g.at(i, j));
    return interval_bernstein::double_grid_of(d, prec_);
  };
  auto keeps_sign = [](const Grid& G) { return G && G->common_sign(G->radius()) != 0; };
  auto halve = [](const Grid& G, bool along_u, Grid& lo, Grid& hi) {
    if (!G) return;
    auto l = std::make_shared<Double_bernstein_grid>(), h = std::make_shared<Double_bernstein_grid>();
    G->split(along_u, 0.5, *l, *h);
    lo = l;
    hi = h;
  };
  std::vector<Piece> stack{{derivative(true), derivative(false), 0, 1, 0, 1, 0}};
  for (int count = 0; !stack.empty(); ++count) {
    const Piece P = stack.back();
    stack.pop_back();
    if (Rational(P.x0) >= sx0 && Rational(P.x1) <= sx1 && Rational(P.y0) >= sy0 && Rational(P.y1) <= sy1) continue;
    if (keeps_sign(P.gu) || keeps_sign(P.gv)) continue;
    if (P.depth >= 28 || count > 20000) return false;
    const bool along_u = (P.x1 - P.x0) * aspect >= (P.y1 - P.y0);
    Piece L = P, R = P;
    ++L.depth;
    ++R.depth;
    halve(P.gu, along_u, L.gu, R.gu);
    halve(P.gv, along_u, L.gv, R.gv);
    work_ += 2 * double(a_ + 1) * (b_ + 1) * std::max(1, a_ + b_) / 16;
    if (along_u)
      L.x1 = R.x0 = 0.5 * (P.x0 + P.x1);
    else
      L.y1 = R.y0 = 0.5 * (P.y0 + P.y1);
    stack.push_back(L);
    stack.push_back(R);
  }
  return true;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_SUBDIVISION_MULTIPLE_POINTS_H

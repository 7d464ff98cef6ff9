// The space path of intersect_curves (default method, space curves with positive weights): intervals first
// (space_interval_solver.h: Krawczyk boxes of square subsystems covering every common point), then the exact
// shape basis {g(s) = 0, t = psi(s)} of F_1 = F_2 = F_3 = 0 (space_shape_basis.h), whose real roots are proved
// common points; every box must hold one of them. See doc/curve_intersection.md.
//
// Internal header: members of Curve_intersection_engine (Curve_intersection.h), not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_SPACE_CURVE_PATH_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_SPACE_CURVE_PATH_H

#include <bezoutian/intersection/Curve_intersection.h>

#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/intersection/internal/space_interval_solver.h>
#include <bezoutian/intersection/internal/space_shape_basis.h>

#include <algorithm>
#include <vector>

namespace bezoutian {
namespace internal {

// Space curves with positive weights. Intervals first (space_interval_solver.h): boxes covering every common
// point in [0,1]^2, each holding exactly one zero of a square subsystem (G_a, G_b) (Krawczyk), boxes where the
// third equation is proved nonzero dropped; none left = no intersection. Otherwise the exact step, small: the shape
// basis {g(s) = 0, t = psi(s)} of F_1 = F_2 = F_3 = 0 (space_shape_basis.h: modular, verified exactly over Q), so
// that every root of g gives a proved common point (sigma, psi(sigma)). Every box must contain one of them
// (isolating interval of sigma and an enclosure of psi(sigma) inside the box): a box holds at most one zero of
// its subsystem, which is then that common point, so nothing is missed. Krawczyk's proof includes a regular
// Jacobian of the subsystem, i.e. non-parallel tangents: transversal, multiplicity 1. Anything else (tangency,
// overlap, common points with equal s, an unmatched box) returns false: the exact paths below decide.
// (Public for benchmarks: true = the pair was settled here, `res` holds the answer.)
template <int D>
bool Curve_intersection_engine<D>::space_path(Curve_intersection_result& res) const {
  if constexpr (D != 3) {
    (void)res;
    return false;
  } else {
    if (!positive_weights(c1_) || !positive_weights(c2_)) return false;
    BEZOUTIAN_PROFILE_START;
    const Space_interval_curve ia = space_interval_curve(c1_, H1_), ib = space_interval_curve(c2_, H2_);
    Space_interval_solver solver{ia, ib, {}};
    solver.run(ia.inet, 0, 1, ib.inet, 0, 1, 0);
    BEZOUTIAN_PROFILE_STEP("space interval solver");
    if (solver.failed) return false;
    if (solver.found.empty()) return true;  // proved: no common point
    Space_shape_basis sb;
    if (!space_shape_basis(H1_, H2_, sb)) return false;
    BEZOUTIAN_PROFILE_STEP("space shape basis");
    const std::size_t d = sb.g.size() - 1;
    if (d == 0) return false;  // boxes left but no common zero: undecided here
    Rational lo(0), hi(1);
    for (const auto& b : solver.found) {
      lo = std::min(lo, Rational(b.s_lo));
      hi = std::max(hi, Rational(b.s_hi));
    }
    const Polynomial_1<Rational> g(sb.g.begin(), sb.g.end());
    const Polynomial_1<Rational> psi = sb.psi.empty() ? Polynomial_1<Rational>(0)
                                                       : Polynomial_1<Rational>(sb.psi.begin(), sb.psi.end());
    const std::vector<Isolated_root> roots = isolate_real_roots(g, lo, hi);
    BEZOUTIAN_PROFILE_STEP("space isolate");
    auto eval = [](const Polynomial_1<Rational>& f, const Rational& x) {
      Rational r(0);
      for (int i = f.degree(); i >= 0; --i) r = r * x + f[i];
      return r;
    };
    // psi = N / q with an integer polynomial N and a positive rational q
    const P1 N = CGAL::is_zero(psi) ? P1(0) : internal::integer_multiple(psi);
    Rational q(1);
    for (int i = 0; i <= psi.degree(); ++i)
      if (!CGAL::is_zero(psi[i])) q = Rational(N[i]) / psi[i];
    const P1 G = internal::integer_multiple(g);
    P1 P;  // vanishes at psi(sigma) for every root sigma of g (computed once, if an irrational sigma needs it)
    std::vector<Rational> s_enc_lo, s_enc_hi, t_enc_lo, t_enc_hi;  // enclosures of (sigma, psi(sigma))
    std::vector<Algebraic_real> ts;
    std::vector<char> matched(solver.found.size(), 0);
    for (const Isolated_root& r : roots) {
      const Algebraic_real& x = r.root;
      if (x.is_rational()) {
        const Rational t = eval(psi, x.rational_value());
        s_enc_lo.push_back(x.rational_value());
        s_enc_hi.push_back(x.rational_value());
        t_enc_lo.push_back(t);
        t_enc_hi.push_back(t);
        ts.push_back(Algebraic_real(t));
        continue;
      }
      // irrational sigma: t = psi(sigma) is a root of P(t) = Res_s(g(s), q t - N(s)); its isolating interval
      // from an MPFI enclosure of psi on sigma's refined interval
      if (CGAL::is_zero(P) && !CGAL::is_zero(psi)) P = partner_polynomial(G, N, q);
      bool ok = false;
      for (int bits = 64; bits <= 1024 && !ok; bits *= 2) {
        Integer p2(1);
        mpz_mul_2exp(p2.mpz(), p2.mpz(), (unsigned long)bits);
        x.refine_to_width(Rational(1) / Rational(p2));
        const mpfr_prec_t prec = mpfr_prec_t(2 * bits + 64 + coefficient_bits_);
        using I = internal::Mpfi_interval;
        const I u = I::hull(x.lower(), x.upper(), prec);
        const I v = I::horner(N, u) / I::hull(q, q, prec);
        const Rational vlo = v.lower(), vhi = v.upper();
        try {
          Algebraic_real t = CGAL::is_zero(psi) ? Algebraic_real(0) : Algebraic_real(P, vlo, vhi);
          s_enc_lo.push_back(x.lower());
          s_enc_hi.push_back(x.upper());
          t_enc_lo.push_back(vlo);
          t_enc_hi.push_back(vhi);
          ts.push_back(t);
          ok = true;
        } catch (const Invalid_input&) {
        }
      }
      if (!ok) return false;
    }
    BEZOUTIAN_PROFILE_STEP("space partners");
    // every box must hold a root (sigma, psi(sigma)): enclosures inside the box, or exact comparisons with its ends
    for (std::size_t k = 0; k < solver.found.size(); ++k) {
      const auto& b = solver.found[k];
      const Rational bs0(b.s_lo), bs1(b.s_hi), bt0(b.t_lo), bt1(b.t_hi);
      for (std::size_t i = 0; i < roots.size() && !matched[k]; ++i) {
        if (s_enc_hi[i] < bs0 || s_enc_lo[i] > bs1 || t_enc_hi[i] < bt0 || t_enc_lo[i] > bt1) continue;
        if (bs0 <= s_enc_lo[i] && s_enc_hi[i] <= bs1 && bt0 <= t_enc_lo[i] && t_enc_hi[i] <= bt1) {
          matched[k] = 1;
          break;
        }
        // overlapping but not inside: compare the exact numbers with the box ends
        const Algebraic_real& x = roots[i].root;
        if (x.compare(bs0) >= 0 && x.compare(bs1) <= 0 && ts[i].compare(bt0) >= 0 && ts[i].compare(bt1) <= 0)
          matched[k] = 1;
      }
      if (!matched[k]) return false;
    }
    for (std::size_t i = 0; i < roots.size(); ++i) {
      const Algebraic_real &s = roots[i].root, &t = ts[i];
      if (s.compare(Rational(0)) < 0 || s.compare(Rational(1)) > 0) continue;
      if (t.compare(Rational(0)) < 0 || t.compare(Rational(1)) > 0) continue;
      // a common point of the arcs lies in some box (the boxes cover all of them): check, for safety
      bool in_box = false;
      for (const auto& b : solver.found)
        in_box = in_box || (s.compare(Rational(b.s_lo)) >= 0 && s.compare(Rational(b.s_hi)) <= 0 &&
                            t.compare(Rational(b.t_lo)) >= 0 && t.compare(Rational(b.t_hi)) <= 0);
      if (!in_box) return false;
      Curve_intersection_point p;
      p.s = s;
      p.t = t;
      auto end = [](const Algebraic_real& x) { return x.is_rational() && (x == 0 || x == 1); };
      p.kind = (end(s) || end(t)) ? Curve_intersection_kind::endpoint : Curve_intersection_kind::transversal;
      res.points.push_back(p);
    }
    BEZOUTIAN_PROFILE_STEP("space match");
    return true;
  }
}

// P(t) = Res_s(g(s), b N(s) - a t) for psi = N / q, q = a / b: vanishes at psi(sigma) for every root sigma of g.
template <int D>
auto Curve_intersection_engine<D>::partner_polynomial(const P1& G, const P1& N, const Rational& q) -> P1 {
  std::vector<P1> gc, hc;
  for (int i = 0; i <= G.degree(); ++i) gc.push_back(P1(G[i]));
  for (int i = 0; i <= N.degree(); ++i) hc.push_back(P1(q.denominator() * N[i]));
  if (hc.empty()) hc.push_back(P1(0));
  hc[0] -= P1(Integer(0), q.numerator());
  return CGAL::resultant(P2(gc.begin(), gc.end()), P2(hc.begin(), hc.end()));
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_INTERSECTION_INTERNAL_SPACE_CURVE_PATH_H

// The sheared system of two curves (doc/curve_intersection.md step 5). Where several intersections lie on one
// line s = s_i and on one line t = t_j, neither elimination inverts them (S11 vanishes on both lines). The shear
// s = u - lambda t separates them for generic lambda: each root u_k of Res_t(G1(u - lambda t, t), G2(...)) in
// [0, 1 + lambda] gives t = -S10(u_k)/S11(u_k) and s = u_k - lambda t (du-1989 eq. 4.3 in the sheared variables),
// located among the unresolved roots by exact sign decisions. A point alone on its line u = u_k has the
// multiplicity of u_k as its intersection multiplicity (also used for rational tangencies: local_multiplicity).
//
// Internal header: members of Curve_intersection_engine (Curve_intersection.h), not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_SHEAR_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_SHEAR_H

#include <bezoutian/intersection/Curve_intersection.h>

#include <vector>

namespace bezoutian {
namespace internal {

// Shear s = u - lambda t: for generic lambda distinct solutions have distinct u; each root u_k of
// Res_t(G1(u - lambda t, t), G2(...)) in [0, 1 + lambda] gives t = -S10(u_k)/S11(u_k) and s = u_k - lambda t, located
// among the unresolved roots by exact sign decisions (polynomials in u evaluated at the algebraic u_k).
// The system in (u, t) with s = u - lambda t: f(u - lambda t, t) for every f.
template <int D>
auto Curve_intersection_engine<D>::sheared_system(const std::vector<P2>& F, int lambda) -> std::vector<P2> {
  const P2 U(P1(Integer(0), Integer(1)));
  const P2 T(P1(0), P1(1));
  const P2 S = U - T * P2(lambda);
  std::vector<P2> Fs;
  for (const P2& f : F) {
    // f(S, t) = sum_j t^j f_j(S): Horner in the inner variable
    P2 r(0);
    for (int j = t_degree(f); j >= 0; --j) {
      P2 fj(0);
      for (int i = f[j].degree(); i >= 0; --i) fj = fj * S + P2(f[j][i]);
      r += fj * CGAL::ipower(T, j);
    }
    Fs.push_back(r);
  }
  return Fs;
}

template <int D>
bool Curve_intersection_engine<D>::sheared_elimination(const std::vector<P2>& Fs, Elimination& e) {
  for (const auto& pr : candidate_pairs(Fs)) {
    e = eliminate(pr.first, pr.second);
    if (e.ok) return true;
  }
  return false;
}

// Intersection multiplicity of the rational solution (a, b) of F = 0: the multiplicity of u0 = a + lambda b as a
// root of the sheared resultant of a pair of F, for a shear and a pair that leave (a, b) alone on its line u = u0
// (S11(u0) != 0: the gcd of the pair on that line has degree 1; a leading coefficient survives: no solution at
// infinity). In the plane F is the pair itself. In space each pair is a projection of the two curves, whose
// multiplicity at the point is at least the curves' own (the ideal of the pair lies in that of F) and equal to it
// for a generic projection; a special one may even fail the conditions on every shear (two circles in the planes
// x = 1 and y = 1 touching at (1, 1, 0): the pair (x, y) has a double root in t alone, so its gcd on every line
// has degree 2). So every pair is tried and the least multiplicity is the answer.
template <int D>
int Curve_intersection_engine<D>::local_multiplicity(const std::vector<P2>& F, const Rational& a, const Rational& b) const {
  int best = 0;
  for (int lambda = 1; lambda <= 12; ++lambda) {
    const Rational u0 = a + Rational(lambda) * b;
    auto value = [&](const P1& f) {
      Rational r(0);
      for (int i = f.degree(); i >= 0; --i) r = r * u0 + Rational(f[i]);
      return r;
    };
    for (const auto& pr : candidate_pairs(sheared_system(F, lambda))) {
      const Elimination e = eliminate(pr.first, pr.second);
      if (!e.ok || CGAL::is_zero(value(e.S11))) continue;
      if (CGAL::is_zero(value(e.G1[t_degree(e.G1)])) && CGAL::is_zero(value(e.G2[t_degree(e.G2)]))) continue;
      const P1 lin(-u0.numerator(), u0.denominator());  // den u - num
      P1 R = e.R;
      int m = 0;
      for (;;) {
        P1 q, r;
        Integer d;
        P1::pseudo_division(R, lin, q, r, d);
        if (!CGAL::is_zero(r)) break;
        R = q;
        ++m;
      }
      if (best == 0 || m < best) best = m;
      if (F.size() == 2 || best <= 2) return best;  // (a tangency has multiplicity >= 2)
    }
    if (best > 0) return best;
  }
  if (best > 0) return best;
  throw Error("intersect_curves: no separating shear found for the multiplicity of a tangency");
}

template <int D>
auto Curve_intersection_engine<D>::sheared_pairs(const std::vector<P2>& F, const std::vector<Isolated_root>& rs,
                                              const std::vector<Isolated_root>& rt, const std::vector<int>& us,
                                              const std::vector<int>& ut) const -> std::vector<Sheared_pair> {
  for (int lambda = 1; lambda <= 12; ++lambda) {
    const std::vector<P2> Fs = sheared_system(F, lambda);
    Elimination e;
    if (!sheared_elimination(Fs, e)) continue;
    std::vector<Isolated_root> ru = isolate_real_roots(e.R, Rational(0), Rational(1 + lambda));
    std::vector<Sheared_pair> found;
    bool good = true;
    for (const Isolated_root& r : ru) {
      const Algebraic_real& u = r.root;
      const int s11 = root_sign(u, e.S11);
      const P1& l1 = e.G1[t_degree(e.G1)];
      const P1& l2 = e.G2[t_degree(e.G2)];
      if (s11 == 0 || (root_sign(u, l1) == 0 && root_sign(u, l2) == 0)) {
        good = false;
        break;
      }
      const Polynomial_1<Rational> S10 = to_rational(e.S10), S11 = to_rational(e.S11);
      const Polynomial_1<Rational> su = Polynomial_1<Rational>(Rational(0), Rational(1)) * S11 + S10 * Polynomial_1<Rational>(Rational(lambda));
      // sign(t - c) = -sign(S10 + c S11) sign(S11); sign(s - c) = sign(u S11 + lambda S10 - c S11) sign(S11)
      auto tcmp = [&](const Rational& c) { return -root_sign(u, S10 + S11 * Polynomial_1<Rational>(c)) * s11; };
      auto scmp = [&](const Rational& c) { return root_sign(u, su - S11 * Polynomial_1<Rational>(c)) * s11; };
      auto locate = [&](const std::vector<Isolated_root>& roots, const std::vector<int>& cand, auto cmp) {
        for (int k : cand) {
          const Algebraic_real& x = roots[k].root;
          if (x.is_rational() ? cmp(x.rational_value()) == 0 : (cmp(x.lower()) > 0 && cmp(x.upper()) < 0)) return k;
        }
        return -1;
      };
      const int i = locate(rs, us, scmp), j = locate(rt, ut, tcmp);
      if (i < 0 || j < 0) continue;
      bool all = true;
      if (F.size() > 2 || Fs.size() > 2) {
        for (const P2& f : Fs) all = all && root_sign(u, substitute(f, -e.S10, e.S11)) == 0;
      }
      if (all) found.push_back({i, j, r, e.S10, e.S11, lambda});
    }
    if (!good) continue;
    return found;
  }
  throw Error("intersect_curves: no separating shear found for a degenerate configuration");
}

// A point found by the shear: u_k is a root of Res_t of the sheared pair whose line u = u_k carries this point
// only (S11(u_k) != 0 and a leading coefficient survives, checked in sheared_pairs), with s = (u S11 + lambda
// S10)/S11, t = -S10/S11. So the multiplicity of u_k is the intersection multiplicity of the point, and the
// tangents are parallel iff every 2x2 minor of (D1(s), D2(t)) vanishes there: minor(s(u), t(u)) is a rational
// function of u, an exact univariate sign at u_k. (The eliminations in s or t cannot decide this: S11 vanishes
// on both lines through the point, e.g. at a node shared by both curves, lyon-loops-nested.)
template <int D>
Curve_intersection_point Curve_intersection_engine<D>::sheared_point(const Isolated_root& s, const Isolated_root& t,
                                                                  const Sheared_pair& q) const {
  Curve_intersection_point p;
  p.s = s.root;
  p.t = t.root;
  p.tangent = false;
  if (q.u.multiplicity >= 2 && !tangents_apart(s.root, t.root)) {
    std::array<P1, D> da, db;
    for (int k = 0; k < D; ++k) {
      da[k] = CGAL::differentiate(H1_[k + 1]) * H1_[0] - H1_[k + 1] * CGAL::differentiate(H1_[0]);
      db[k] = CGAL::differentiate(H2_[k + 1]) * H2_[0] - H2_[k + 1] * CGAL::differentiate(H2_[0]);
    }
    const P1 su = P1(Integer(0), Integer(1)) * q.S11 + q.S10 * P1(q.lambda);
    p.tangent = true;
    for (int i = 0; i < D && p.tangent; ++i)
      for (int j = i + 1; j < D && p.tangent; ++j) {
        const P2 m = lift_outer(db[j]) * P2(da[i]) - lift_outer(db[i]) * P2(da[j]);  // s inner, t outer
        p.tangent = root_sign(q.u.root, substitute_affine(m, su, -q.S10, q.S11)) == 0;
      }
  }
  p.multiplicity = p.tangent ? q.u.multiplicity : 1;
  auto end = [](const Algebraic_real& x) { return x.is_rational() && (x == 0 || x == 1); };
  p.kind = (end(p.s) || end(p.t)) ? Curve_intersection_kind::endpoint
                                  : (p.tangent ? Curve_intersection_kind::tangent : Curve_intersection_kind::transversal);
  return p;
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_SHEAR_H

// Pairing for the exact system F_k(s,t) = 0 of two curves (du-1989 ch. 4). The equations: the candidate systems
// and pairs (linear combinations of the F_k tried in turn, so that a pair without a common component is found
// unless all F_k share one). The roots: each root s_i of the eliminant R is paired with t* = -S10(s_i)/S11(s_i)
// from the first subresultant S_1 = S11 t + S10 (du-1989 eq. 4.3), valid where S11(s_i) != 0 and a leading
// coefficient survives (both decided exactly), and t* is located among the roots of T by exact sign decisions.
// The point of a pair: its multiplicity from the eliminants and the tangency decided by an interval proof that
// the tangents are apart, else exactly (each 2x2 minor of the tangent vectors a univariate sign decision).
//
// Internal header: members of Curve_intersection_engine (Curve_intersection.h), not part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_CANDIDATE_PAIRS_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_CANDIDATE_PAIRS_H

#include <bezoutian/intersection/Curve_intersection.h>

#include <bezoutian/arithmetic/interval_krawczyk.h>

#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

// Linearly independent combinations of the F_k tried in turn (the first ones are the F_k themselves); a pair of
// them with a vanishing resultant shares a component, which a combination avoids unless all F_k share it.
template <int D>
auto Curve_intersection_engine<D>::candidate_systems(const std::vector<P2>& F) -> std::vector<std::vector<P2>> {
  std::vector<std::vector<P2>> c;
  if (F.size() == 2) {
    c.push_back({F[0], F[1]});
    c.push_back({F[0] + F[1], F[0] + F[1] * P2(2)});
    c.push_back({F[0] * P2(3) - F[1], F[0] + F[1] * P2(5)});
  } else {
    c.push_back({F[0], F[1], F[2]});
    c.push_back({F[1], F[2], F[0]});
    c.push_back({F[2], F[0], F[1]});
    c.push_back({F[0] + F[1] + F[2], F[0] - F[1] + F[2] * P2(2), F[0] + F[1] * P2(3) - F[2]});
    c.push_back({F[0] * P2(2) + F[1] - F[2], F[0] + F[1] * P2(5) + F[2] * P2(3), F[0] - F[1] * P2(4) + F[2]});
  }
  return c;
}

// Pairs of F to eliminate: F1,F2 first; in 3D combinations with F3 if F1,F2 share a component.
template <int D>
auto Curve_intersection_engine<D>::candidate_pairs(const std::vector<P2>& F) -> std::vector<std::pair<P2, P2>> {
  std::vector<std::pair<P2, P2>> c;
  c.push_back({F[0], F[1]});
  c.push_back({F[0] + F[1], F[0] + F[1] * P2(2)});
  if (F.size() == 3) {
    c.push_back({F[0], F[2]});
    c.push_back({F[1], F[2]});
    c.push_back({F[0] + F[2], F[1] - F[2] * P2(2)});
    c.push_back({F[0] * P2(3) + F[1] + F[2], F[1] + F[2] * P2(5) - F[0]});
  }
  return c;
}

// For each root a_i of the first variable (outer variable of G is the second one): the index of its unique
// partner among roots_b, none, or unresolved (gcd of G1(a_i,.), G2(a_i,.) not of degree 1 / leading terms vanish).
template <int D>
std::vector<int> Curve_intersection_engine<D>::pair_roots(const Elimination& e, const std::vector<Isolated_root>& ra,
                                                       const std::vector<Isolated_root>& rb) {
  std::vector<int> out(ra.size(), none);
  const int d1 = t_degree(e.G1), d2 = t_degree(e.G2);
  const P1 l1 = e.G1[d1], l2 = e.G2[d2];
  const Polynomial_1<Rational> S10 = to_rational(e.S10), S11 = to_rational(e.S11);
  for (std::size_t i = 0; i < ra.size(); ++i) {
    const Algebraic_real& a = ra[i].root;
    // subresultants specialize at a when the leading coefficient of the higher-degree polynomial survives
    const bool lc_ok = d1 == d2 ? (root_sign(a, l1) != 0 || root_sign(a, l2) != 0)
                                : root_sign(a, d1 > d2 ? l1 : l2) != 0;
    const int s11 = lc_ok ? root_sign(a, e.S11) : 0;
    if (s11 == 0) {
      out[i] = unresolved;
      continue;
    }
    // b* = -S10(a)/S11(a) is a root of Res_a(G1,G2); sign(b* - c) = -sign(S10 + c S11) * sign(S11)
    auto cmp = [&](const Rational& c) { return -root_sign(a, S10 + S11 * Polynomial_1<Rational>(c)) * s11; };
    int found = none;
    for (std::size_t j = 0; j < rb.size() && found == none; ++j) {
      const Algebraic_real& b = rb[j].root;
      if (b.is_rational()) {
        if (cmp(b.rational_value()) == 0) found = int(j);
      } else if (cmp(b.lower()) > 0 && cmp(b.upper()) < 0) {
        found = int(j);
      }
    }
    out[i] = found;
  }
  return out;
}

// Pairing of the roots `ra` of the first variable with the roots of the second one (main list `rb`): a root a_i
// is paired through every elimination pair (G1, G_m), m = 2 (.. 3 in space); the partner b* = -S10/S11 (a_i) is
// located among the roots `loc[m]` of Res_a(G1, G_m) (of which it is a root) and all located roots must be equal
// (then all G vanish at (a_i, b*)). The result is an index into rb, none or unresolved.
template <int D>
std::vector<int> Curve_intersection_engine<D>::pair_all(const std::vector<Elimination>& e,
                                                     const std::vector<std::vector<Isolated_root>>& loc,
                                                     const std::vector<Isolated_root>& ra,
                                                     const std::vector<Isolated_root>& rb, bool rb_is_loc0) {
  std::vector<std::vector<int>> q;
  for (std::size_t m = 0; m < e.size(); ++m) q.push_back(pair_roots(e[m], ra, loc[m]));
  std::vector<int> out(ra.size(), none);
  for (std::size_t i = 0; i < ra.size(); ++i) {
    // "none" from one resolved pair proves that no partner exists in [0,1]
    bool unres = false, nothing = false;
    for (const auto& v : q) unres = unres || v[i] == unresolved;
    for (const auto& v : q) nothing = nothing || v[i] == none;
    if (nothing) continue;
    if (unres) {
      out[i] = unresolved;
      continue;
    }
    const Algebraic_real& b = loc[0][q[0][i]].root;
    bool same = true;
    for (std::size_t m = 1; m < q.size(); ++m) same = same && loc[m][q[m][i]].root == b;
    if (!same) continue;
    if (rb_is_loc0) {
      out[i] = q[0][i];
      continue;
    }
    for (std::size_t j = 0; j < rb.size(); ++j)
      if (rb[j].root == b) out[i] = int(j);
  }
  return out;
}

template <int D>
Polynomial_1<Rational> Curve_intersection_engine<D>::to_rational(const P1& f) {
  std::vector<Rational> c;
  for (int i = 0; i <= f.degree(); ++i) c.push_back(Rational(f[i]));
  return Polynomial_1<Rational>(c.begin(), c.end());
}

template <int D>
Curve_intersection_point Curve_intersection_engine<D>::make_point(const Isolated_root& s, const Isolated_root& t,
                                                               const Elimination& es, const Elimination& et,
                                                               bool s_direction) const {
  Curve_intersection_point p;
  p.s = s.root;
  p.t = t.root;
  const int m = std::min(s.multiplicity, t.multiplicity);
  p.tangent = m >= 2 && !tangents_apart(s.root, t.root) && parallel_tangents(s.root, t.root, s_direction ? es : et, s_direction);
  p.multiplicity = p.tangent ? m : 1;
  auto end = [](const Algebraic_real& x) { return x.is_rational() && (x == 0 || x == 1); };
  p.kind = (end(p.s) || end(p.t)) ? Curve_intersection_kind::endpoint
                                  : (p.tangent ? Curve_intersection_kind::tangent : Curve_intersection_kind::transversal);
  return p;
}

// Interval proof that the tangent directions at (s, t) are not parallel (some 2x2 minor of [D1(s); D2(t)] has an
// enclosure without 0), refining s and t; false = not proved (then parallel_tangents decides exactly).
template <int D>
bool Curve_intersection_engine<D>::tangents_apart(const Algebraic_real& s, const Algebraic_real& t) const {
  using I = internal::Mpfi_interval;
  for (int bits = 24; bits <= 96; bits *= 2) {
    Integer p2(1);
    mpz_mul_2exp(p2.mpz(), p2.mpz(), (unsigned long)bits);
    const Rational w = Rational(1) / Rational(p2);
    const mpfr_prec_t prec = mpfr_prec_t(64 + 2 * bits + coefficient_bits_);
    auto box = [&](const Algebraic_real& x) {
      if (x.is_rational()) return I::hull(x.rational_value(), x.rational_value(), prec);
      x.refine_to_width(w);
      return x.is_rational() ? I::hull(x.rational_value(), x.rational_value(), prec) : I::hull(x.lower(), x.upper(), prec);
    };
    const I us = box(s), ut = box(t);
    auto tangent = [&](const Form& H, const I& u) {
      std::array<I, D> d = make_array_of_intervals(prec);
      const I w0 = I::horner(H[0], u), dw0 = I::horner(CGAL::differentiate(H[0]), u);
      for (int k = 0; k < D; ++k)
        d[k] = I::horner(CGAL::differentiate(H[k + 1]), u) * w0 - I::horner(H[k + 1], u) * dw0;
      return d;
    };
    const auto da = tangent(H1_, us), db = tangent(H2_, ut);
    for (int i = 0; i < D; ++i)
      for (int j = i + 1; j < D; ++j)
        if (!(da[i] * db[j] - da[j] * db[i]).contains_zero()) return true;
  }
  return false;
}

// Tangent vectors D(u) = X_k' W - X_k W' are parallel iff all 2x2 minors of [D1(s); D2(t)] vanish; t is the
// rational function -S10/S11 of s (or symmetrically), so each minor is a univariate sign decision.
template <int D>
bool Curve_intersection_engine<D>::parallel_tangents(const Algebraic_real& s, const Algebraic_real& t,
                                                     const Elimination& e, bool s_direction) const {
  const Form& A = s_direction ? H1_ : H2_;
  const Form& B = s_direction ? H2_ : H1_;
  const Algebraic_real& a = s_direction ? s : t;
  (void)t;
  std::array<P1, D> da, db;
  for (int k = 0; k < D; ++k) {
    da[k] = CGAL::differentiate(A[k + 1]) * A[0] - A[k + 1] * CGAL::differentiate(A[0]);
    db[k] = CGAL::differentiate(B[k + 1]) * B[0] - B[k + 1] * CGAL::differentiate(B[0]);
  }
  const P1 N = -e.S10;
  for (int i = 0; i < D; ++i)
    for (int j = i + 1; j < D; ++j) {
      // da_i(a) db_j(b) - da_j(a) db_i(b), b = N/S11
      P2 m = lift_outer(db[j]) * P2(da[i]) - lift_outer(db[i]) * P2(da[j]);
      if (root_sign(a, substitute(m, N, e.S11)) != 0) return false;
    }
  return true;
}

template <int D>
std::array<internal::Mpfi_interval, D> Curve_intersection_engine<D>::make_array_of_intervals(mpfr_prec_t prec) {
  using I = internal::Mpfi_interval;
  if constexpr (D == 2) return {I(prec), I(prec)};
  else return {I(prec), I(prec), I(prec)};
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_CANDIDATE_PAIRS_H

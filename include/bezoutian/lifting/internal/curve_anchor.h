// The anchor of a zero curve where the arc runs within rounding of a side of its cell.
//
// The anchor of a span proof (partner_span_proofs.h: zero_curve_anchored) encloses gamma(t*), the zero of the
// partner equations E(t*, .) unique in a box, by Krawczyk's test at one value t* of the graph coordinate, and needs
// the enclosure G of its other coordinate strictly inside the cell: then (t*, gamma_0(t*)) is a point of D = 0 in
// the cell on the line through t*, which is the arc point. Where the arc touches the cell's side (D = 0 tangent to
// a side of the domain, as a torus's Villarceau circles are at the end of an arc) G straddles the side's value c
// from some depth of the halving on, whatever the precision of the test.
//
// The curve equation decides it exactly: (t*, gamma_0(t*)) lies on D = 0 (E vanishes there with nonzero weights,
// so the point has a partner and the projection operator vanishes on it). If q(o) = D(t*, o) has no zero on the
// part of G beyond c, gamma_0(t*) lies in the part of G inside the cell, and strictly so, since q(c) != 0.
// No zero between c and the end of G beyond it: the Taylor expansion of q about c, in exact rationals
// (curve_has_no_zero_beyond).
#ifndef BEZOUTIAN_LIFTING_INTERNAL_CURVE_ANCHOR_H
#define BEZOUTIAN_LIFTING_INTERNAL_CURVE_ANCHOR_H

#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace bezoutian {
namespace internal {

/// Whether D(x1, x2), restricted to the line {x_axis = t}, has no zero with the other coordinate o between the
/// value c, where D(t, c) != 0, and `end` (either side of c; exact). With o = c + sigma s, s in [0, H], sigma the
/// side's sign and p_k = sigma^k q_k the Taylor coefficients of D(t, o) about c: no zero if |p_0| > sum |p_k| H^k,
/// or if p' = sum k p_k s^(k-1) has the sign of p_0 on [0, H] (|p_1| > sum_{k>=2} k |p_k| H^(k-1)): then |p| grows
/// from |p_0| > 0. The second test holds where the arc comes within rounding of the side (q(c) tiny, q' not).
/// False also where neither test decides.
inline bool curve_has_no_zero_beyond(const Polynomial_2<Integer>& D, int axis, const Rational& t, const Rational& c,
                                     const Rational& end) {
  // q: the coefficients of D(t, o) (axis 0: D's outer variable x2 is o) or D(o, t) (axis 1) in o
  std::vector<Rational> q;
  if (axis == 0) {
    for (int j = 0; j <= D.degree(); ++j) {
      Rational s(0);
      for (int i = D[j].degree(); i >= 0; --i) s = s * t + Rational(D[j][i]);
      q.push_back(s);
    }
  } else {
    int inner = 0;
    for (int j = 0; j <= D.degree(); ++j) inner = std::max(inner, D[j].degree());
    q.assign(std::size_t(inner + 1), Rational(0));
    Rational power(1);
    for (int j = 0; j <= D.degree(); ++j, power = power * t)
      for (int i = 0; i <= D[j].degree(); ++i) q[std::size_t(i)] = q[std::size_t(i)] + Rational(D[j][i]) * power;
  }
  const std::size_t n = q.size();
  if (n == 0) return false;
  // the Taylor shift q(c + h) (repeated synthetic division by o - c), then h = sigma s
  for (std::size_t k = 0; k + 1 < n; ++k)
    for (std::size_t i = n - 1; i > k; --i) q[i - 1] = q[i - 1] + c * q[i];
  if (CGAL::is_zero(q[0])) return false;
  const bool down = end < c;
  const Rational H = down ? c - end : end - c;
  for (std::size_t k = 1; k < n; k += 2)
    if (down) q[k] = -q[k];
  Rational rest(0), power(1);
  for (std::size_t k = 1; k < n; ++k) {
    power = power * H;
    rest = rest + CGAL::abs(q[k]) * power;
  }
  if (CGAL::abs(q[0]) > rest) return true;
  if (n < 2 || CGAL::sign(q[1]) != CGAL::sign(q[0])) return false;
  Rational slope_rest(0);
  power = Rational(1);
  for (std::size_t k = 2; k < n; ++k) {
    power = power * H;
    slope_rest = slope_rest + Rational(int(k)) * CGAL::abs(q[k]) * power;
  }
  return CGAL::abs(q[1]) > slope_rest;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_INTERNAL_CURVE_ANCHOR_H

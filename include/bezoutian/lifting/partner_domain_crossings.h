// Points of an arc of D = 0 where the partner crosses the boundary of the partner domain: the genuine part of the
// locus ends there (buse-elkadi-galligo-2008 §4: a point of D = 0 is genuine iff a partner lies in the domain), e.g.
// where the intersection curve of two patches reaches a boundary curve of the second patch, or where a double
// curve of a self-intersection leaves the patch through its other sheet.
//
// Such a point z = (x1, x2, y1, y2) solves the square system
//   F(z) = (E1(z), E2(z), E3(z), g(z)) = 0,    g(z) = (coordinate c of the point P or Q) - (domain bound b),
// where E = 0 are the partner equations (double_partner_witness.h: P(x, y) and Q(x, y) have the same image) and
// g is linear. It is isolated by Krawczyk's test in R^4: if
//   K = m - C F(m) + (I - C F'(Z)) (Z - m) lies in the interior of Z  (m the centre of Z, C ~ F'(m)^-1),
// F has exactly one zero in Z and F' is regular there (Krawczyk 1969, Moore 1977). F' regular means that
// grad g is not orthogonal to the tangent of the curve E = 0: the partner crosses the line g = 0 transversally,
// so the status of the arc really changes there. With nonzero weights on Z (so E = 0 puts (x1, x2) on D = 0 with
// partner y) and Z's projection inside a cell where the subdivision proved D = 0 to be a graph over one
// coordinate, the zero is THE point of the arc over its graph coordinate. The crossing is then known as exactly
// as any algebraic point: the unique solution, in a proved box, of an explicit polynomial system with rational
// coefficients; the box is as narrow as double precision allows (about 1e-15).
#ifndef BEZOUTIAN_LIFTING_PARTNER_DOMAIN_CROSSINGS_H
#define BEZOUTIAN_LIFTING_PARTNER_DOMAIN_CROSSINGS_H

#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/lifting/double_partner_witness.h>

#include <array>
#include <cmath>
#include <optional>

namespace bezoutian {
namespace internal {

/// Is the double interval [x.lo, x.hi] inside [a, b] (exactly), disjoint from it?
inline bool interval_inside(const Double_interval& x, const Rational& a, const Rational& b) {
  return Rational(x.lo) >= a && Rational(x.hi) <= b;
}
inline bool interval_disjoint(const Double_interval& x, const Rational& a, const Rational& b) {
  return Rational(x.hi) < a || Rational(x.lo) > b;
}

/// A line of the partner domain's boundary: coordinate `coordinate` (0: u, 1: v) of the point P (`point` 0) or
/// Q (`point` 1) of the partner equations equals `bound`.
struct Partner_domain_side {
  int point = 0, coordinate = 0;
  Rational bound;
};

/// A certified crossing: `box` (x1, x2, y1, y2) holds exactly one zero of F (see the header comment).
struct Partner_domain_crossing {
  Partner_domain_side side;
  std::array<Double_interval, 4> box;
};

/// The coordinate of P or Q that `side` bounds, over z.
inline Double_interval side_coordinate(const Partner_equations& eq, const Partner_domain_side& side,
                                       const std::array<Double_interval, 4>& z) {
  std::array<Double_interval, 2> P, Q;
  eq.points(z, P, Q);
  return side.point == 0 ? P[side.coordinate] : Q[side.coordinate];
}

/// F(z) and its Jacobian F'(z) over the box z (outward-rounded).
inline void crossing_system(const Partner_equations& eq, const Partner_domain_side& side,
                            const std::array<Double_interval, 4>& z, std::array<Double_interval, 4>& F,
                            std::array<std::array<Double_interval, 4>, 4>& J) {
  std::array<Double_interval, 3> E;
  std::array<std::array<Double_interval, 4>, 3> JE;
  eq.evaluate(z, E, &JE);
  for (int r = 0; r < 3; ++r) F[r] = E[r], J[r] = JE[r];
  F[3] = side_coordinate(eq, side, z) - Double_interval::of(side.bound);
  for (int i = 0; i < 4; ++i) {
    const double d = side.point == 0 ? eq.dP(side.coordinate, i) : eq.dQ(side.coordinate, i);
    J[3][i] = Double_interval{d, d};
  }
}

/// Inverse of a 4 x 4 matrix of doubles by Gauss-Jordan elimination with partial pivoting (floating point: a
/// preconditioner or Newton step, never a decision); false if singular.
inline bool invert_4x4(std::array<std::array<double, 4>, 4> A, std::array<std::array<double, 4>, 4>& Inv) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) Inv[r][c] = r == c;
  for (int k = 0; k < 4; ++k) {
    int p = k;
    for (int r = k + 1; r < 4; ++r)
      if (std::fabs(A[r][k]) > std::fabs(A[p][k])) p = r;
    if (!(std::fabs(A[p][k]) > 0) || !std::isfinite(A[p][k])) return false;
    std::swap(A[k], A[p]);
    std::swap(Inv[k], Inv[p]);
    const double f = 1 / A[k][k];
    for (int c = 0; c < 4; ++c) A[k][c] *= f, Inv[k][c] *= f;
    for (int r = 0; r < 4; ++r)
      if (r != k && A[r][k] != 0) {
        const double g = A[r][k];
        for (int c = 0; c < 4; ++c) A[r][c] -= g * A[k][c], Inv[r][c] -= g * Inv[k][c];
      }
  }
  return true;
}

/// Krawczyk's test in R^4 on Z with strict inclusion; on success Z is replaced by K (which holds the zero).
inline bool crossing_krawczyk(const Partner_equations& eq, const Partner_domain_side& side,
                              std::array<Double_interval, 4>& Z) {
  using D = Double_interval;
  std::array<D, 4> m, Fm, FZ;
  for (int c = 0; c < 4; ++c) m[c] = D{Z[c].mid(), Z[c].mid()};
  std::array<std::array<D, 4>, 4> Jm, JZ;
  crossing_system(eq, side, m, Fm, Jm);
  crossing_system(eq, side, Z, FZ, JZ);
  std::array<std::array<double, 4>, 4> A, C;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) A[r][c] = Jm[r][c].mid();
  if (!invert_4x4(A, C)) return false;
  std::array<D, 4> K;
  for (int r = 0; r < 4; ++r) {
    D k = m[r];
    for (int c = 0; c < 4; ++c) {
      k = k - D{C[r][c], C[r][c]} * Fm[c];
      D g{r == c ? 1.0 : 0.0, r == c ? 1.0 : 0.0};
      for (int l = 0; l < 4; ++l) g = g - D{C[r][l], C[r][l]} * JZ[l][c];
      k = k + g * (Z[c] - m[c]);
    }
    if (!(std::isfinite(k.lo) && std::isfinite(k.hi) && Z[r].lo < k.lo && k.hi < Z[r].hi)) return false;
    K[r] = k;
  }
  Z = K;
  return true;
}

/// Newton's method on F from `z` (floating point), then Krawczyk's test on a small box around the result, with
/// epsilon-inflation and a few contractions. Empty if no box is proved.
inline std::optional<Partner_domain_crossing> isolate_crossing(const Partner_equations& eq,
                                                               const Partner_domain_side& side,
                                                               std::array<double, 4> z) {
  using D = Double_interval;
  for (int it = 0; it < 30; ++it) {
    std::array<D, 4> p, F;
    for (int c = 0; c < 4; ++c) p[c] = D{z[c], z[c]};
    std::array<std::array<D, 4>, 4> J;
    crossing_system(eq, side, p, F, J);
    std::array<std::array<double, 4>, 4> A, C;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) A[r][c] = J[r][c].mid();
    if (!invert_4x4(A, C)) return std::nullopt;
    double step = 0, size = 0;
    for (int r = 0; r < 4; ++r) {
      double d = 0;
      for (int c = 0; c < 4; ++c) d += C[r][c] * F[c].mid();
      z[r] -= d;
      step += std::fabs(d), size += std::fabs(z[r]);
    }
    if (!std::isfinite(step) || step > 1e3 * (1 + size)) return std::nullopt;
    if (step <= 1e-15 * (1 + size)) break;
  }
  double r = 0;
  for (int c = 0; c < 4; ++c) r = std::max(r, 1e-12 * (1 + std::fabs(z[c])));
  for (int attempt = 0; attempt < 6; ++attempt, r *= 16) {
    std::array<D, 4> Z;
    for (int c = 0; c < 4; ++c) Z[c] = D{z[c] - r, z[c] + r};
    if (!crossing_krawczyk(eq, side, Z)) continue;
    for (int tighten = 0; tighten < 4; ++tighten) {  // each success keeps a box holding the (unique) zero
      std::array<D, 4> next = Z;
      if (!crossing_krawczyk(eq, side, next)) break;
      Z = next;
    }
    return Partner_domain_crossing{side, Z};
  }
  return std::nullopt;
}

/// Refines a certified crossing to boxes narrower than 2^-bits: Krawczyk's test in MPFI arithmetic at about
/// bits + 64 bits of precision, started from the proved double box (each step keeps the unique zero, and with
/// the double preconditioner each step shrinks the box by about the factor |I - C F'| ~ 1e-15 cond F'). The
/// result is exact: rational bounds {lo, hi} per coordinate (x1, x2, y1, y2). Empty if the test fails at the
/// higher precision (not expected after the double proof) or does not reach the width within 64 steps.
inline std::optional<std::array<std::array<Rational, 2>, 4>> refine_crossing(const Partner_equations& eq,
                                                                            const Partner_domain_crossing& c, int bits) {
  using I = Mpfi_interval;
  using Cx = Partner_equations::Cx;
  const mpfr_prec_t prec = std::max(bits, 53) + 64;
  const Partner_domain_side& side = c.side;
  auto real = [&](const std::array<I, 4>& x) {
    std::array<Cx, 4> z{Cx{x[0], I::point(0, prec)}, Cx{x[1], I::point(0, prec)}, Cx{x[2], I::point(0, prec)},
                        Cx{x[3], I::point(0, prec)}};
    return z;
  };
  auto coordinate = [&](const std::array<I, 4>& x) {
    I r = I::point(0, prec);
    for (int i = 0; i < 4; ++i) {
      const int d = side.point == 0 ? eq.dP(side.coordinate, i) : eq.dQ(side.coordinate, i);
      if (d) r = r + x[i];
    }
    return r - I::hull(side.bound, side.bound, prec);
  };
  const Cx zc{I::point(0, prec), I::point(0, prec)};
  std::array<Cx, 3> E{zc, zc, zc};
  std::array<std::array<Cx, 4>, 3> J{std::array<Cx, 4>{zc, zc, zc, zc}, std::array<Cx, 4>{zc, zc, zc, zc},
                                     std::array<Cx, 4>{zc, zc, zc, zc}};
  std::array<Cx, 2> w{zc, zc};
  auto value = [&](const std::array<I, 4>& x, std::array<I, 4>& F) {
    eq.evaluate(real(x), E, J, w);
    for (int r = 0; r < 3; ++r) F[r] = E[r].re;
    F[3] = coordinate(x);
  };
  auto jacobian = [&](const std::array<I, 4>& x, std::vector<std::vector<I>>& Jout) {
    eq.evaluate(real(x), E, J, w);
    for (int r = 0; r < 3; ++r)
      for (int i = 0; i < 4; ++i) Jout[r][i] = J[r][i].re;
    for (int i = 0; i < 4; ++i)
      Jout[3][i] = I::point(side.point == 0 ? eq.dP(side.coordinate, i) : eq.dQ(side.coordinate, i), prec);
  };
  std::array<I, 4> X{I::point(0, prec), I::point(0, prec), I::point(0, prec), I::point(0, prec)};
  for (int i = 0; i < 4; ++i) X[i] = I::hull(Rational(c.box[i].lo), Rational(c.box[i].hi), prec);
  const Rational target = Rational(1) / (Integer(1) << bits);
  for (int step = 0; step < 64; ++step) {
    if (step > 0)  // strict inclusion needs interior: widen by 2^-(bits + 16) (a coordinate may be exact)
      for (int i = 0; i < 4; ++i) X[i] = I::hull(X[i].lower() - target / 65536, X[i].upper() + target / 65536, prec);
    if (!krawczyk_prove<4>(X, value, jacobian)) return std::nullopt;
    bool narrow = true;
    for (int i = 0; i < 4; ++i) narrow = narrow && X[i].upper() - X[i].lower() < target;
    if (narrow) {
      std::array<std::array<Rational, 2>, 4> out;
      for (int i = 0; i < 4; ++i) out[i] = {X[i].lower(), X[i].upper()};
      return out;
    }
  }
  return std::nullopt;
}

/// The four lines of the partner domain's boundary that a partner can cross along an arc: P's second coordinate
/// and Q's first (the others are the projection's own coordinates, whose crossings are box-boundary vertices when
/// the box is the domain), both bounds; also P's first and Q's second when the box differs from the domain.
inline std::vector<Partner_domain_side> partner_domain_sides(const Parameter_box& domain, const Parameter_box& box) {
  std::vector<Partner_domain_side> out;
  auto add = [&](int point, int coordinate) {
    const bool u = coordinate == 0;
    out.push_back({point, coordinate, u ? domain.u0 : domain.v0});
    out.push_back({point, coordinate, u ? domain.u1 : domain.v1});
  };
  add(0, 1);
  add(1, 0);
  if (!(box.u0 == domain.u0 && box.u1 == domain.u1 && box.v0 == domain.v0 && box.v1 == domain.v1)) {
    add(0, 0);
    add(1, 1);
  }
  return out;
}

/// Searches the crossing of `side` between traced points a and b of an arc (z = (x1, x2, y1, y2): projection and
/// floating-point partner), where the side's coordinate changes sign. Certified only if, over the proved box Z:
/// the weights are nonzero; (self-intersection) the partner is not the trivial y = 0; the other coordinates of P
/// and Q lie inside the domain (so the crossing is a genuine point and the status changes only by this side);
/// Z's projection lies in the piece's cell `cell`, where D = 0 is a graph over `axis`; and its graph coordinate
/// lies strictly between the two traced points' (so the point is inserted between them, in order).
inline std::optional<Partner_domain_crossing> crossing_between(const Partner_equations& eq,
                                                               const Parameter_box& domain,
                                                               const std::vector<Partner_domain_side>& sides,
                                                               const std::array<double, 4>& a,
                                                               const std::array<double, 4>& b,
                                                               const Parameter_box& cell, int axis) {
  using D = Double_interval;
  auto coordinate_of = [&](const Partner_domain_side& s, const std::array<double, 4>& z) {
    std::array<D, 4> p;
    for (int c = 0; c < 4; ++c) p[c] = D{z[c], z[c]};
    return side_coordinate(eq, s, p).mid() - CGAL::to_double(s.bound);
  };
  // Newton's starting points: where the side's coordinate changes sign between a and b, the linear
  // interpolation; otherwise (one end's floating-point partner is another one, e.g. the trivial partner of a
  // self-intersection on the phantom side) each end itself.
  auto trivial = [&](const std::array<double, 4>& z) {
    return eq.self_intersection() && std::fabs(z[2]) + std::fabs(z[3]) <= 1e-9;
  };
  std::vector<std::pair<Partner_domain_side, std::array<double, 4>>> starts;
  for (const Partner_domain_side& s : sides) {
    const double fa = coordinate_of(s, a), fb = coordinate_of(s, b);
    if (fa * fb < 0 && !trivial(a) && !trivial(b)) {
      const double lambda = fa / (fa - fb);
      std::array<double, 4> z;
      for (int c = 0; c < 4; ++c) z[c] = a[c] + lambda * (b[c] - a[c]);
      starts.emplace_back(s, z);
    } else {
      for (const auto* z : {&a, &b})
        if (!trivial(*z) && std::isfinite((*z)[2]) && std::isfinite((*z)[3])) starts.emplace_back(s, *z);
    }
  }
  for (const auto& start : starts) {
    const Partner_domain_side& s = start.first;
    const auto found = isolate_crossing(eq, s, start.second);
    if (!found) continue;
    const std::array<D, 4>& Z = found->box;
    const auto w = eq.weights(Z);
    if (w[0].contains_zero() || w[1].contains_zero()) continue;
    if (eq.self_intersection() && Z[2].contains_zero() && Z[3].contains_zero()) continue;
    std::array<D, 2> P, Q;
    eq.points(Z, P, Q);
    bool others_inside = true;
    for (int point = 0; point < 2; ++point)
      for (int coordinate = 0; coordinate < 2; ++coordinate) {
        if (point == s.point && coordinate == s.coordinate) continue;
        const D& x = point == 0 ? P[coordinate] : Q[coordinate];
        others_inside = others_inside && (coordinate == 0 ? interval_inside(x, domain.u0, domain.u1)
                                                          : interval_inside(x, domain.v0, domain.v1));
      }
    if (!others_inside) continue;
    if (!(interval_inside(Z[0], cell.u0, cell.u1) && interval_inside(Z[1], cell.v0, cell.v1))) continue;
    const double lo = std::min(a[axis], b[axis]), hi = std::max(a[axis], b[axis]);
    if (!(lo < Z[axis].lo && Z[axis].hi < hi)) continue;
    return found;
  }
  return std::nullopt;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_PARTNER_DOMAIN_CROSSINGS_H

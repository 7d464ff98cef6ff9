// Exclusion of every partner next to a boundary curve shared by the two patches (a seam of a model), by blowing
// up the partner equations along the seam.
//
// Two patches phi (u, v) and psi (s, t) that share a boundary curve, phi(c, g(t)) = psi(c', t) (side u = c of
// the projection box, the partner's side s = c'; or t = c and v = c', with s = g(u)), give the partner equations
// E(z) = 0 (double_partner_witness.h, z = (u, t, v, s)) a whole curve of zeros, the seam
//   Sigma = { z : z_x = c, z_y = c', z_d = g(z_a) }      (x: the fixed projection coordinate, y: the fixed partner
//                                                        coordinate, d: the partner coordinate that follows a)
// Its points are genuine (the edge line, explained exactly by box_edge_lines.h). An arc of D = 0 that ends on
// the seam has its partner tending to the seam's partner; the exclusion boxes around that end hold points of
// Sigma, where E vanishes, so no exclusion test succeeds there however small the boxes (buse-elkadi-galligo-2008
// §4: the lifting asks for every partner in the domain, and here one exists at the end point).
//
// Blow-up. Write d1 = sigma1 (z_x - c) >= 0 (into the box), d2 = sigma2 (z_y - c') >= 0 (into the partner domain),
// d3 = z_d - g(z_a), and scale them by h1, h2, h3 (the region's extent). Every point of the region off Sigma has
// r = max(d1 / h1, d2 / h2, |d3| / h3) in (0, 1] and alpha = (d1 / h1, d2 / h2, d3 / h3) / r on one of the four
// faces alpha1 = 1, alpha2 = 1, alpha3 = 1, alpha3 = -1 of [0, 1]^2 x [-1, 1]. With z0 = (c, c', g(a), a) on
// Sigma and Delta = (sigma1 h1 alpha1, sigma2 h2 alpha2, h3 alpha3) in the coordinates (x, y, d),
//   E(z0 + r Delta) = E(z0) + r grad E(xi) . Delta = r F,   F in J(H) . Delta,
// by the mean value theorem (E(z0) = 0 exactly on Sigma, xi on the segment from z0, H the box hull of the
// segments). So a chart box (r, a, two free alphas) on which an enclosure of F (or of E itself, for r > 0)
// excludes zero holds no zero of E off Sigma. On r = 0 (the exceptional divisor) F is the derivative of E along
// Delta at the seam: it vanishes only along the kernel of the Jacobian. Where the patches continue each other
// across the seam (tangent planes equal, the patches on opposite sides), the kernel's direction off the seam
// leaves one domain to enter the other (d1 > 0 forces d2 < 0), outside the closed region d2 >= 0; at a crease the
// kernel is the seam's tangent alone. Either way F is bounded away from zero near r = 0 and the subdivision of
// the chart boxes terminates. Where the patches meet the seam from the same side (a fold back), the kernel's
// direction lies in the region and the test fails: correctly, as a genuine partner may then run along.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_SEAM_BLOWUP_EXCLUSION_H
#define BEZOUTIAN_LIFTING_INTERNAL_SEAM_BLOWUP_EXCLUSION_H

#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/internal/combined_equations_exclusion.h>
#include <bezoutian/lifting/internal/partner_span_proofs.h>
#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace bezoutian {
namespace internal {

/// A boundary curve shared by the two patches of an intersection, in the coordinates z = (u, t, v, s) of the
/// partner equations: z[fixed_x] = x_value (a side of the projection box), z[fixed_y] = y_value (a side of the
/// partner domain), z[dependent] = g0 + g1 z[along]. The identity E = 0 on it is proved exactly (shared_seam).
struct Shared_seam {
  int fixed_x = 0, fixed_y = 3, dependent = 2, along = 1;
  Rational x_value, y_value, g0, g1;
  int x_inward = 1, y_inward = 1;  ///< +1: the box (the partner domain) lies on the side z >= value
  Rational dependent_lo, dependent_hi;  ///< the partner domain's range of z[dependent]
  Rational fixed_y_lo, fixed_y_hi;      ///< the partner domain's range of z[fixed_y] (y_value is one of its ends)
};

namespace seam_detail {

using Poly = std::vector<Rational>;  // univariate, coefficient k multiplies a^k

inline Poly mul(const Poly& p, const Poly& q) {
  if (p.empty() || q.empty()) return {};
  Poly r(p.size() + q.size() - 1, Rational(0));
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < q.size(); ++j) r[i + j] += p[i] * q[j];
  return r;
}
inline Poly add(Poly p, const Poly& q, const Rational& f = Rational(1)) {
  if (p.size() < q.size()) p.resize(q.size(), Rational(0));
  for (std::size_t i = 0; i < q.size(); ++i) p[i] += f * q[i];
  return p;
}
// the power form f ([j][i] multiplies x^i y^j) along x = x(a), y = y(a), both polynomials in a
inline Poly compose(const std::vector<std::vector<Rational>>& f, const Poly& x, const Poly& y) {
  Poly r;
  for (std::size_t j = f.size(); j-- > 0;) {
    Poly row;
    for (std::size_t i = f[j].size(); i-- > 0;) row = add(mul(row, x), Poly{f[j][i]});
    r = add(mul(r, y), row);
  }
  return r;
}
inline bool is_zero(const Poly& p) {
  for (const Rational& c : p)
    if (c != 0) return false;
  return true;
}

}  // namespace seam_detail

/// The seam of an edge line explained as a shared boundary curve (Edge_line_explanation::shared_curve): side
/// `side` of the projection box `box` (boundary_curve order: 1, 3 are u = c; 0, 2 are t = c), the partner
/// domain's side `partner_side` at `partner_value`. The correspondence g is sought among the affine maps that
/// carry the box's range of the free coordinate onto the partner domain's range of the dependent one (either
/// direction) and the identity and reflection a -> a, a -> 1 - a; the one kept makes E vanish identically on the
/// seam, checked exactly on the power forms. Empty when none does (a seam shared with another parametrization).
inline std::optional<Shared_seam> shared_seam(const Partner_equations& eq, int side, const Rational& c,
                                              int partner_side, const Rational& partner_value,
                                              const Parameter_box& box, const Parameter_box& domain) {
  using namespace seam_detail;
  if (eq.self_intersection() || partner_side < 0) return std::nullopt;
  const bool vertical = side == 1 || side == 3;
  Shared_seam S;
  S.x_value = c;
  S.y_value = partner_value;
  if (vertical) {  // u = c; the partner's s = c'; v = g(t)
    S.fixed_x = 0, S.fixed_y = 3, S.dependent = 2, S.along = 1;
    S.x_inward = c == box.u0 ? 1 : -1;
    S.y_inward = partner_value == domain.u0 ? 1 : -1;
    S.dependent_lo = domain.v0, S.dependent_hi = domain.v1;
    S.fixed_y_lo = domain.u0, S.fixed_y_hi = domain.u1;
  } else {  // t = c; the partner's v = c'; s = g(u)
    S.fixed_x = 1, S.fixed_y = 2, S.dependent = 3, S.along = 0;
    S.x_inward = c == box.v0 ? 1 : -1;
    S.y_inward = partner_value == domain.v0 ? 1 : -1;
    S.dependent_lo = domain.u0, S.dependent_hi = domain.u1;
    S.fixed_y_lo = domain.v0, S.fixed_y_hi = domain.v1;
  }
  const Rational a0 = vertical ? box.v0 : box.u0, a1 = vertical ? box.v1 : box.u1;
  if (!(a0 < a1) || !(S.dependent_lo < S.dependent_hi)) return std::nullopt;
  const Rational k = (S.dependent_hi - S.dependent_lo) / (a1 - a0);
  const std::array<std::array<Rational, 2>, 4> candidates{{{S.dependent_lo - k * a0, k},
                                                           {S.dependent_hi + k * a0, -k},
                                                           {Rational(0), Rational(1)},
                                                           {Rational(1), Rational(-1)}}};
  for (const auto& g : candidates) {
    std::array<Poly, 4> z;  // the seam's coordinates as polynomials in a
    z[std::size_t(S.fixed_x)] = {c};
    z[std::size_t(S.fixed_y)] = {partner_value};
    z[std::size_t(S.dependent)] = {g[0], g[1]};
    z[std::size_t(S.along)] = {Rational(0), Rational(1)};
    // P = (z0, z2) on phi, Q = (z3, z1) on psi (Partner_equations::points)
    std::array<Poly, 4> A, B;
    for (int f = 0; f < 4; ++f) {
      A[std::size_t(f)] = compose(eq.form(0, f), z[0], z[2]);
      B[std::size_t(f)] = compose(eq.form(1, f), z[3], z[1]);
    }
    bool vanishes = true;
    for (int f = 1; f <= 3 && vanishes; ++f)
      vanishes = is_zero(add(mul(A[std::size_t(f)], B[0]), mul(B[std::size_t(f)], A[0]), Rational(-1)));
    if (vanishes) {
      S.g0 = g[0];
      S.g1 = g[1];
      return S;
    }
  }
  return std::nullopt;
}

/// Proves that every zero of the partner equations with (u, t) in the box `X` and its partner (v, s) in the
/// partner domain lies on the seam S (module comment). `X` must touch the seam's side of the projection box
/// (its range of z[fixed_x] ends at the seam's value, on the box's side); false otherwise, and when the chart
/// boxes are not all excluded within `max_boxes` tests.
inline bool only_seam_zeros(const Partner_equations& eq, const Shared_seam& S, const Parameter_box& X,
                            Exclusion_budget& budget, std::size_t max_boxes = 6000) {
  using D = Double_interval;
  const Rational x_lo = S.fixed_x == 0 ? X.u0 : X.v0, x_hi = S.fixed_x == 0 ? X.u1 : X.v1;
  if (S.x_inward > 0 ? x_lo != S.x_value : x_hi != S.x_value) return false;
  const Rational a_lo = S.along == 0 ? X.u0 : X.v0, a_hi = S.along == 0 ? X.u1 : X.v1;
  const D one{1, 1};
  const D h1 = D::of(x_hi - x_lo), A = D::hull(a_lo, a_hi), g0 = D::of(S.g0), g1 = D::of(S.g1),
          xc = D::of(S.x_value), yc = D::of(S.y_value), dlo = D::of(S.dependent_lo), dhi = D::of(S.dependent_hi);
  const D G = g0 + g1 * A;  // g over the along range
  // d2 runs over the partner domain's width on z[fixed_y]; d3 = z_d - g(a) over [dlo - G.hi, dhi - G.lo]
  const D h2 = D::of(S.fixed_y_hi - S.fixed_y_lo);
  const double h3 = std::max((dhi - G).hi, (G - dlo).hi);
  if (!(h1.hi > 0) || !(h2.hi > 0) || !(h3 > 0) || !(A.lo <= A.hi)) return false;
  const D H1{h1.hi, h1.hi}, H2{h2.hi, h2.hi}, H3{h3, h3};
  const D s1{double(S.x_inward), double(S.x_inward)}, s2{double(S.y_inward), double(S.y_inward)};
  struct Chart_box {
    int face;  // 0: alpha1 = 1, 1: alpha2 = 1, 2: alpha3 = 1, 3: alpha3 = -1
    D r, a, p, q;  // p, q: the two free alphas (in the order alpha1, alpha2, alpha3 without the face's)
  };
  std::vector<Chart_box> stack;
  const D unit{0, 1}, sym{-1, 1};
  stack.push_back({0, unit, A, unit, sym});
  stack.push_back({1, unit, A, unit, sym});
  stack.push_back({2, unit, A, unit, unit});
  stack.push_back({3, unit, A, unit, unit});
  const double a_width = std::max(A.hi - A.lo, 1e-300);
  std::size_t tests = 0;
  while (!stack.empty()) {
    const Chart_box b = stack.back();
    stack.pop_back();
    if (++tests > max_boxes) return false;
    if (tests % 64 == 0) budget.poll();
    const D alpha1 = b.face == 0 ? one : b.p, alpha2 = b.face == 1 ? one : (b.face == 0 ? b.p : b.q),
            alpha3 = b.face == 2 ? one : (b.face == 3 ? D{-1, -1} : b.q);
    // Delta, per unit r, in the coordinates (fixed_x, fixed_y, dependent); 0 along the seam
    std::array<D, 4> delta{D{0, 0}, D{0, 0}, D{0, 0}, D{0, 0}}, z0{}, z{}, hull{};
    delta[std::size_t(S.fixed_x)] = s1 * H1 * alpha1;
    delta[std::size_t(S.fixed_y)] = s2 * H2 * alpha2;
    delta[std::size_t(S.dependent)] = H3 * alpha3;
    z0[std::size_t(S.fixed_x)] = xc;
    z0[std::size_t(S.fixed_y)] = yc;
    z0[std::size_t(S.dependent)] = g0 + g1 * b.a;
    z0[std::size_t(S.along)] = b.a;
    const D segment{0, b.r.hi};
    for (std::size_t i = 0; i < 4; ++i) {
      z[i] = z0[i] + b.r * delta[i];
      hull[i] = z0[i] + segment * delta[i];
    }
    // (points of the chart box outside the partner domain's range of z[dependent] are not in the region)
    const D& zd = z[std::size_t(S.dependent)];
    bool excluded = zd.hi < dlo.lo || dhi.hi < zd.lo;
    std::array<D, 3> E;
    if (!excluded && b.r.lo > 0) {  // E itself (every point of the box is off the seam), in mean value form
      std::array<std::array<D, 4>, 3> J;
      eq.evaluate(z, E, &J);
      excluded = !E[0].contains_zero() || !E[1].contains_zero() || !E[2].contains_zero();
      if (!excluded) {
        std::array<D, 4> centre, dz;
        for (std::size_t i = 0; i < 4; ++i) {
          centre[i] = D{z[i].mid(), z[i].mid()};
          dz[i] = z[i] - centre[i];
        }
        std::array<D, 3> Ec;
        eq.evaluate(centre, Ec);
        for (int c = 0; c < 3 && !excluded; ++c) {
          D v = Ec[std::size_t(c)];
          for (std::size_t i = 0; i < 4; ++i) v = v + J[std::size_t(c)][i] * dz[i];
          excluded = !v.contains_zero();
        }
        excluded = excluded || combination_excludes_zero(Ec, J, dz);
      }
    }
    if (!excluded) {  // F = E / r in J(hull) . Delta
      std::array<std::array<D, 4>, 3> J;
      eq.evaluate(hull, E, &J);
      for (int c = 0; c < 3 && !excluded; ++c) {
        D F{0, 0};
        for (std::size_t i = 0; i < 4; ++i)
          if (i != std::size_t(S.along)) F = F + J[std::size_t(c)][i] * delta[i];
        excluded = !F.contains_zero();
      }
    }
    if (excluded) continue;
    // split the widest side, the along range measured against its full width
    const double w[4] = {b.r.hi - b.r.lo, (b.a.hi - b.a.lo) / a_width, b.p.hi - b.p.lo,
                         (b.q.hi - b.q.lo) / (b.face < 2 ? 2 : 1)};
    const int k = int(std::max_element(w, w + 4) - w);
    Chart_box lo = b, hi = b;
    D& x_lo = k == 0 ? lo.r : (k == 1 ? lo.a : (k == 2 ? lo.p : lo.q));
    D& x_hi = k == 0 ? hi.r : (k == 1 ? hi.a : (k == 2 ? hi.p : hi.q));
    const double m = x_lo.mid();
    if (!(x_lo.lo < m && m < x_lo.hi)) return false;  // cannot split further
    x_lo.hi = m;
    x_hi.lo = m;
    stack.push_back(hi);
    stack.push_back(lo);
  }
  return true;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_INTERNAL_SEAM_BLOWUP_EXCLUSION_H

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
  /// A common corner of the box and the partner domain instead of a curve: z[along] = along_value and
  /// z[dependent] = g0 (g1 = 0) as well, each one-sided (towards the box, the partner domain)
  bool corner = false;
  Rational along_value;
  int along_inward = 1, dependent_inward = 1;
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

/// The corners shared by the two patches: a corner (u*, v*) of the first patch's domain (u* a side of the box,
/// v* of the partner domain) and a corner (s*, t*) of the second's with the same point, E(u*, t*, v*, s*) = 0
/// exactly, both weights nonzero; as where four patches of a model meet at a vertex and two diagonal ones touch
/// there. Corners on one of the `seams` are left out (the seam's blow-up holds them), and so are corners on a
/// collapsed side of either patch (a pole).
inline std::vector<Shared_seam> shared_corners(const Partner_equations& eq, const Parameter_box& box,
                                               const Parameter_box& domain, const std::vector<Shared_seam>& seams) {
  using namespace seam_detail;
  std::vector<Shared_seam> out;
  if (eq.self_intersection() || !(box.u0 < box.u1) || !(box.v0 < box.v1) || !(domain.u0 < domain.u1) ||
      !(domain.v0 < domain.v1))
    return out;
  using Forms = std::array<Rational, 4>;
  auto at = [&](int which, const Rational& x, const Rational& y) {  // the forms of a patch at a point
    Forms F;
    for (int f = 0; f < 4; ++f) {
      const Poly p = compose(eq.form(which, f), {x}, {y});
      F[std::size_t(f)] = p.empty() ? Rational(0) : p[0];
    }
    return F;
  };
  auto same_point = [](const Forms& A, const Forms& B) {
    bool same = A[0] != 0 && B[0] != 0;
    for (std::size_t f = 1; f < 4 && same; ++f) same = A[f] * B[0] == B[f] * A[0];
    return same;
  };
  // a corner whose point is also a neighbouring corner's lies on a collapsed side (a pole): the zeros there form a
  // surface, not an isolated point, and the blow-up at the point cannot hold them
  auto on_collapsed_side = [&](int which, const Rational& x, const Rational& y, const Parameter_box& b) {
    const Forms P = at(which, x, y);
    return same_point(P, at(which, x == b.u0 ? b.u1 : b.u0, y)) || same_point(P, at(which, x, y == b.v0 ? b.v1 : b.v0));
  };
  // (the first patch's domain: u over the box, v over the partner domain; the second's: s over the partner
  // domain, t over the box)
  const Parameter_box first{box.u0, box.u1, domain.v0, domain.v1}, second{domain.u0, domain.u1, box.v0, box.v1};
  for (const Rational& u : {box.u0, box.u1})
    for (const Rational& t : {box.v0, box.v1})
      for (const Rational& v : {domain.v0, domain.v1})
        for (const Rational& s : {domain.u0, domain.u1}) {
          if (!same_point(at(0, u, v), at(1, s, t))) continue;
          if (on_collapsed_side(0, u, v, first) || on_collapsed_side(1, s, t, second)) continue;
          bool on_seam = false;
          for (const Shared_seam& S : seams) {
            const std::array<Rational, 4> z{u, t, v, s};
            on_seam = on_seam || (z[std::size_t(S.fixed_x)] == S.x_value && z[std::size_t(S.fixed_y)] == S.y_value &&
                                  z[std::size_t(S.dependent)] == S.g0 + S.g1 * z[std::size_t(S.along)]);
          }
          if (on_seam) continue;
          Shared_seam C;
          C.corner = true;
          C.fixed_x = 0, C.fixed_y = 3, C.dependent = 2, C.along = 1;
          C.x_value = u, C.x_inward = u == box.u0 ? 1 : -1;
          C.y_value = s, C.y_inward = s == domain.u0 ? 1 : -1;
          C.fixed_y_lo = domain.u0, C.fixed_y_hi = domain.u1;
          C.g0 = v, C.g1 = 0, C.dependent_inward = v == domain.v0 ? 1 : -1;
          C.dependent_lo = domain.v0, C.dependent_hi = domain.v1;
          C.along_value = t, C.along_inward = t == box.v0 ? 1 : -1;
          out.push_back(C);
        }
  return out;
}

/// Proves that every zero of the partner equations with (u, t) in the box `X` and its partner (v, s) in the
/// partner domain lies on the seam S, or is the corner S (module comment). `X` must reach the seam's side of the
/// projection box (its range of z[fixed_x] ends at the seam's value, on the box's side; for a corner, its range of
/// z[along] ends at that corner's value too); false otherwise, and when the chart boxes are not all excluded within
/// `max_boxes` tests and the locus's `budget.seam_boxes_left`, which pays for the tests taken.
inline bool only_seam_zeros(const Partner_equations& eq, const Shared_seam& S, const Parameter_box& X,
                            Exclusion_budget& budget, std::size_t max_boxes = 100000) {
  using D = Double_interval;
  std::size_t tests = 0;
  struct Pay {  // the tests taken, on every return
    Exclusion_budget& budget;
    const std::size_t& tests;
    ~Pay() { budget.seam_boxes_left -= std::min(tests, budget.seam_boxes_left); }
  } pay{budget, tests};
  max_boxes = std::min(max_boxes, budget.seam_boxes_left);
  auto range = [&](int i, Rational& lo, Rational& hi) {  // X's range of the projection coordinate z[i]
    lo = i == 0 ? X.u0 : X.v0;
    hi = i == 0 ? X.u1 : X.v1;
  };
  // X reaches the one-sided value c of z[i] from the side `inward`: the extent h of X from it
  auto reach = [&](int i, const Rational& c, int inward, D& h) {
    Rational lo, hi;
    range(i, lo, hi);
    if (inward > 0 ? lo != c : hi != c) return false;
    h = D::of(hi - lo);
    return h.hi > 0;
  };
  // Each coordinate: one-sided (blown up, alpha in [0, 1]), two-sided (blown up, alpha in [-1, 1]) or free (the
  // seam's own coordinate, not blown up). z_i = base_i + r step_i alpha_i, with base_dependent = g0 + g1 z_along.
  enum Role { one_sided, two_sided, free };
  std::array<Role, 4> role;
  std::array<D, 4> base, step;
  const D g0 = D::of(S.g0), g1 = D::of(S.g1), dlo = D::of(S.dependent_lo), dhi = D::of(S.dependent_hi);
  const std::size_t fx = std::size_t(S.fixed_x), fy = std::size_t(S.fixed_y), dep = std::size_t(S.dependent),
                    al = std::size_t(S.along);
  D h;
  if (!reach(S.fixed_x, S.x_value, S.x_inward, h)) return false;
  role[fx] = one_sided, base[fx] = D::of(S.x_value), step[fx] = D{double(S.x_inward), double(S.x_inward)} * D{h.hi, h.hi};
  h = D::of(S.fixed_y_hi - S.fixed_y_lo);
  if (!(h.hi > 0)) return false;
  role[fy] = one_sided, base[fy] = D::of(S.y_value), step[fy] = D{double(S.y_inward), double(S.y_inward)} * D{h.hi, h.hi};
  Rational a_lo, a_hi;
  range(S.along, a_lo, a_hi);
  const D A = D::hull(a_lo, a_hi);
  if (!(A.lo <= A.hi)) return false;
  if (S.corner) {
    if (!reach(S.along, S.along_value, S.along_inward, h)) return false;
    role[al] = one_sided, base[al] = D::of(S.along_value), step[al] = D{double(S.along_inward), double(S.along_inward)} * D{h.hi, h.hi};
    h = D::of(S.dependent_hi - S.dependent_lo);
    if (!(h.hi > 0)) return false;
    role[dep] = one_sided, base[dep] = g0,
    step[dep] = D{double(S.dependent_inward), double(S.dependent_inward)} * D{h.hi, h.hi};
  } else {
    // d3 = z_d - g(a) over [dlo - G.hi, dhi - G.lo], G = g over the along range
    const D G = g0 + g1 * A;
    const double h3 = std::max((dhi - G).hi, (G - dlo).hi);
    if (!(h3 > 0)) return false;
    role[al] = free, base[al] = A, step[al] = D{0, 0};
    role[dep] = two_sided, step[dep] = D{h3, h3};
  }
  struct Chart_box {
    std::size_t face;  // the coordinate whose alpha is +-1
    double sign;       // that alpha's value
    D r, a;            // a: the free coordinate's range (a seam)
    std::array<D, 4> alpha;
  };
  std::vector<Chart_box> stack;
  const D unit{0, 1}, sym{-1, 1};
  for (std::size_t f = 0; f < 4; ++f) {
    if (role[f] == free) continue;
    for (const double sign : {1.0, -1.0}) {
      if (sign < 0 && role[f] != two_sided) continue;
      Chart_box b{f, sign, unit, A, {}};
      for (std::size_t i = 0; i < 4; ++i) b.alpha[i] = role[i] == two_sided ? sym : unit;
      b.alpha[f] = D{sign, sign};
      stack.push_back(b);
    }
  }
  const double a_width = std::max(A.hi - A.lo, 1e-300);
  while (!stack.empty()) {
    const Chart_box b = stack.back();
    stack.pop_back();
    if (++tests > max_boxes) return false;
    if (tests % 64 == 0) budget.poll();
    // Delta (per unit r) and the centre z0 of the box's points; z = z0 + r Delta, hull: the segments from z0
    std::array<D, 4> delta, z0, z, hull;
    for (std::size_t i = 0; i < 4; ++i) {
      delta[i] = role[i] == free ? D{0, 0} : step[i] * b.alpha[i];
      z0[i] = role[i] == free ? b.a : base[i];
    }
    if (!S.corner) z0[dep] = g0 + g1 * b.a;
    const D segment{0, b.r.hi};
    for (std::size_t i = 0; i < 4; ++i) {
      z[i] = z0[i] + b.r * delta[i];
      hull[i] = z0[i] + segment * delta[i];
    }
    // (points of the chart box outside the partner domain's range of z[dependent] are not in the region)
    bool excluded = z[dep].hi < dlo.lo || dhi.hi < z[dep].lo;
    std::array<D, 3> E;
    if (!excluded && b.r.lo > 0) {  // E itself (every point of the box is off the centre), in mean value form
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
          if (role[i] != free) F = F + J[std::size_t(c)][i] * delta[i];
        excluded = !F.contains_zero();
      }
    }
    if (excluded) continue;
    // split the widest side: r, the free coordinate against its full width, the alphas against theirs
    double widest = b.r.hi - b.r.lo;
    int k = -2;  // -2: r, -1: a, i: alpha_i
    if (!S.corner && (b.a.hi - b.a.lo) / a_width > widest) widest = (b.a.hi - b.a.lo) / a_width, k = -1;
    for (std::size_t i = 0; i < 4; ++i) {
      if (role[i] == free || i == b.face) continue;
      const double w = (b.alpha[i].hi - b.alpha[i].lo) / (role[i] == two_sided ? 2 : 1);
      if (w > widest) widest = w, k = int(i);
    }
    Chart_box lo = b, hi = b;
    D& x_lo = k == -2 ? lo.r : (k == -1 ? lo.a : lo.alpha[std::size_t(k)]);
    D& x_hi = k == -2 ? hi.r : (k == -1 ? hi.a : hi.alpha[std::size_t(k)]);
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

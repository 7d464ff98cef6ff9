// Two patches that are pieces of one parametrized surface: Psi = Phi o M for a reparametrization M of the plane
// that keeps the tensor-product structure, M(s, t) = (alpha(s), beta(t)) or (alpha(t), beta(s)) with Moebius maps
// alpha, beta (geometry/Moebius_map.h). The two halves of a de Casteljau split, a sub-patch and its parent, a
// degree-elevated copy, two pieces of one sphere or cylinder given by rotated copies of one rational map are all of
// this kind. Phi(u, v) = Psi(s, t) then holds on the whole surface (u, v) = M(s, t), so for every (u, t) the
// eliminated system has a solution and det B vanishes identically (Theorems 2-3 need finite fibres): the
// intersection is found here instead.
//
// Theorem. Let D1, D2 be the parameter rectangles of Phi and Psi, R = M(D2) (a rectangle when alpha and beta are
// finite, hence monotone, on the sides of D2), H the smallest rectangle holding D1 and R, and suppose Phi is
// injective on H apart from sides of H collapsed to one point (prove_injective on Phi restricted to H). Then
//   Phi(D1) ∩ Psi(D2) = Phi(D1 ∩ R),  and  Phi(u, v) = Psi(s, t) iff (u, v) = M(s, t) in D1 ∩ R,
// for (u, v) in D1, (s, t) in D2, except at the one 3D point of a collapsed side of H, a boundary point of both
// patches (a boundary contact). Proof: Psi(s, t) = Phi(M(s, t)) with M(s, t) in R, a subset of H, and Phi is one to
// one on H. So the intersection is exactly a rectangle of both domains (an overlap), a common boundary segment, a
// common corner, or empty. The same holds with the roles exchanged (Phi = Psi o M^-1, H in Psi's parameters),
// which is tried when M is not finite on D2 or Phi is not proved injective on H.
//
// Finding M: Gauss-Newton in floating point finds preimages on Phi's continuation (over [-3, 4]^2) of five points of
// Psi, which give three values of alpha and three of beta; the Moebius maps through them, rounded to the simplest
// rationals, are then checked exactly as an identity of rational maps, Psi_k (Phi o M)_0 = (Phi o M)_k Psi_0 for
// k = 1, 2, 3 (homogeneous coordinates), so a degree-elevated copy or one with rescaled weights is found too. Both
// directions are searched (Psi in Phi's parameters, Phi in Psi's). Floating point only proposes M; the identity
// decides it.
#ifndef BEZOUTIAN_INTERSECTION_PATCH_COMMON_PARENT_H
#define BEZOUTIAN_INTERSECTION_PATCH_COMMON_PARENT_H

#include <bezoutian/arithmetic/exact_text.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/arithmetic/simplest_rational.h>
#include <bezoutian/geometry/Moebius_map.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/intersection/Patch_injectivity.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace bezoutian {

/// Psi(s, t) = Phi(M(s, t)) identically, M(s, t) = swapped ? (along_u(t), along_v(s)) : (along_u(s), along_v(t)).
struct Common_parent {
  bool found = false;
  bool swapped = false;
  Moebius_map along_u, along_v;
  std::string reason;
  /// M in words: "(u, v) = (..., ...)" in the variables s, t.
  std::string text() const {
    return "(u, v) = (" + along_u.text(swapped ? "t" : "s") + ", " + along_v.text(swapped ? "s" : "t") + ")";
  }
};

/// Outcome of intersect_common_parent().
struct Common_parent_intersection {
  /// A reparametrization Psi = Phi o M is proved (then `relation` holds it).
  bool related = false;
  /// The common part below is proved to be all of Phi(D1) ∩ Psi(D2) (the header's theorem); without this, the
  /// common part (when `related`) is still proved to be part of the intersection.
  bool proved = false;
  Common_parent relation;
  enum Kind { empty, corner, boundary_segment, region };
  Kind kind = empty;
  /// The common part D1 ∩ M(D2) in Phi's parameters {u0, u1, v0, v1} and its preimage in Psi's {s0, s1, t0, t1}
  /// (when not empty)
  std::array<Rational, 4> first{}, second{};
  std::string reason;
};

namespace internal {

using Rectangle = std::array<Rational, 4>;  // {x0, x1, y0, y1}

// (P o M) in homogeneous power form, bi-degree at most (m, n) in (x, y): the coordinates times
// (c_u x + d_u)^m (c_v y + d_v)^n, with x and y exchanged in M when `swapped`.
inline Rational_bezier_patch<Rational>::Power_form reparametrized_power_form(const Rational_bezier_patch<Rational>& P,
                                                                            const Common_parent& M) {
  using Poly1 = Polynomial_1<Rational>;
  using Poly2 = Polynomial_2<Rational>;
  auto linear = [](const Rational& slope, const Rational& constant, bool outer) {
    return outer ? Poly2(Poly1(constant), Poly1(slope)) : Poly2(Poly1(constant, slope));
  };
  const int m = P.degree_u(), n = P.degree_v();
  auto powers = [](const Poly2& p, int k) {
    std::vector<Poly2> out{Poly2(Rational(1))};
    for (int i = 1; i <= k; ++i) out.push_back(out.back() * p);
    return out;
  };
  const auto Nu = powers(linear(M.along_u.a, M.along_u.b, M.swapped), m);
  const auto Du = powers(linear(M.along_u.c, M.along_u.d, M.swapped), m);
  const auto Nv = powers(linear(M.along_v.a, M.along_v.b, !M.swapped), n);
  const auto Dv = powers(linear(M.along_v.c, M.along_v.d, !M.swapped), n);
  std::vector<Poly2> U, V;  // u^i and v^j after substitution and homogenization
  for (int i = 0; i <= m; ++i) U.push_back(Nu[std::size_t(i)] * Du[std::size_t(m - i)]);
  for (int j = 0; j <= n; ++j) V.push_back(Nv[std::size_t(j)] * Dv[std::size_t(n - j)]);
  const auto f = P.power_form();  // f[k][j][i]: coefficient of u^i v^j
  Rational_bezier_patch<Rational>::Power_form out;
  for (std::size_t k = 0; k < 4; ++k) {
    Poly2 F(Rational(0));
    for (int j = 0; j <= f[k].degree(); ++j) {
      Poly2 row(Rational(0));
      for (int i = 0; i <= f[k][j].degree(); ++i)
        if (!CGAL::is_zero(f[k][j][i])) row += U[std::size_t(i)] * f[k][j][i];
      F += row * V[std::size_t(j)];
    }
    out[k] = F;
  }
  return out;
}

// Psi = P o M as rational maps (exact).
inline bool is_reparametrization(const Rational_bezier_patch<Rational>& P, const Rational_bezier_patch<Rational>& Psi,
                                 const Common_parent& M) {
  const auto F = reparametrized_power_form(P, M);
  if (CGAL::is_zero(F[0])) return false;
  const auto g = Psi.power_form();
  for (std::size_t k = 1; k < 4; ++k)
    if (g[k] * F[0] != F[k] * g[0]) return false;
  return true;
}

// Floating-point preimages of x on the continuation of P over [-3, 4]^2: Gauss-Newton from a grid of starts.
inline std::vector<std::array<double, 2>> preimages(const Rational_bezier_patch<Rational>& P,
                                                    const std::array<double, 3>& x) {
  std::vector<std::array<double, 2>> out;
  const double scale = 1 + std::fabs(x[0]) + std::fabs(x[1]) + std::fabs(x[2]);
  auto residual = [&](double u, double v) {
    const auto p = P.evaluate(u, v);
    return std::array<double, 3>{p[0] - x[0], p[1] - x[1], p[2] - x[2]};
  };
  for (int i = 0; i <= 14; ++i)
    for (int j = 0; j <= 14; ++j) {
      double u = -3 + 0.5 * i, v = -3 + 0.5 * j;
      bool converged = false;
      for (int it = 0; it < 40 && !converged; ++it) {
        const auto f = residual(u, v);
        const double r = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        if (!std::isfinite(r) || std::fabs(u) > 10 || std::fabs(v) > 10) break;
        if (r < 1e-12 * scale) converged = true;
        const double hu = 1e-7 * (1 + std::fabs(u)), hv = 1e-7 * (1 + std::fabs(v));
        const auto a = residual(u + hu, v), b = residual(u - hu, v), c = residual(u, v + hv), d = residual(u, v - hv);
        double J[3][2], g[2] = {0, 0}, N[2][2] = {{0, 0}, {0, 0}};
        for (int k = 0; k < 3; ++k) {
          J[k][0] = (a[std::size_t(k)] - b[std::size_t(k)]) / (2 * hu);
          J[k][1] = (c[std::size_t(k)] - d[std::size_t(k)]) / (2 * hv);
          for (int p = 0; p < 2; ++p) {
            g[p] += J[k][p] * f[std::size_t(k)];
            for (int q = 0; q < 2; ++q) N[p][q] += J[k][p] * J[k][q];
          }
        }
        const double det = N[0][0] * N[1][1] - N[0][1] * N[1][0];
        if (!(std::fabs(det) > 1e-300)) break;
        double du = -(N[1][1] * g[0] - N[0][1] * g[1]) / det, dv = -(N[0][0] * g[1] - N[1][0] * g[0]) / det;
        const double len = std::hypot(du, dv);
        if (len > 1) du /= len, dv /= len;
        u += du;
        v += dv;
      }
      if (!converged) continue;
      bool seen = false;
      for (const auto& p : out) seen = seen || std::hypot(p[0] - u, p[1] - v) < 1e-7;
      if (!seen) out.push_back({u, v});
    }
  return out;
}

inline Rational simplest_near(double x) {
  const double w = 1e-9 * (1 + std::fabs(x));
  Rational r;
  if (!simplest_rational_in(Rational(x - w), Rational(x + w), r)) r = Rational(x);
  return r;
}

// Searches Psi = P o M from five points of Psi on the lines s = 1/2 and t = 1/2 (inside, away from collapsed sides).
inline bool find_reparametrization(const Rational_bezier_patch<Rational>& P, const Rational_bezier_patch<Rational>& Psi,
                                   Common_parent& M, const std::function<bool(const Common_parent&)>& accept) {
  const std::array<Rational, 3> x{Rational(1, 4), Rational(1, 2), Rational(3, 4)};
  // points 0, 1, 2 at (x_i, 1/2), points 3, 1, 4 at (1/2, x_i)
  const std::array<std::array<double, 2>, 5> at{{{0.25, 0.5}, {0.5, 0.5}, {0.75, 0.5}, {0.5, 0.25}, {0.5, 0.75}}};
  std::array<std::vector<std::array<double, 2>>, 5> pre;
  for (std::size_t i = 0; i < 5; ++i) {
    pre[i] = preimages(P, Psi.evaluate(at[i][0], at[i][1]));
    if (pre[i].empty()) return false;
  }
  const double tol = 1e-6;
  int tries = 0;
  for (const auto& c : pre[1])
    for (bool swapped : {false, true}) {
      // along s (points 0, 2) the coordinate fed by s varies: u unless swapped; the other one stays at c's
      const std::size_t varies_s = swapped ? 1 : 0, varies_t = 1 - varies_s;
      for (const auto& p0 : pre[0])
        for (const auto& p2 : pre[2])
          for (const auto& p3 : pre[3])
            for (const auto& p4 : pre[4]) {
              if (std::fabs(p0[varies_t] - c[varies_t]) > tol || std::fabs(p2[varies_t] - c[varies_t]) > tol ||
                  std::fabs(p3[varies_s] - c[varies_s]) > tol || std::fabs(p4[varies_s] - c[varies_s]) > tol)
                continue;
              if (++tries > 16) return false;
              const std::array<Rational, 3> ys{simplest_near(p0[varies_s]), simplest_near(c[varies_s]),
                                               simplest_near(p2[varies_s])};
              const std::array<Rational, 3> yt{simplest_near(p3[varies_t]), simplest_near(c[varies_t]),
                                               simplest_near(p4[varies_t])};
              Moebius_map fs, ft;
              if (!moebius_through(x, ys, fs) || !moebius_through(x, yt, ft)) continue;
              Common_parent candidate;
              candidate.swapped = swapped;
              candidate.along_u = swapped ? ft : fs;  // u = along_u(t) when swapped
              candidate.along_v = swapped ? fs : ft;
              // (a surface may have several: a sphere's (u, v) and its antipodal chart (-1/u, 1/v) name one point)
              if (!is_reparametrization(P, Psi, candidate) || !accept(candidate)) continue;
              M = candidate;
              M.found = true;
              return true;
            }
    }
  return false;
}

}  // namespace internal

/// \brief Finds a reparametrization M with Psi = Phi o M (see the header), proved by an exact identity of rational
/// maps. Returns found = false when none is found (which proves nothing).
/// `accept` may reject a reparametrization found (one with poles on the domains), so that the search goes on.
inline Common_parent find_common_parent(const Rational_bezier_patch<Rational>& phi,
                                        const Rational_bezier_patch<Rational>& psi,
                                        const std::function<bool(const Common_parent&)>& accept =
                                            [](const Common_parent&) { return true; }) {
  auto inverted = [](const Common_parent& N) {  // Phi = Psi o N  ->  Psi = Phi o N^-1
    Common_parent M;
    M.found = N.found;
    M.swapped = N.swapped;
    M.along_u = N.swapped ? N.along_v.inverse() : N.along_u.inverse();
    M.along_v = N.swapped ? N.along_u.inverse() : N.along_v.inverse();
    return M;
  };
  Common_parent M;
  if (internal::find_reparametrization(phi, psi, M, accept)) {
    M.reason = "the second patch is the first reparametrized, Psi(s, t) = Phi(u, v) with " + M.text() +
               " (an identity of rational maps, checked exactly)";
    return M;
  }
  Common_parent N;
  if (internal::find_reparametrization(psi, phi, N, [&](const Common_parent& n) { return accept(inverted(n)); })) {
    M = inverted(N);
    M.reason = "the first patch is the second reparametrized, Psi(s, t) = Phi(u, v) with " + M.text() +
               " (an identity of rational maps, checked exactly)";
    return M;
  }
  M.reason = "no reparametrization of one patch onto the other was found";
  return M;
}

/// \brief The intersection of Phi on D1 and Psi on D2 ({x0, x1, y0, y1} parameter rectangles) when one patch is a
/// reparametrization of the other (the header's theorem): proved exactly, or `proved` false with the reason.
inline Common_parent_intersection intersect_common_parent(const Rational_bezier_patch<Rational>& phi,
                                                          const Rational_bezier_patch<Rational>& psi,
                                                          const internal::Rectangle& D1, const internal::Rectangle& D2) {
  Common_parent_intersection out;
  // a map that, or whose inverse, is finite on the domain it is applied to (so that a hull H exists)
  auto usable = [&](const Common_parent& M) {
    const bool sw = M.swapped;
    const bool forward = M.along_u.finite_on(sw ? D2[2] : D2[0], sw ? D2[3] : D2[1]) &&
                         M.along_v.finite_on(sw ? D2[0] : D2[2], sw ? D2[1] : D2[3]);
    const bool backward = M.along_u.inverse().finite_on(D1[0], D1[1]) && M.along_v.inverse().finite_on(D1[2], D1[3]);
    return forward || backward;
  };
  out.relation = find_common_parent(phi, psi, usable);
  if (!out.relation.found) out.relation = find_common_parent(phi, psi);
  out.reason = out.relation.reason;
  if (!out.relation.found) return out;
  out.related = true;
  const Common_parent& M = out.relation;
  auto box_text = [](const internal::Rectangle& r) {
    return "[" + io::to_exact_string(r[0]) + ", " + io::to_exact_string(r[1]) + "] x [" + io::to_exact_string(r[2]) +
           ", " + io::to_exact_string(r[3]) + "]";
  };
  static const char* kinds[] = {"nothing", "a common corner (a boundary contact)",
                                "a common boundary segment (a boundary contact)", "a common region (an overlap)"};
  bool common_part_known = false;  // out.kind, first, second hold Phi(D1 ∩ M(D2)), part of the intersection
  std::string failures;
  for (int parent = 0; parent < 2; ++parent) {
    const Rational_bezier_patch<Rational>& P = parent == 0 ? phi : psi;
    const internal::Rectangle &own = parent == 0 ? D1 : D2, &other = parent == 0 ? D2 : D1;
    // the other patch's parameters (x, y) in P's: (fu(x or y), fv(y or x)), M or its inverse
    const bool sw = M.swapped;
    const Moebius_map fu = parent == 0 ? M.along_u : (sw ? M.along_v.inverse() : M.along_u.inverse());
    const Moebius_map fv = parent == 0 ? M.along_v : (sw ? M.along_u.inverse() : M.along_v.inverse());
    const Rational &ux0 = sw ? other[2] : other[0], &ux1 = sw ? other[3] : other[1];  // fed into fu
    const Rational &vx0 = sw ? other[0] : other[2], &vx1 = sw ? other[1] : other[3];  // fed into fv
    const std::string where = parent == 0 ? "the first patch's" : "the second patch's";
    if (!fu.finite_on(ux0, ux1) || !fv.finite_on(vx0, vx1)) {
      failures += (failures.empty() ? "" : "; ") + std::string("the map into ") + where + " parameters has a pole";
      continue;
    }
    const auto ur = fu.image(ux0, ux1), vr = fv.image(vx0, vx1);
    const internal::Rectangle I{std::max(own[0], ur[0]), std::min(own[1], ur[1]), std::max(own[2], vr[0]),
                                std::min(own[3], vr[1])};
    const bool meet = I[0] <= I[1] && I[2] <= I[3];
    if (!common_part_known) {  // the common part is the same from either side: record it once
      common_part_known = true;
      if (meet) {
        const int dims = int(I[0] < I[1]) + int(I[2] < I[3]);
        out.kind = dims == 2   ? Common_parent_intersection::region
                   : dims == 1 ? Common_parent_intersection::boundary_segment
                               : Common_parent_intersection::corner;
        // I in the other patch's parameters
        const auto xu = fu.inverse().image(I[0], I[1]), xv = fv.inverse().image(I[2], I[3]);
        const internal::Rectangle J = sw ? internal::Rectangle{xv[0], xv[1], xu[0], xu[1]}
                                         : internal::Rectangle{xu[0], xu[1], xv[0], xv[1]};
        out.first = parent == 0 ? I : J;
        out.second = parent == 0 ? J : I;
      }
    }
    const internal::Rectangle H{std::min(own[0], ur[0]), std::max(own[1], ur[1]), std::min(own[2], vr[0]),
                                std::max(own[3], vr[1])};
    // P on H. Its Bernstein weights there may be non-positive where the weight function is not (a half circle of
    // degree 2 has a zero middle weight, and with it a zero control vector): degree elevation, done before the
    // restriction (the two commute), makes them positive if the weight has no zero on H (Bernstein coefficients
    // of a positive polynomial converge to its values under elevation)
    Rational_bezier_patch<Rational> Q = P;
    bool positive = false;
    for (int e = 0; e <= 4 && !positive; ++e) {
      try {
        Q = P.elevated(e, e).restriction(H[0], H[1], H[2], H[3]);
      } catch (const Invalid_input&) {
        continue;  // a zero control vector: elevate further
      }
      positive = Q.has_positive_weights();
    }
    Injectivity_proof proof;
    if (positive)
      proof = prove_injective(Q);
    else
      proof.reason = "its Bernstein weights there are not all positive, even after degree elevation";
    if (!proof.proved) {
      failures += (failures.empty() ? "" : "; ") + where + " continuation on " + box_text(H) +
                  " is not proved injective (" + proof.reason + ")";
      continue;
    }
    out.proved = true;
    out.reason = M.reason + "; " + where + " continuation is injective on " + box_text(H) +
                 ", which holds both domains (" + proof.reason + "), so the patches meet exactly in " +
                 kinds[int(out.kind)];
    if (meet) out.reason += ": " + box_text(out.first) + " of the first patch, " + box_text(out.second) + " of the second";
    return out;
  }
  out.reason = M.reason;
  if (common_part_known && out.kind != Common_parent_intersection::empty)
    out.reason += "; the patches share " + std::string(kinds[int(out.kind)]) + ": " + box_text(out.first) +
                  " of the first patch, " + box_text(out.second) + " of the second";
  out.reason += "; other intersection points (where a patch self-intersects) are not decided: " + failures;
  return out;
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_INTERSECTION_PATCH_COMMON_PARENT_H

// One fold of D = 0 in a box of the subdivision (Curve_topology_by_subdivision.h): a point p where the curve turns
// back across the lines x = const (D = D_y = 0, D_x != 0), such as the tip of a thin closed loop. Near the tip of a
// loop of width w the tangent becomes vertical (the fold) and horizontal (D = D_x = 0) about w^2 apart, and neither
// derivative of D keeps a sign on a box holding both: plain splitting needs boxes narrower than w^2, beyond the depth
// limit from w = 2^-14 on. This certificate resolves a box holding the fold whole.
//
// With y the coordinate across (v for axis 0, u for axis 1) and x the other one:
//  (1) sigma D_yy > 0 on the box (its Bernstein second differences in y, as in two_branch_box.h): on each line
//      x = const, sigma D is strictly convex in y; D_y has at most one zero phi(x) there, the minimiser of sigma D.
//  (2) On a thin strip X0 = [xa, xb] x [0, 1] around the floating-point fold, cut into pieces X_k along x, each with
//      a y-window [ylo_k, yhi_k] around the minimisers (a staircase that follows {D_y = 0}):
//       a. sigma D_y < 0 on X_k x [0, ylo_k] and sigma D_y > 0 on X_k x [yhi_k, 1]: every line of X0 has its
//          minimiser phi(x) inside its window, so {D_y = 0} over X0 is one continuous graph y = phi(x);
//       b. D_x has one strict sign on every X_k x [ylo_k, yhi_k], the same for all k: m(x) = sigma D(x, phi(x)), the
//          least value of sigma D on the line, has m'(x) = sigma D_x(x, phi(x)) (D_y = 0 there), so m is strictly
//          monotone on X0;
//       c. m(xa) and m(xb) have strict opposite signs (m > 0 at an end: the coefficients of sigma D on that end's
//          window are positive; m < 0: sigma D < 0 at one point of the end line).
//      So X0 holds exactly one point p with D = D_y = 0, inside (xa, xb) x (min ylo_k, max yhi_k), and D_x(p) != 0.
//  (3) The rest of the box has no point with D = D_y = 0: two_branch::no_fold on [0, xa] and [xb, 1], whose
//      strips may also pass as valleys of sigma D above 0 (two_branch::Valley_bound: D != 0 there).
// Then D = 0 in the box, apart from p, is the union of C- = {D = 0, sigma D_y < 0} and C+ = {D = 0, sigma D_y > 0},
// each meeting every line x = const at most once: each is a union of graphs over disjoint x-intervals whose ends
// are crossings of the box's edges or p. At p the curve is smooth (D_x != 0) and tangent to x = x_p, and, as
// h''(y_p) = -D_yy / D_x != 0 for its local graph x = h(y), it lies on one side of that line: one arc of C- and one of
// C+ end at p, on the side of X0's end where m < 0. The caller pairs the ends of each family sorted along x, p
// included, as in a two-branch box: the two arcs at p are one arc of the curve through p.
//
// Interval arithmetic as in two_branch_box.h (Double_interval on the grid's proved enclosures); plain doubles choose
// p's position, the strip and its y-window, and screen the proof first.
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_FOLD_BOX_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_FOLD_BOX_H

#include <bezoutian/topology/internal/two_branch_box.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace bezoutian {
namespace internal {

/// What fold_certificate() proved: axis 0 (y = v, the fold a vertical tangent), 1 (y = u), -1 nothing. The fold
/// point lies in (xa, xb) x (ya, yb) in the box's local coordinates (x along, y across); the curve near it lies on
/// the side `curve_side` (+1: x > x_p, where m(xb) < 0; -1: x < x_p). sigma: the sign of D_yy on the box.
struct Fold_box {
  int axis = -1;
  int sigma = 0;
  double xa = 0, xb = 0, ya = 0, yb = 0;
  int curve_side = 0;
  /// nothing proved, but the plain-double screen passed: a sharper grid of the same box may succeed
  bool screened = false;
};

namespace fold {

using two_branch::Grid;

// The least value of sigma D on the line x of the box (floating point) and where it is reached.
inline double line_minimum(const Grid<double>& M, int sigma, double x, double& y) {
  std::vector<double> basis, c, w;
  two_branch::line_at(M, x, basis, c);
  y = two_branch::minimiser(c, sigma);
  return sigma * two_branch::bernstein_at(c, y, w);
}

// Floating point (a policy): where the least value of sigma D on the lines x = const changes sign with its minimiser
// inside the box (a fold of D = 0 there), by bisection between 32 lines. False if no line pair shows one.
inline bool locate(const Grid<double>& M, int sigma, double& x, double& y) {
  const int n = 32;
  double x0 = 0, y0 = 0, m0 = line_minimum(M, sigma, 0, y0);  // the last line with a nonzero minimum
  for (int k = 1; k <= n; ++k) {
    double y1 = 0;
    const double x1 = double(k) / n, m1 = line_minimum(M, sigma, x1, y1);
    if (m1 == 0) continue;  // a fold on a sample line: bracket it by its neighbours
    const bool inside = y0 > 0 && y0 < 1 && y1 > 0 && y1 < 1;
    if (inside && ((m0 < 0 && m1 > 0) || (m0 > 0 && m1 < 0))) {
      double a = x0, b = x1;
      const bool rising = m0 < 0;
      for (int it = 0; it < 60 && b - a > 1e-17; ++it) {
        const double mid = 0.5 * (a + b);
        double ym = 0;
        ((line_minimum(M, sigma, mid, ym) < 0) == rising ? a : b) = mid;
      }
      x = 0.5 * (a + b);
      line_minimum(M, sigma, x, y);
      return y > 0 && y < 1;
    }
    x0 = x1, y0 = y1, m0 = m1;
  }
  return false;
}

// A piece [xa, xb] of the fold strip with its y-window [ylo, yhi].
struct Window {
  double xa, xb, ylo, yhi;
};

// Conditions (2a)-(2c) of the header comment on the fold strip, cut into the pieces W (consecutive along x), each with
// its own y-window: (2a) and (2b) hold on each piece, with one sign of D_x for all, so m is strictly monotone on the
// whole strip; (2c) at its two ends. A staircase of windows follows a slanted line of minimisers {D_y = 0} closely,
// where one window over the whole strip would reach the curve D_x = 0 beside it. `side` receives the curve's side.
// `strips` counts the strip grids computed.
template <class N>
bool fold_strip(const Grid<N>& S, int sigma, const std::vector<Window>& W, int& side, std::size_t& strips) {
  const int nx = S.nx, ny = S.ny;
  Grid<N> T{nx, ny, std::vector<N>(S.v.size())}, U{nx, ny, std::vector<N>(S.v.size())};
  std::vector<N> w, col;
  auto column = [&](int i, double lo, double hi) {
    col.resize(std::size_t(ny + 1));
    for (int j = 0; j <= ny; ++j) col[std::size_t(j)] = T.at(i, j);
    two_branch::restrict_to(col, lo, hi);
    return col;
  };
  // (2c) at the end column i of the current piece: +1 if m > 0 there, -1 if m < 0, 0 if not proved
  auto end_sign = [&](int i) {
    bool above = true;  // sigma D > 0 on the end's segment [ylo, yhi], which holds the line's minimiser
    for (int j = 0; j <= ny; ++j) above = above && (sigma > 0 ? two_branch::lower(U.at(i, j)) > 0 : two_branch::upper(U.at(i, j)) < 0);
    if (above) return 1;
    std::vector<double> mid(std::size_t(ny + 1));
    for (int j = 0; j <= ny; ++j) mid[std::size_t(j)] = two_branch::middle(T.at(i, j));
    const double y = two_branch::minimiser(mid, sigma);  // a point of the end line where sigma D < 0 (to be proved)
    const std::vector<N>& v = column(i, y, y);
    return (sigma > 0 ? two_branch::upper(v[0]) < 0 : two_branch::lower(v[0]) > 0) ? -1 : 0;
  };
  int dx_sign = 0, sa = 0, sb = 0;
  for (std::size_t k = 0; k < W.size(); ++k) {
    const Window& q = W[k];
    two_branch::strip_grid(S, q.xa, q.xb, T, w);
    ++strips;
    for (int i = 0; i <= nx; ++i) {
      // (2a): the differences in y of D on [0, ylo] have the sign -sigma, on [yhi, 1] the sign sigma
      for (int part = 0; part < 2; ++part) {
        const std::vector<N>& c = part == 0 ? column(i, 0, q.ylo) : column(i, q.yhi, 1);
        const int want = part == 0 ? -sigma : sigma;
        for (int j = 0; j < ny; ++j) {
          const N d = c[std::size_t(j + 1)] - c[std::size_t(j)];
          if (!(want > 0 ? two_branch::lower(d) > 0 : two_branch::upper(d) < 0)) return false;
        }
      }
      const std::vector<N>& c = column(i, q.ylo, q.yhi);
      for (int j = 0; j <= ny; ++j) U.at(i, j) = c[std::size_t(j)];
    }
    // (2b): D_x on the piece's window, nx times the differences in x of U: one strict sign, the same on all pieces
    bool pos = true, neg = true;
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j <= ny; ++j) {
        const N d = U.at(i + 1, j) - U.at(i, j);
        pos = pos && two_branch::lower(d) > 0;
        neg = neg && two_branch::upper(d) < 0;
      }
    const int s = pos ? 1 : (neg ? -1 : 0);
    if (s == 0 || (dx_sign != 0 && s != dx_sign)) return false;
    dx_sign = s;
    if (k == 0) sa = end_sign(0);
    if (k + 1 == W.size()) sb = end_sign(nx);
  }
  if (sa * sb != -1) return false;
  side = sb < 0 ? 1 : -1;
  return true;
}

// The fold strip around x (local coordinates) of half-width d, cut into `pieces` windows: each spans the minimisers
// of sigma D on its two end lines, widened by a quarter of their distance and by 2^-30 (floating point: a policy, the
// windows are then proved). A window must stay closer to the minimisers than the curve D_x = 0, which runs beside
// them about the squared width of a thin loop away.
inline std::vector<Window> strip_windows(const Grid<double>& M, int sigma, double x, double d, int pieces) {
  const double xa = std::max(0.0, x - d), xb = std::min(1.0, x + d);
  std::vector<Window> W;
  if (!(xa < xb)) return W;
  double y0 = 0;
  line_minimum(M, sigma, xa, y0);
  for (int k = 1; k <= pieces; ++k) {
    const double a = W.empty() ? xa : W.back().xb, b = k == pieces ? xb : xa + (xb - xa) * k / pieces;
    double y1 = 0;
    line_minimum(M, sigma, b, y1);
    const double pad = 0.25 * std::fabs(y1 - y0) + std::ldexp(1.0, -30);
    W.push_back(Window{a, b, std::max(0.0, std::min(y0, y1) - pad), std::min(1.0, std::max(y0, y1) + pad)});
    if (!(W.back().ylo < W.back().yhi) || !(a < b)) return {};
    y0 = y1;
  }
  return W;
}

}  // namespace fold

/// The certificate of the header comment on the box whose Bernstein grid is G (proved radius): a fold with y = v is
/// tried first, then y = u. The fold strip's half-width is tried from 2^-8 down to 2^-40 of the box, with 1 window,
/// then 8 (wider strips and windows reach the curve D_x = 0 next to a loop's tip, narrower strips leave m's values
/// at the strip's ends below the grid's radius);
/// `max_depth`: at most this many halvings of the rest of the x-range (two_branch::no_fold). `strips` counts the work.
inline Fold_box fold_certificate(const Double_bernstein_grid& G, int max_depth = 48, std::size_t* strips = nullptr) {
  const double rho = G.radius();
  std::size_t work = 0;
  Fold_box out;
  for (int axis = 0; axis < 2; ++axis) {
    two_branch::Grid<double> M;
    int sigma = 0;
    if (!two_branch::across(G, axis, M, sigma)) continue;
    double x = 0, y = 0;
    if (!fold::locate(M, sigma, x, y)) continue;
    work += 64;  // the 32 lines and the bisection cost about 64 line evaluations, a strip grid each
    two_branch::Grid<Double_interval> S;  // the proved enclosures, computed once the screen passes
    // Half-widths 2^-8, 2^-12, ..., 2^-40 with one window per strip, then with a staircase of 8: the first that passes
    // the plain-double screen is proved (if the proof fails on the grid's radius, the caller may retry on a sharper
    // grid). The rest of the x-range is halved at most e + 12 times: the strips next to the fold strip need about
    // as many halvings as the fold strip is narrow, and a failing rest costs no more than that.
    int proofs = 0;
    bool rest_fails = false;
    for (int pieces : {1, 8}) {
      for (int e = 8; e <= 40 && proofs < 1 && !rest_fails; e += 4) {
        const int depth = std::min(max_depth, e + 12);
        const std::vector<fold::Window> W = fold::strip_windows(M, sigma, x, std::ldexp(1.0, -e), pieces);
        int side = 0;
        if (W.empty() || !fold::fold_strip(M, sigma, W, side, work)) continue;
        const double xa = W.front().xa, xb = W.back().xb;
        if (!two_branch::no_fold(M, sigma, 0, xa, depth, work, true) ||
            !two_branch::no_fold(M, sigma, xb, 1, depth, work, true)) {
          rest_fails = true;  // the rest of the box fails even in plain doubles: another fold, or a tangency
          break;
        }
        out.screened = true;
        ++proofs;
        if (S.v.empty()) S = two_branch::enclosure(M, rho);
        std::size_t proof = 0;
        const bool ok = fold::fold_strip(S, sigma, W, side, proof) &&
                        two_branch::no_fold(S, sigma, 0, xa, depth, proof, true) &&
                        two_branch::no_fold(S, sigma, xb, 1, depth, proof, true);
        work += 8 * proof;  // an interval operation costs about eight double ones
        if (!ok) continue;
        if (strips) *strips += work;
        out.axis = axis;
        out.sigma = sigma;
        out.xa = xa, out.xb = xb;
        out.ya = W.front().ylo, out.yb = W.front().yhi;
        for (const fold::Window& q : W) out.ya = std::min(out.ya, q.ylo), out.yb = std::max(out.yb, q.yhi);
        out.curve_side = side;
        return out;
      }
      if (proofs > 0 || rest_fails) break;  // the staircase only when no single window passed the screen
    }
  }
  if (strips) *strips += work;
  return out;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_FOLD_BOX_H

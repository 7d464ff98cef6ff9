// Two arcs of D = 0 in one box of the subdivision (Curve_topology_by_subdivision.h) where neither derivative of D
// keeps a sign. Two branches that run close together (between two nodes with nearly tangent branches, along a thin
// loop) otherwise force quadtree boxes thinner than the gap between them all along their length: a random (3,2)
// self-intersection spent 20000 boxes on such a pair and was not certified. This certificate resolves the box whole.
//
// Let y be the coordinate across the branches (v for graphs v = g(u), u for graphs u = g(v)) and x the other one.
//  (1) The Bernstein second differences of D in y have one strict sign sigma on the box: sigma D_yy > 0, so on each
//      line x = const, sigma D is strictly convex and has at most two zeros, one with sigma D_y < 0 and one with
//      sigma D_y > 0.
//  (2) No fold: no point of the closed box with D = D_y = 0. At such a point sigma D would reach its minimum 0 on
//      that line, so it suffices that on each line x = const either D_y or D has no zero, or sigma D takes a
//      negative value. The x-range is cut into pieces X (halving, or in the window where the minimiser of sigma D
//      leaves the box: window_cut); on each, the Bernstein coefficients of D on the
//      strip X x [0, 1] prove D_y != 0 (differences in y of one strict sign) or D != 0 (one strict sign), or those
//      of D restricted to a segment across the strip (from the minimiser of sigma D on the strip's left edge to the
//      one on its right edge, a segment inside the box over all of X) all have the sign -sigma.
// Then D = 0 in the box is the disjoint union of C- = {D = 0, sigma D_y < 0} and C+ = {D = 0, sigma D_y > 0}, both
// closed in the box, smooth (D_y != 0) and meeting each line x = const at most once: each is, like the curve in a
// simple box, a union of graphs over disjoint x-intervals whose ends are crossings of the box's edges. The caller
// classifies the exact crossings by the exact sign of D_y there and pairs consecutive crossings of each class
// along x.
//
// Interval arithmetic: Double_interval (one ulp outward per operation) on the grid's proved enclosures
// 2^e (m_ij +- rho); only the signs matter, so the common scale 2^e is left out. Restricting Bernstein coefficients to
// a sub-interval (de Casteljau) and to a segment (the restriction of each row, then the product rule
// B_p^n B_q^m = C(n,p) C(m,q) / C(n+m,p+q) B_(p+q)^(n+m); the positive factor 1 / C(n+m, k) does not change signs).
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_TWO_BRANCH_BOX_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_TWO_BRANCH_BOX_H

#include <bezoutian/topology/internal/double_bernstein_grid.h>
#include <bezoutian/arithmetic/double_interval.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <tuple>
#include <vector>

namespace bezoutian {
namespace internal {

/// What two_branch_certificate() proved: axis 0, graphs v = g(u) (y = v); axis 1, graphs u = g(v) (y = u); -1 nothing.
/// sigma: the sign of D_yy on the box.
struct Two_branch_box {
  int axis = -1;
  int sigma = 0;
  double gap = 1;  ///< floating point: the distance between the two branches across the box (branch_gap)
  /// nothing proved, but the plain-double screen passed for some axis: the proof failed on the grid's radius,
  /// and a sharper grid of the same box may succeed
  bool screened = false;
};

namespace two_branch {

using I = Double_interval;

// The two arithmetics of the certificate: Double_interval proves, plain double (midpoints) only screens a box
// first, at a fraction of the cost, so that boxes with a fold are rejected cheaply.
inline I constant(const I&, double x) { return I{x, x}; }
inline double constant(double, double x) { return x; }
inline I one_minus(const I& r) { return I::widen(1 - r.hi, 1 - r.lo); }
inline double one_minus(double r) { return 1 - r; }
inline I ratio(const I&, double a, double b) {
  I r = I::widen(a / b, a / b);
  r.hi = std::min(r.hi, 1.0);
  return r;
}
inline double ratio(double, double a, double b) { return a / b; }
inline double lower(const I& x) { return x.lo; }
inline double upper(const I& x) { return x.hi; }
inline double lower(double x) { return x; }
inline double upper(double x) { return x; }
inline double middle(const I& x) { return x.mid(); }
inline double middle(double x) { return x; }

// Bernstein coefficients w[0..n] of a polynomial on [0, 1] replaced by those of its restriction to [lo, hi]
// (0 <= lo <= hi <= 1): the left part of a de Casteljau split at hi, then the right part of that at lo / hi.
template <class T>
void restrict_to(std::vector<T>& w, double lo, double hi) {
  const std::size_t n = w.size() - 1;
  if (n == 0 || (lo == 0 && hi == 1)) return;
  std::vector<T> c(w), out(w.size());
  auto level_step = [&](const T& r, std::size_t level) {
    const T s = one_minus(r);
    for (std::size_t k = 0; k + level <= n; ++k) c[k] = s * c[k] + r * c[k + 1];
  };
  if (hi < 1) {
    const T r = constant(T{}, hi);
    out[0] = c[0];
    for (std::size_t level = 1; level <= n; ++level) level_step(r, level), out[level] = c[0];
    c = out;
  }
  if (lo > 0) {
    const T r = ratio(T{}, lo, hi);
    out[n] = c[n];
    for (std::size_t level = 1; level <= n; ++level) level_step(r, level), out[n - level] = c[n - level];
    c = out;
  }
  w = c;
}

// sum_j c_j B_j(t), Bernstein basis of degree c.size() - 1 (de Casteljau; floating point, for policies only).
inline double bernstein_at(const std::vector<double>& c, double t, std::vector<double>& w) {
  w.assign(c.begin(), c.end());
  for (std::size_t r = 1; r < w.size(); ++r)
    for (std::size_t k = 0; k + r < w.size(); ++k) w[k] = (1 - t) * w[k] + t * w[k + 1];
  return w.empty() ? 0 : w[0];
}

// A root of sum_j c_j B_j on [a, b] by bisection when the values at a and b have strict opposite signs, else NaN.
inline double bernstein_root(const std::vector<double>& c, double a, double b, int iterations) {
  std::vector<double> w;
  const double fa = bernstein_at(c, a, w), fb = bernstein_at(c, b, w);
  if (!(fa * fb < 0)) return std::numeric_limits<double>::quiet_NaN();
  for (int it = 0; it < iterations; ++it) {
    const double m = 0.5 * (a + b);
    ((bernstein_at(c, m, w) < 0) == (fa < 0) ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// The point of [0, 1] where sigma P is least, P(y) = sum_j c_j B_j(y) strictly convex times sigma (floating point: it
// only chooses a segment, whose coefficients are then proved).
inline double minimiser(const std::vector<double>& c, int sigma, int iterations = 55) {
  const std::size_t n = c.size() - 1;
  std::vector<double> d(n), w;
  for (std::size_t j = 0; j < n; ++j) d[j] = sigma * (c[j + 1] - c[j]);
  if (d[0] >= 0) return 0;
  if (d[n - 1] <= 0) return 1;
  double a = 0, b = 1;
  for (int it = 0; it < iterations && b - a > 1e-16; ++it) {
    const double m = 0.5 * (a + b);
    (bernstein_at(d, m, w) < 0 ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// A grid of coefficients, i along x (0..nx), j along y (0..ny).
template <class T>
struct Grid {
  int nx = 0, ny = 0;
  std::vector<T> v;
  T& at(int i, int j) { return v[std::size_t(i) * (ny + 1) + j]; }
  const T& at(int i, int j) const { return v[std::size_t(i) * (ny + 1) + j]; }
};

template <class T>
int common_sign(const Grid<T>& g) {
  bool pos = true, neg = true;
  for (const T& x : g.v) pos = pos && lower(x) > 0, neg = neg && upper(x) < 0;
  return pos ? 1 : (neg ? -1 : 0);
}

template <class T>
int difference_sign_y(const Grid<T>& g) {
  bool pos = true, neg = true;
  for (int i = 0; i <= g.nx && (pos || neg); ++i)
    for (int j = 0; j < g.ny; ++j) {
      const T d = g.at(i, j + 1) - g.at(i, j);
      pos = pos && lower(d) > 0;
      neg = neg && upper(d) < 0;
    }
  return pos ? 1 : (neg ? -1 : 0);
}

// Binomial coefficients C(n, k) (as intervals: Pascal's triangle with outward rounding).
template <class T>
std::vector<T> binomials(int n) {
  std::vector<T> c(std::size_t(n + 1), constant(T{}, 0));
  c[0] = constant(T{}, 1);
  for (int r = 1; r <= n; ++r)
    for (int k = r; k >= 1; --k) c[std::size_t(k)] = c[std::size_t(k)] + c[std::size_t(k - 1)];
  return c;
}

// Where, in the strip's local coordinate x, the minimiser of sigma D on the lines x = const reaches the box's edge
// y = e, when it lies on that edge at one end of the strip and inside the box at the other (floating point: D_y = 0
// on the edge there); NaN otherwise. `e` receives the edge.
template <class N>
double minimiser_exit(const Grid<N>& T, double y_left, double y_right, double& e) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool cl = y_left == 0 || y_left == 1, cr = y_right == 0 || y_right == 1;
  if (cl == cr || T.ny < 1) return nan;
  e = cl ? y_left : y_right;
  std::vector<double> dy(std::size_t(T.nx + 1));
  for (int i = 0; i <= T.nx; ++i)
    dy[std::size_t(i)] = e == 0 ? middle(T.at(i, 1)) - middle(T.at(i, 0)) : middle(T.at(i, T.ny)) - middle(T.at(i, T.ny - 1));
  const double x = bernstein_root(dy, 0, 1, 50);
  return x > 0 && x < 1 ? x : nan;
}

// Where to cut a strip whose tests failed, in its local coordinate x in (0, 1) (floating point: a policy, the pieces
// are then proved). The midpoint, unless the minimiser of sigma D lies on the box's edge y = e (e = 0 or 1) at one
// end of the strip and inside the box at the other. Between the point where a branch leaves the box through y = e
// (D = 0 there) and the point where the minimiser reaches that edge (D_y = 0 there), lines on the near side carry
// D_y != 0 in the whole box and lines on the far side a negative value of sigma D next to y = e, so a cut in that
// window lets both halves pass. The window is about (gap between the branches) / (their slope) wide: halving
// would find it only after many steps.
template <class N>
double window_cut(const Grid<N>& T, int sigma, double y_left, double y_right) {
  double e = 0;
  const double x_min = minimiser_exit(T, y_left, y_right, e);  // the minimiser reaches y = e
  if (std::isnan(x_min)) return 0.5;
  const int j = e == 0 ? 0 : T.ny;
  std::vector<double> val(std::size_t(T.nx + 1));
  for (int i = 0; i <= T.nx; ++i) val[std::size_t(i)] = sigma * middle(T.at(i, j));
  const double end = y_left == e ? 0 : 1;
  const double x_exit = bernstein_root(val, end, x_min, 50);  // a branch leaves through y = e
  if (!(x_exit >= 0 && x_exit <= 1)) return 0.5;
  const double cut = 0.5 * (x_min + x_exit);
  return cut > 1e-9 && cut < 1 - 1e-9 ? cut : 0.5;
}

// The strip's grid T: the columns (j fixed) of the box's grid S restricted to [xa, xb].
template <class N>
void strip_grid(const Grid<N>& S, double xa, double xb, Grid<N>& T, std::vector<N>& w) {
  for (int j = 0; j <= S.ny; ++j) {
    w.resize(std::size_t(S.nx + 1));
    for (int i = 0; i <= S.nx; ++i) w[std::size_t(i)] = S.at(i, j);
    restrict_to(w, xa, xb);
    for (int i = 0; i <= S.nx; ++i) T.at(i, j) = w[std::size_t(i)];
  }
}

// The segment from (0, ya) to (1, yb) across the strip (reversed: from (1, ya) to (0, yb)), ya <= yb:
// g_k = sum_{p+q=k} C(nx,p) C(ny,q) r_pq, r_p. the coefficients of row p of T restricted to [ya, yb], is
// C(nx+ny, k) times the k-th Bernstein coefficient of the polynomial of T on the segment. cx, cy: binomials.
template <class N>
std::vector<N> on_segment(const Grid<N>& T, double ya, double yb, bool reversed, const std::vector<N>& cx,
                          const std::vector<N>& cy, std::vector<N>& w) {
  std::vector<N> g(std::size_t(T.nx + T.ny + 1), constant(N{}, 0));
  for (int i = 0; i <= T.nx; ++i) {
    const int row = reversed ? T.nx - i : i;
    w.resize(std::size_t(T.ny + 1));
    for (int j = 0; j <= T.ny; ++j) w[std::size_t(j)] = T.at(row, j);
    restrict_to(w, ya, yb);
    for (int q = 0; q <= T.ny; ++q) g[std::size_t(i + q)] = g[std::size_t(i + q)] + cx[std::size_t(i)] * cy[std::size_t(q)] * w[std::size_t(q)];
  }
  return g;
}

// The minimisers of sigma D on the strip's two edges x = 0 and x = 1 (floating point).
template <class N>
std::pair<double, double> edge_minimisers(const Grid<N>& T, int sigma) {
  std::vector<double> left(std::size_t(T.ny + 1)), right(std::size_t(T.ny + 1));
  for (int j = 0; j <= T.ny; ++j) left[std::size_t(j)] = middle(T.at(0, j)), right[std::size_t(j)] = middle(T.at(T.nx, j));
  return {minimiser(left, sigma), minimiser(right, sigma)};
}

inline double quotient(double a, double c) { return a / c; }
// a / c for c > 0, outward rounded
inline I quotient(const I& a, const I& c) {
  const double q[4] = {a.lo / c.lo, a.lo / c.hi, a.hi / c.lo, a.hi / c.hi};
  return I::widen(*std::min_element(q, q + 4), *std::max_element(q, q + 4));
}

// The valley bound on a strip T = X x [0, 1] (sigma D_yy > 0 there): with L > 0 a lower bound of sigma D_yy on the
// strip and (x, y0(x)) a segment across it, on each line x
//   sigma D(x, y) >= sigma D(x, y0) + sigma D_y(x, y0) (y - y0) + L/2 (y - y0)^2 >= sigma D(x, y0) - D_y(x, y0)^2 / (2L),
// and the Bernstein coefficients on the segment bound sigma D(x, y0) from below and |D_y(x, y0)| from above. The
// segment joins the minimisers of sigma D on the strip's edges; the bound needs it within about the valley's width
// of the valley's floor. operator() is true if the bound proves sigma D > 0 on the strip.
template <class N>
struct Valley_bound {
  int nx, ny;
  std::vector<N> cx, cy, cy1, cs, cs1;
  Grid<N> Ty;
  Valley_bound(int nx_, int ny_)
      : nx(nx_), ny(ny_), cx(binomials<N>(nx_)), cy(binomials<N>(ny_)), cy1(binomials<N>(std::max(ny_ - 1, 0))),
        cs(binomials<N>(nx_ + ny_)), cs1(binomials<N>(std::max(nx_ + ny_ - 1, 0))),
        Ty{nx_, std::max(ny_ - 1, 0), std::vector<N>(std::size_t(nx_ + 1) * std::max(ny_, 1))} {}
  bool operator()(const Grid<N>& T, int sigma, std::vector<N>& w) {
    if (ny < 2) return false;
    const N s = constant(N{}, double(sigma));
    double least = HUGE_VAL;  // the least sigma-second difference in y on the strip: L = ny (ny - 1) least
    for (int i = 0; i <= nx; ++i)
      for (int j = 0; j + 2 <= ny; ++j) least = std::min(least, lower(s * (T.at(i, j + 2) - T.at(i, j + 1) - T.at(i, j + 1) + T.at(i, j))));
    if (!(least > 0)) return false;
    for (int i = 0; i <= nx; ++i)
      for (int j = 0; j < ny; ++j) Ty.at(i, j) = T.at(i, j + 1) - T.at(i, j);  // D_y = ny x (this grid)
    const auto [y_left, y_right] = edge_minimisers(T, sigma);
    const bool reversed = y_left > y_right;
    const double ya = std::min(y_left, y_right), yb = std::max(y_left, y_right);
    const std::vector<N> g = on_segment(T, ya, yb, reversed, cx, cy, w), h = on_segment(Ty, ya, yb, reversed, cx, cy1, w);
    double low = HUGE_VAL, high = 0;  // sigma D >= low and |D_y| / ny <= high on the segment
    for (std::size_t k = 0; k < g.size(); ++k) low = std::min(low, lower(quotient(s * g[k], cs[k])));
    for (std::size_t k = 0; k < h.size(); ++k) {
      const N q = quotient(h[k], cs1[k]);
      high = std::max(high, std::max(-lower(q), upper(q)));
    }
    if (!(low > 0)) return false;
    // 2 L low - (ny high)^2 > 0, with L = ny (ny - 1) least
    const N L = constant(N{}, least) * constant(N{}, double(ny) * (ny - 1)), H = constant(N{}, high) * constant(N{}, double(ny));
    return lower(constant(N{}, 2) * L * constant(N{}, low) - H * H) > 0;
  }
};

// The strip search shared by the two certificates below: the strip [x_from, x_to] x [0, 1] (in the box's local
// coordinates) passes if each of its pieces X passes `pass` (given the grid of X x [0, 1], restricted from S); a piece
// that fails is cut at `cut` (a ratio in (0, 1), floating point: a policy) down to `max_depth` times. `strips` counts
// the strip grids computed (the work).
template <class N, class Pass, class Cut>
bool strip_search(const Grid<N>& S, double x_from, double x_to, int max_depth, std::size_t& strips, Pass pass, Cut cut) {
  struct Piece {
    double xa, xb;
    int depth;
  };
  if (!(x_from < x_to)) return true;
  std::vector<Piece> todo{{x_from, x_to, 0}};
  Grid<N> T{S.nx, S.ny, std::vector<N>(S.v.size())};
  std::vector<N> w;
  while (!todo.empty()) {
    const Piece p = todo.back();
    todo.pop_back();
    ++strips;
    strip_grid(S, p.xa, p.xb, T, w);
    if (pass(T)) continue;
    if (p.depth >= max_depth) return false;
    const double m = p.xa + cut(T) * (p.xb - p.xa);
    todo.push_back({m, p.xb, p.depth + 1});
    todo.push_back({p.xa, m, p.depth + 1});
  }
  return true;
}

// True if every line x = const of the strip [x_from, x_to] x [0, 1] carries no point with D = D_y = 0: by one of the
// three tests of the header comment (or, if `valley`, because the valley bound proves D != 0 on the strip), on pieces
// of the strip cut by window_cut down to `max_depth` times.
template <class N>
bool no_fold(const Grid<N>& S, int sigma, double x_from, double x_to, int max_depth, std::size_t& strips,
             bool valley = false) {
  const std::vector<N> cx = binomials<N>(S.nx), cy = binomials<N>(S.ny);
  std::vector<N> w;
  std::unique_ptr<Valley_bound<N>> above;
  if (valley) above.reset(new Valley_bound<N>(S.nx, S.ny));
  double y_left = 0, y_right = 0;  // the minimisers of the last piece tested, for its cut
  auto pass = [&](const Grid<N>& T) {
    if (difference_sign_y(T) != 0 || common_sign(T) != 0) return true;
    // the segment between the minimisers of sigma D on the strip's two edges x = xa and x = xb
    std::tie(y_left, y_right) = edge_minimisers(T, sigma);
    const bool reversed = y_left > y_right;  // then run x backwards, so that the segment rises
    const std::vector<N> g = on_segment(T, std::min(y_left, y_right), std::max(y_left, y_right), reversed, cx, cy, w);
    bool negative = true;  // sigma D < 0 on the segment
    for (const N& x : g) negative = negative && (sigma > 0 ? upper(x) < 0 : lower(x) > 0);
    return negative || (above && (*above)(T, sigma, w));
  };
  auto cut = [&](const Grid<N>& T) { return window_cut(T, sigma, y_left, y_right); };
  return strip_search(S, x_from, x_to, max_depth, strips, pass, cut);
}

// True if D has no zero in the closed box (sigma D_yy > 0 there: the caller's test). On each piece X of the x-range
// (halving, or a cut where the valley's floor leaves the box; down to `max_depth` times), D has one strict sign on the
// strip X x [0, 1], or the strip is a valley of sigma D above 0 (Valley_bound). Two branches that become a complex
// pair (beyond the tips of a thin loop, a near miss of two surfaces) leave such a valley, where D is small and
// positive: a plain sign test needs boxes about sqrt(min D / D_yy) wide there.
template <class N>
bool no_zero(const Grid<N>& S, int sigma, int max_depth, std::size_t& strips) {
  if (S.ny < 2) return false;
  Valley_bound<N> above(S.nx, S.ny);
  std::vector<N> w;
  auto pass = [&](const Grid<N>& T) { return common_sign(T) != 0 || above(T, sigma, w); };
  // cut where the valley's floor leaves the box, if it does in this strip, else halve: a chord with one end on the
  // edge and the other on the floor follows neither, while on each side of the cut it follows one of them (the
  // bound is exact for a quadratic in y whichever y0 it starts from, so a chord along the edge serves too)
  auto cut = [&](const Grid<N>& T) {
    const auto [y_left, y_right] = edge_minimisers(T, sigma);
    double e = 0;
    const double x = minimiser_exit(T, y_left, y_right, e);
    return x > 1.0 / 64 && x < 63.0 / 64 ? x : 0.5;
  };
  return strip_search(S, 0, 1, max_depth, strips, pass, cut);
}

// The coefficients c (in y) of D on the line x = const of the grid M (floating point).
inline void line_at(const Grid<double>& M, double x, std::vector<double>& basis, std::vector<double>& c) {
  basis.assign(std::size_t(M.nx + 1), 0.0);  // the Bernstein basis at x, by de Casteljau's recurrence
  basis[0] = 1;
  for (int d = 1; d <= M.nx; ++d)
    for (int k = d; k >= 0; --k) basis[std::size_t(k)] = (1 - x) * basis[std::size_t(k)] + (k > 0 ? x * basis[std::size_t(k - 1)] : 0);
  c.assign(std::size_t(M.ny + 1), 0.0);
  for (int j = 0; j <= M.ny; ++j)
    for (int i = 0; i <= M.nx; ++i) c[std::size_t(j)] += basis[std::size_t(i)] * M.at(i, j);
}

// Floating point, for the caller's policy (no proof rests on it): the least distance, in the box's local coordinate
// y, between the two zeros of D on the lines x = 1/4, 1/2, 3/4 that have two; 1 if none has.
inline double branch_gap(const Grid<double>& M, int sigma) {
  double gap = 1;
  std::vector<double> basis, c, w;
  auto value = [&](double t) { return sigma * bernstein_at(c, t, w); };
  auto root = [&](double a, double b) {  // sigma D > 0 at a, < 0 at b (or the reverse): bisection
    const bool rising = value(a) < 0;
    for (int it = 0; it < 24; ++it) {  // a few digits: a policy, not a proof
      const double m = 0.5 * (a + b);
      ((value(m) < 0) == rising ? a : b) = m;
    }
    return 0.5 * (a + b);
  };
  for (double x : {0.25, 0.5, 0.75}) {
    line_at(M, x, basis, c);
    const double y = minimiser(c, sigma, 24);
    if (!(value(y) < 0 && value(0) > 0 && value(1) > 0)) continue;
    gap = std::min(gap, root(y, 1) - root(0, y));
  }
  return gap;
}

// Floating point, for the caller's policy: sigma D has a positive minimum on the lines x = 1/4, 1/2, 3/4 (a valley
// of sigma D above 0 may cross the box).
inline bool valley_candidate(const Grid<double>& M, int sigma) {
  std::vector<double> basis, c, w;
  for (double x : {0.25, 0.5, 0.75}) {
    line_at(M, x, basis, c);
    if (!(sigma * bernstein_at(c, minimiser(c, sigma, 24), w) > 0)) return false;
  }
  return true;
}

// The box's grid with y across (axis 0: y = v; axis 1: y = u) and sigma, the strict sign of its second differences
// in y (proved with the grid's radius); false if they have none or D has degree < 2 in y.
inline bool across(const Double_bernstein_grid& G, int axis, Grid<double>& M, int& sigma) {
  const int nx = axis == 0 ? G.a() : G.b(), ny = axis == 0 ? G.b() : G.a();
  if (ny < 2) return false;
  double lo, hi;
  G.second_difference_range(axis == 0 ? 2 : 0, G.radius(), lo, hi);
  sigma = lo > 0 ? 1 : (hi < 0 ? -1 : 0);
  if (sigma == 0) return false;
  M = Grid<double>{nx, ny, std::vector<double>(std::size_t(nx + 1) * (ny + 1))};
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) M.at(i, j) = axis == 0 ? G.at(i, j) : G.at(j, i);
  return true;
}

// The proved enclosures m_ij +- rho of the midpoints M.
inline Grid<Double_interval> enclosure(const Grid<double>& M, double rho) {
  Grid<Double_interval> S{M.nx, M.ny, std::vector<Double_interval>(M.v.size())};
  for (std::size_t k = 0; k < M.v.size(); ++k) S.v[k] = Double_interval::widen(M.v[k] - rho, M.v[k] + rho);
  return S;
}

}  // namespace two_branch

/// The certificate of the header comment on the box whose Bernstein grid is G (proved radius): graphs over u are
/// tried first, then graphs over v. `max_depth`: halvings of the x-range in the fold test. `max_gap`: the policy of
/// the caller (the subdivision), not a condition of the proof: a box whose two branches lie further apart than
/// that (branch_gap, a fraction of the box) is not tried; a few more splits separate them, into cells where the
/// curve is one graph (the lifting's proofs are stronger there).
inline Two_branch_box two_branch_certificate(const Double_bernstein_grid& G, int max_depth = 4,
                                             std::size_t* strips = nullptr, double max_gap = 1) {
  const double rho = G.radius();
  std::size_t work = 0;
  bool screened = false;
  for (int axis = 0; axis < 2; ++axis) {
    two_branch::Grid<double> M;
    int sigma = 0;
    if (!two_branch::across(G, axis, M, sigma)) continue;
    const double gap = max_gap < 1 ? two_branch::branch_gap(M, sigma) : 0;
    if (!(gap < max_gap)) continue;
    if (!two_branch::no_fold(M, sigma, 0, 1, max_depth, work)) continue;  // the midpoints alone fail: no proof
    screened = true;
    const two_branch::Grid<Double_interval> S = two_branch::enclosure(M, rho);
    std::size_t proof = 0;
    const bool ok = two_branch::no_fold(S, sigma, 0, 1, max_depth, proof);
    work += 8 * proof;  // an interval operation costs about eight double ones
    if (ok) {
      if (strips) *strips += work;
      return Two_branch_box{axis, sigma, gap};
    }
  }
  if (strips) *strips += work;
  Two_branch_box none;
  none.screened = screened;
  return none;
}

/// True if D is proved to have no zero in the box whose grid G is (proved radius): a valley of sigma D above 0
/// (two_branch::no_zero; y = v, then y = u). Tried only where the minimum of sigma D on three lines across the box
/// is positive (floating point: a policy). `screened`: nothing proved, but the plain-double screen passed.
inline bool valley_exclusion(const Double_bernstein_grid& G, int max_depth, std::size_t* strips, bool* screened) {
  const double rho = G.radius();
  std::size_t work = 0;
  for (int axis = 0; axis < 2; ++axis) {
    two_branch::Grid<double> M;
    int sigma = 0;
    if (!two_branch::across(G, axis, M, sigma)) continue;
    if (!two_branch::valley_candidate(M, sigma) || !two_branch::no_zero(M, sigma, max_depth, work)) continue;
    if (screened) *screened = true;
    const two_branch::Grid<Double_interval> S = two_branch::enclosure(M, rho);
    std::size_t proof = 0;
    const bool ok = two_branch::no_zero(S, sigma, max_depth, proof);
    work += 8 * proof;
    if (ok) {
      if (strips) *strips += work;
      return true;
    }
  }
  if (strips) *strips += work;
  return false;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_TWO_BRANCH_BOX_H

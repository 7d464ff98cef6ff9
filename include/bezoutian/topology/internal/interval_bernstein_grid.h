// Interval arithmetic on Bernstein grids, the numerical core of the subdivision (Curve_topology_by_subdivision.h).
// A polynomial D of bi-degree (a, b) on a box is the grid of its Bernstein coefficients there; every value of D on
// the box is a convex combination of them, so the hull of a grid encloses the range of D, and forward differences
// of a grid are (up to the factors a, b) the grids of the partial derivatives. The grids hold MPFI intervals
// (outward rounding: every interval encloses the exact coefficient):
//  * bernstein_on_box converts D from the power basis to the Bernstein basis of the domain box (interval Taylor
//    shifts and scalings, then the exact binomial ratios of the basis change);
//  * split_grid restricts a grid to a sub-box by de Casteljau's algorithm (convex combinations: the interval widths
//    do not grow, so the working precision can stay well below the conversion's);
//  * double_grid_of and double_double_of round a grid to the cheaper double (double_bernstein_grid.h) and
//    double-double (double_double_bernstein.h) grids with proved error bounds;
//  * hessian_range and grid_value enclose second derivatives on a box and partial derivatives at an interval point
//    (Krawczyk's test at a critical point of D); local_jet evaluates the value and the derivatives up to order 2 of
//    a long double grid (a floating-point Newton start).
#ifndef BEZOUTIAN_TOPOLOGY_INTERNAL_INTERVAL_BERNSTEIN_GRID_H
#define BEZOUTIAN_TOPOLOGY_INTERNAL_INTERVAL_BERNSTEIN_GRID_H

#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/topology/internal/double_bernstein_grid.h>
#include <bezoutian/topology/internal/double_double_bernstein.h>
#include <bezoutian/arithmetic/binomial.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Polynomial.h>

#include <mpfi.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <vector>

namespace bezoutian {
namespace internal {

// A (a+1) x (b+1) grid of MPFI intervals (Bernstein coefficients c[i][j], i along u).
class Interval_grid {
 public:
  Interval_grid(int a, int b, mpfr_prec_t prec) : a_(a), b_(b), v_(new __mpfi_struct[std::size_t(a + 1) * (b + 1)]) {
    for (std::size_t k = 0; k < size(); ++k) mpfi_init2(&v_[k], prec);
  }
  Interval_grid(const Interval_grid&) = delete;
  Interval_grid& operator=(const Interval_grid&) = delete;
  ~Interval_grid() {
    for (std::size_t k = 0; k < size(); ++k) mpfi_clear(&v_[k]);
  }
  std::size_t size() const { return std::size_t(a_ + 1) * (b_ + 1); }
  mpfi_ptr at(int i, int j) { return &v_[std::size_t(i) * (b_ + 1) + j]; }
  mpfi_srcptr at(int i, int j) const { return &v_[std::size_t(i) * (b_ + 1) + j]; }
  int a() const { return a_; }
  int b() const { return b_; }

 private:
  int a_, b_;
  std::unique_ptr<__mpfi_struct[]> v_;
};

namespace interval_bernstein {

// The rows C(n, 0), ..., C(n, n) as exact integers, one per degree, computed on first use (bernstein_value
// multiplies by a whole row at every evaluation).
class Binomial_rows {
 public:
  const std::vector<Integer>& row(int n) const {
    auto it = rows_.find(n);
    if (it != rows_.end()) return it->second;
    return rows_[n] = bezoutian::binomial_row<Integer>(n);
  }

 private:
  mutable std::map<int, std::vector<Integer>> rows_;
};

// Bernstein coefficients of D on the root box: shift and scale the power form (interval Taylor shifts), then
// b_kl = sum_{i<=k, j<=l} C(k,i) C(l,j) / (C(a,i) C(b,j)) e_ij.
// D has bi-degree (g.a(), g.b()); `root_prec` covers the conversion's loss of about a + b bits.
inline void bernstein_on_box(const Polynomial_2<Integer>& D, const Parameter_box& box, mpfr_prec_t root_prec,
                             Interval_grid& g) {
  const int a = g.a(), b = g.b();
  Interval_grid e(a, b, root_prec);
  for (int i = 0; i <= a; ++i)
    for (int j = 0; j <= b; ++j) {
      const bool has = j <= D.degree() && !CGAL::is_zero(D[j]) && i <= D[j].degree();
      if (has)
        mpfi_set_z(e.at(i, j), D[j][i].mpz());
      else
        mpfi_set_ui(e.at(i, j), 0);
    }
  mpfi_t c, w, t;
  mpfi_init2(c, root_prec);
  mpfi_init2(w, root_prec);
  mpfi_init2(t, root_prec);
  // u -> u0 + (u1 - u0) x for every column j
  for (int pass = 0; pass < 2; ++pass) {
    const bool along_u = pass == 0;
    const int n = along_u ? a : b, m = along_u ? b : a;
    const Rational& lo = along_u ? box.u0 : box.v0;
    const Rational& hi = along_u ? box.u1 : box.v1;
    mpfi_set_q(c, lo.mpq());
    const Rational wd = hi - lo;
    mpfi_set_q(w, wd.mpq());
    auto at = [&](int k, int l) { return along_u ? e.at(k, l) : e.at(l, k); };
    for (int l = 0; l <= m; ++l) {
      if (!CGAL::is_zero(lo))  // Taylor shift by lo (synthetic division, O(n^2))
        for (int k = 0; k < n; ++k)
          for (int r = n - 1; r >= k; --r) {
            mpfi_mul(t, at(r + 1, l), c);
            mpfi_add(at(r, l), at(r, l), t);
          }
      mpfi_set_ui(t, 1);
      for (int k = 0; k <= n; ++k) {  // scale x^k by width^k
        mpfi_mul(at(k, l), at(k, l), t);
        mpfi_mul(t, t, w);
      }
    }
  }
  // power -> Bernstein, first along u then along v
  for (int pass = 0; pass < 2; ++pass) {
    const bool along_u = pass == 0;
    const int n = along_u ? a : b, m = along_u ? b : a;
    auto src = [&](int k, int l) { return along_u ? e.at(k, l) : e.at(l, k); };
    std::vector<Rational> q(std::size_t(n + 1) * (n + 1));
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= k; ++i)
        q[std::size_t(k) * (n + 1) + i] =
            Rational(bezoutian::binomial<Integer>(k, i)) / Rational(bezoutian::binomial<Integer>(n, i));
    std::vector<__mpfi_struct> out(std::size_t(n + 1));
    for (auto& x : out) mpfi_init2(&x, root_prec);
    for (int l = 0; l <= m; ++l) {
      for (int k = 0; k <= n; ++k) {
        mpfi_set_ui(&out[k], 0);
        for (int i = 0; i <= k; ++i) {
          mpfi_mul_q(t, src(i, l), q[std::size_t(k) * (n + 1) + i].mpq());
          mpfi_add(&out[k], &out[k], t);
        }
      }
      for (int k = 0; k <= n; ++k) mpfi_set(src(k, l), &out[k]);
    }
    for (auto& x : out) mpfi_clear(&x);
  }
  for (int i = 0; i <= a; ++i)
    for (int j = 0; j <= b; ++j) mpfi_set(g.at(i, j), e.at(i, j));
  mpfi_clear(c);
  mpfi_clear(w);
  mpfi_clear(t);
}

// de Casteljau at ratio `ratio` in (0,1) along u (or v): left/right children.
inline void split_grid(const Interval_grid& g, bool along_u, const Rational& ratio, Interval_grid& left,
                       Interval_grid& right, mpfr_prec_t prec) {
  const int a = g.a(), b = g.b();
  const int n = along_u ? a : b, m = along_u ? b : a;
  mpfi_t r, s, t;
  mpfi_init2(r, prec);
  mpfi_init2(s, prec);
  mpfi_init2(t, prec);
  mpfi_set_q(r, ratio.mpq());
  mpfi_ui_sub(s, 1, r);
  std::vector<__mpfi_struct> w(std::size_t(n + 1));
  for (auto& x : w) mpfi_init2(&x, prec);
  for (int l = 0; l <= m; ++l) {
    for (int k = 0; k <= n; ++k) mpfi_set(&w[k], along_u ? g.at(k, l) : g.at(l, k));
    auto L = [&](int k) { return along_u ? left.at(k, l) : left.at(l, k); };
    auto R = [&](int k) { return along_u ? right.at(k, l) : right.at(l, k); };
    mpfi_set(L(0), &w[0]);
    mpfi_set(R(n), &w[n]);
    for (int level = 1; level <= n; ++level) {
      for (int k = 0; k + level <= n; ++k) {
        mpfi_mul(t, &w[k], s);
        mpfi_mul(&w[k], &w[k + 1], r);
        mpfi_add(&w[k], &w[k], t);
      }
      mpfi_set(L(level), &w[0]);
      mpfi_set(R(n - level), &w[n - level]);
    }
  }
  for (auto& x : w) mpfi_clear(&x);
  mpfi_clear(r);
  mpfi_clear(s);
  mpfi_clear(t);
}

// Copies the coefficients of `from` into `to` (a grid of the same bi-degree).
inline void copy_grid(const Interval_grid& from, Interval_grid& to) {
  for (int i = 0; i <= from.a(); ++i)
    for (int j = 0; j <= from.b(); ++j) mpfi_set(to.at(i, j), from.at(i, j));
}

// Double grid of an MPFI grid: midpoints rounded to nearest, scaled by one power of two, and the largest
// distance from a midpoint to its interval's ends rounded upwards.
inline std::shared_ptr<const Double_bernstein_grid> double_grid_of(const Interval_grid& g, mpfr_prec_t prec) {
  const int a = g.a(), b = g.b();  // D's grid, or one of its derivatives' (no_critical_point_outside)
  auto f = std::make_shared<Double_bernstein_grid>(a, b);
  mpfr_t mid, d;
  mpfr_init2(mid, prec);
  mpfr_init2(d, prec);
  long emax = LONG_MIN;
  for (int i = 0; i <= a; ++i)
    for (int j = 0; j <= b; ++j) {
      mpfi_mid(mid, g.at(i, j));
      if (!mpfr_zero_p(mid)) emax = std::max(emax, long(mpfr_get_exp(mid)));
      if (!mpfr_zero_p(&g.at(i, j)->right)) emax = std::max(emax, long(mpfr_get_exp(&g.at(i, j)->right)));
      if (!mpfr_zero_p(&g.at(i, j)->left)) emax = std::max(emax, long(mpfr_get_exp(&g.at(i, j)->left)));
    }
  if (emax == LONG_MIN) emax = 0;
  double rho = 0;
  for (int i = 0; i <= a; ++i)
    for (int j = 0; j <= b; ++j) {
      mpfi_mid(mid, g.at(i, j));
      mpfr_mul_2si(mid, mid, -emax, MPFR_RNDN);
      const double m = mpfr_get_d(mid, MPFR_RNDN);
      f->at(i, j) = m;
      // radius: max(right - m, m - left) in the scaled units, rounded up
      mpfr_mul_2si(d, &g.at(i, j)->right, -emax, MPFR_RNDU);
      mpfr_sub_d(d, d, m, MPFR_RNDU);
      rho = std::max(rho, mpfr_get_d(d, MPFR_RNDU));
      mpfr_mul_2si(d, &g.at(i, j)->left, -emax, MPFR_RNDD);
      mpfr_d_sub(d, m, d, MPFR_RNDU);
      rho = std::max(rho, mpfr_get_d(d, MPFR_RNDU));
    }
  mpfr_clear(mid);
  mpfr_clear(d);
  f->set_radius(rho);
  f->set_exponent(int(emax));
  f->rescale();
  return f;
}

// The double-double form of an MPFI grid (internal/double_double_bernstein.h): midpoints split into hi + lo,
// scaled by 2^-scale; the error bound adds the interval radii and what the split drops.
inline std::shared_ptr<const Double_double_bernstein> double_double_of(const Interval_grid& g, int& scale,
                                                                      mpfr_prec_t prec) {
  const int a = g.a(), b = g.b();
  auto f = std::make_shared<Double_double_bernstein>(a, b);
  const mpfr_prec_t p = prec + 128;
  mpfr_t mid, t, d;
  mpfr_init2(mid, p);
  mpfr_init2(t, p);
  mpfr_init2(d, 64);
  long emax = LONG_MIN;
  for (int i = 0; i <= a; ++i)
    for (int j = 0; j <= b; ++j)
      for (mpfr_srcptr e : {&g.at(i, j)->left, &g.at(i, j)->right})
        if (!mpfr_zero_p(e)) emax = std::max(emax, long(mpfr_get_exp(e)));
  if (emax == LONG_MIN) return nullptr;
  double err = 0, mag = 0;
  for (int i = 0; i <= a; ++i)
    for (int j = 0; j <= b; ++j) {
      mpfi_mid(mid, g.at(i, j));
      mpfr_mul_2si(mid, mid, -emax, MPFR_RNDN);  // exact (a power of two)
      const double hi = mpfr_get_d(mid, MPFR_RNDN);
      mpfr_sub_d(t, mid, hi, MPFR_RNDN);  // exact at p bits
      const double lo = mpfr_get_d(t, MPFR_RNDN);
      mpfr_sub_d(t, t, lo, MPFR_RNDN);  // exact
      double e = std::fabs(mpfr_get_d(t, MPFR_RNDU)) * 2;
      // radius of the interval about its midpoint, in the scaled units, rounded up
      mpfr_sub(d, &g.at(i, j)->right, &g.at(i, j)->left, MPFR_RNDU);
      mpfr_mul_2si(d, d, -emax, MPFR_RNDU);
      e += mpfr_get_d(d, MPFR_RNDU);
      err = std::max(err, e);
      mag = std::max(mag, std::fabs(hi) + std::fabs(lo));
      f->at(i, j) = Double_double{hi, lo};
    }
  mpfr_clear(mid);
  mpfr_clear(t);
  mpfr_clear(d);
  err = err * (1 + 1e-14) + 1e-300;
  f->set_bounds(err, (mag + err) * (1 + 1e-14));
  scale = int(emax);
  return f;
}

// Bernstein range (hull of the coefficients) on the box of d^2 D / dx^(2-k) dy^k in the box's local
// coordinates (x, y) in [0,1]^2; k = 0, 1, 2.
inline Mpfi_interval hessian_range(const Interval_grid& g, int k, mpfr_prec_t prec) {
  const int a = g.a(), b = g.b();
  const int di = 2 - k, dj = k;
  Mpfi_interval r = Mpfi_interval::point(0, prec);
  if (a < di || b < dj) return r;
  mpfi_t t;
  mpfi_init2(t, prec);
  bool first = true;
  for (int i = 0; i + di <= a; ++i)
    for (int j = 0; j + dj <= b; ++j) {
      if (k == 0) {
        mpfi_mul_2si(t, g.at(i + 1, j), 1);
        mpfi_sub(t, g.at(i + 2, j), t);
        mpfi_add(t, t, g.at(i, j));
      } else if (k == 2) {
        mpfi_mul_2si(t, g.at(i, j + 1), 1);
        mpfi_sub(t, g.at(i, j + 2), t);
        mpfi_add(t, t, g.at(i, j));
      } else {
        mpfi_sub(t, g.at(i + 1, j + 1), g.at(i + 1, j));
        mpfi_sub(t, t, g.at(i, j + 1));
        mpfi_add(t, t, g.at(i, j));
      }
      if (first)
        mpfi_set(r.get(), t);
      else
        mpfi_union(r.get(), r.get(), t);
      first = false;
    }
  const long f = k == 0 ? long(a) * (a - 1) : (k == 2 ? long(b) * (b - 1) : long(a) * b);
  mpfi_mul_si(r.get(), r.get(), f);
  mpfi_clear(t);
  return r;
}

// sum_k c_k C(n,k) t^k s^(n-k) (s = 1 - t) into `out` (c is overwritten). When t and s are positive intervals:
// Horner's rule in q = t/s (or s/t when t > 1/2, so that |q| <= 1 about the midpoint), times s^n (t^n): O(n)
// interval operations; otherwise de Casteljau's algorithm (O(n^2)). Both are enclosures of the value.
inline void bernstein_value(__mpfi_struct* c, int n, mpfi_srcptr t, mpfi_srcptr s, mpfi_ptr out, mpfi_ptr tmp,
                            mpfr_prec_t prec, const Binomial_rows& rows) {
  if (n >= 1 && mpfi_is_strictly_pos(t) && mpfi_is_strictly_pos(s)) {
    const std::vector<Integer>& C = rows.row(n);
    mpfr_t mid;
    mpfr_init2(mid, 53);
    mpfi_mid(mid, t);
    const bool small_t = mpfr_cmp_d(mid, 0.5) <= 0;
    mpfr_clear(mid);
    mpfi_t q;
    mpfi_init2(q, prec);
    if (small_t)
      mpfi_div(q, t, s);
    else
      mpfi_div(q, s, t);
    const int first = small_t ? n : 0, step = small_t ? -1 : 1;
    mpfi_mul_z(out, &c[first], C[first].mpz());
    for (int k = first + step; k >= 0 && k <= n; k += step) {
      mpfi_mul(out, out, q);
      mpfi_mul_z(tmp, &c[k], C[k].mpz());
      mpfi_add(out, out, tmp);
    }
    mpfi_set(q, small_t ? s : t);  // times s^n (t^n)
    for (int e = n; e > 0; e >>= 1) {
      if (e & 1) mpfi_mul(out, out, q);
      if (e > 1) mpfi_sqr(q, q);
    }
    mpfi_clear(q);
    return;
  }
  for (int level = n; level >= 1; --level)
    for (int j = 0; j < level; ++j) {
      mpfi_mul(tmp, &c[j], s);
      mpfi_mul(&c[j], &c[j + 1], t);
      mpfi_add(&c[j], &c[j], tmp);
    }
  mpfi_set(out, &c[0]);
}

// The partial derivative d^(di+dj) D / dx^di dy^dj in local coordinates at the interval point (x, y), by de
// Casteljau's algorithm on the differenced coefficients: an enclosure of its range there.
inline Mpfi_interval grid_value(const Interval_grid& g, int di, int dj, const Mpfi_interval& x, const Mpfi_interval& y,
                                mpfr_prec_t prec, const Binomial_rows& rows) {
  const int a = g.a(), b = g.b();
  const int n = a - di, m = b - dj;
  Mpfi_interval r = Mpfi_interval::point(0, prec);
  if (n < 0 || m < 0) return r;
  std::vector<__mpfi_struct> w(std::size_t(a + 1) * (b + 1)), col(std::size_t(n + 1));
  for (auto& z : w) mpfi_init2(&z, prec);
  for (auto& z : col) mpfi_init2(&z, prec);
  mpfi_t t, x1, y1;
  mpfi_init2(t, prec);
  mpfi_init2(x1, prec);
  mpfi_init2(y1, prec);
  mpfi_ui_sub(x1, 1, x.get());
  mpfi_ui_sub(y1, 1, y.get());
  auto W = [&](int i, int j) { return &w[std::size_t(i) * (b + 1) + j]; };
  for (int i = 0; i <= a; ++i)
    for (int j = 0; j <= b; ++j) mpfi_set(W(i, j), g.at(i, j));
  for (int s = 0; s < di; ++s)  // forward differences in place: the lower index keeps the difference
    for (int i = 0; i + s < a; ++i)
      for (int j = 0; j <= b; ++j) mpfi_sub(W(i, j), W(i + 1, j), W(i, j));
  for (int s = 0; s < dj; ++s)
    for (int i = 0; i <= a; ++i)
      for (int j = 0; j + s < b; ++j) mpfi_sub(W(i, j), W(i, j + 1), W(i, j));
  // collapse every row (fixed i) along y, then the column along x
  for (int i = 0; i <= n; ++i) bernstein_value(W(i, 0), m, y.get(), y1, &col[i], t, prec, rows);
  bernstein_value(&col[0], n, x.get(), x1, r.get(), t, prec, rows);
  for (int s = 0; s < di; ++s) mpfi_mul_si(r.get(), r.get(), a - s);
  for (int s = 0; s < dj; ++s) mpfi_mul_si(r.get(), r.get(), b - s);
  for (auto& z : w) mpfi_clear(&z);
  for (auto& z : col) mpfi_clear(&z);
  mpfi_clear(t);
  mpfi_clear(x1);
  mpfi_clear(y1);
  return r;
}

// Value and derivatives up to order 2 of the long double grid at (x, y): f, fx, fy, fxx, fxy, fyy.
// L holds the (a + 1) x (b + 1) coefficients row by row (index i (b + 1) + j, i along x).
inline std::array<long double, 6> local_jet(const std::vector<long double>& L, int a, int b, long double x,
                                            long double y) {
  // Bernstein basis values and first/second derivatives in each variable
  auto basis = [](int n, long double t, std::vector<long double>& B0, std::vector<long double>& B1,
                  std::vector<long double>& B2) {
    // the bases of degrees n - 2, n - 1, n by one recursion (each degree is one step from the previous one)
    auto raise = [&](const std::vector<long double>& from, std::vector<long double>& out) {
      const std::size_t d = from.size();
      out.assign(d + 1, 0.0L);
      for (std::size_t k = 0; k < d; ++k) {
        out[k] += from[k] * (1 - t);
        out[k + 1] += from[k] * t;
      }
    };
    std::vector<long double> b1, b2, cur(1, 1.0L), next;  // degrees n - 1, n - 2; cur starts at degree 0
    if (n == 0) {
      B0 = cur;
    } else {
      for (int d = 1; d <= n - 2; ++d) {
        raise(cur, next);
        cur.swap(next);
      }
      if (n >= 2) {
        b2 = cur;
        raise(b2, b1);
      } else {
        b1 = cur;
      }
      raise(b1, B0);
    }
    B1.assign(std::size_t(n + 1), 0.0L);
    B2.assign(std::size_t(n + 1), 0.0L);
    for (int k = 0; k <= n; ++k) {  // d/dt B_k^n = n (B_{k-1}^{n-1} - B_k^{n-1})
      if (n >= 1) B1[k] = n * ((k >= 1 && k - 1 <= n - 1 ? b1[k - 1] : 0) - (k <= n - 1 ? b1[k] : 0));
      if (n >= 2)
        B2[k] = n * (n - 1) *
                ((k >= 2 ? b2[k - 2] : 0) - 2 * (k >= 1 && k - 1 <= n - 2 ? b2[k - 1] : 0) + (k <= n - 2 ? b2[k] : 0));
    }
  };
  std::vector<long double> U0, U1, U2, V0, V1, V2;
  basis(a, x, U0, U1, U2);
  basis(b, y, V0, V1, V2);
  std::array<long double, 6> r{};
  for (int i = 0; i <= a; ++i) {
    long double s0 = 0, s1 = 0, s2 = 0;
    for (int j = 0; j <= b; ++j) {
      const long double c = L[std::size_t(i) * (b + 1) + j];
      s0 += c * V0[j];
      s1 += c * V1[j];
      s2 += c * V2[j];
    }
    r[0] += U0[i] * s0;
    r[1] += U1[i] * s0;
    r[2] += U0[i] * s1;
    r[3] += U2[i] * s0;
    r[4] += U1[i] * s1;
    r[5] += U0[i] * s2;
  }
  return r;
}

}  // namespace interval_bernstein
}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_TOPOLOGY_INTERNAL_INTERVAL_BERNSTEIN_GRID_H

// Phantom proofs through the kernel of the Bezoutian matrix (buse-elkadi-galligo-2008 §4: at a point of D = 0 the
// vector U of Theorems 2-5, evaluated at the partner, is in the kernel of B^t, "so we can often obtain k and l as
// the quotient of two sub-minors").
//
// The kernel system. Let M(x) = B(x)^t (N x N), t the graph coordinate of an arc piece, o the other one, and f a
// fixed index. The N equations M(t, o) w = 0 in the N unknowns z = (o, w_j for j != f), with w_f = 1, are square.
// A strict parametric Krawczyk test over a span T on a box Z = O x W (as in certified_lifting.h, with this
// system for the partner equations) proves, for every t in T, exactly one zero (o(t), w(t)) in Z, with a regular
// Jacobian. Then:
//  - det M(t, o(t)) = 0, so (t, o(t)) lies on D = 0 (D is det B up to a constant factor and multiplicities); with O
//    strictly inside the cell's range of o it is the arc point over t (every line t = c meets D = 0 at most once in
//    the cell);
//  - the kernel of M there is the line through w(t): a second kernel vector could be taken with w_f = 0, and
//    (0, that vector) would be a null vector of the Jacobian;
//  - every partner y of the arc point with a nonzero weight at P or Q (every genuine partner: the weights are
//    nonzero in the partner domain) makes two columns of the determinant of formula (2) (Theorems 2, 4) or of
//    Theorems 3, 5 proportional, so the Bezoutian vanishes for every value of the second set of variables:
//    U(y) B = 0, i.e. U(y) = c w(t) with c != 0 (U(y) != 0: U holds the monomial 1 (intersection), or the monomials
//    l and k and y != 0 (self-intersection)). For monomials mu and mu * y_1 of U, c w_{mu y_1} = y_1 c w_mu, so
//    y_1 = w_{mu y_1} / w_mu wherever w_mu != 0; the same for y_2.
// If these ratios, over the enclosure W, put P or Q outside the partner domain, no arc point over T has a genuine
// partner: the span is phantom. The kernel vector is projective (|w| <= 1 with f its largest entry), so partners
// far outside the domain, where the partner equations E have huge values and slopes (k ~ 20 on random rational
// bicubics), are as easy as near ones. Nothing is claimed for genuine points: a kernel vector need not come from a
// real finite partner.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_KERNEL_PARTNER_PROOFS_H
#define BEZOUTIAN_LIFTING_INTERNAL_KERNEL_PARTNER_PROOFS_H

#include <bezoutian/elimination/Surface_bezoutian_matrices.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/floating_null_vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace bezoutian {
namespace internal {

/// M(x) = B(x)^t and its partial derivatives as interval coefficient grids, and the partner read from a kernel
/// vector of M.
class Kernel_partner_system {
 public:
  using D = Double_interval;
  Kernel_partner_system(const Bezoutian_matrix& B, bool self_intersection)
      : n_(B.size()), self_(self_intersection), monomials_(B.row_monomials) {
    for (auto& g : grids_) g.resize(n_ * n_);
    for (std::size_t r = 0; r < n_; ++r)
      for (std::size_t c = 0; c < n_; ++c) {
        const Polynomial_2<Rational>& p = B.entries[c][r];  // M[r][c] = B[c][r]
        // the coefficient grid q[j][i] of x0^i x1^j, all rows of one length (so the derivative in x1, which
        // moves row j + 1 to row j, keeps every coefficient)
        int width = 0;
        for (int j = 0; j <= p.degree(); ++j) width = std::max(width, p[j].degree() + 1);
        std::vector<std::vector<Rational>> q(std::size_t(std::max(p.degree(), 0)) + 1,
                                             std::vector<Rational>(std::size_t(std::max(width, 1)), Rational(0)));
        for (int j = 0; j <= p.degree(); ++j)
          for (int i = 0; i <= p[j].degree(); ++i) q[j][i] = p[j][i];
        // the value and d/dx0, d/dx1 (x0 the inner variable of Polynomial_2)
        std::array<std::vector<std::vector<Rational>>, 3> e{q, q, q};
        for (std::size_t j = 0; j < q.size(); ++j)
          for (std::size_t i = 0; i < q[j].size(); ++i) {
            e[1][j][i] = i + 1 < q[j].size() ? q[j][i + 1] * Rational(int(i + 1)) : Rational(0);
            e[2][j][i] = j + 1 < q.size() ? q[j + 1][i] * Rational(int(j + 1)) : Rational(0);
          }
        for (int d = 0; d < 3; ++d) {
          std::vector<std::vector<D>>& g = grids_[d][r * n_ + c];
          g.assign(q.size(), {});
          for (std::size_t j = 0; j < q.size(); ++j)
            for (const Rational& a : e[d][j]) g[j].push_back(D::of(a));
        }
      }
    // U(y) != 0 for every partner considered: the monomial 1, or (self-intersection, y != 0) both y_1 and y_2
    bool one = false, first = false, second = false;
    for (const auto& e : monomials_) {
      one = one || (e.first == 0 && e.second == 0);
      first = first || (e.first == 1 && e.second == 0);
      second = second || (e.first == 0 && e.second == 1);
    }
    usable_ = n_ >= 2 && (one || (self_ && first && second));
  }

  std::size_t size() const { return n_; }
  bool self_intersection() const { return self_; }
  /// False if a partner could have U(y) = 0 (then the kernel says nothing about it).
  bool usable() const { return usable_; }

  /// M (d = 0), dM/dx0 (d = 1) or dM/dx1 (d = 2) over the box x0 x x1, row-major.
  void evaluate(int d, const D& x0, const D& x1, std::vector<D>& M) const {
    M.resize(n_ * n_);
    for (std::size_t k = 0; k < n_ * n_; ++k)
      M[k] = grids_[d][k].empty() ? D{0, 0} : interval_horner(grids_[d][k], x0, x1);
  }

  /// The same in floating point (the coefficients' midpoints; for Newton steps only).
  void evaluate(int d, double x0, double x1, std::vector<double>& M) const {
    M.resize(n_ * n_);
    for (std::size_t k = 0; k < n_ * n_; ++k) {
      double s = 0;
      const auto& g = grids_[d][k];
      for (std::size_t j = g.size(); j-- > 0;) {
        double r = 0;
        for (std::size_t i = g[j].size(); i-- > 0;) r = r * x0 + g[j][i].mid();
        s = s * x1 + r;
      }
      M[k] = s;
    }
  }

  /// The partner (y_1, y_2) = ((l, k) or (s, v), the monomial variables of B) of every arc point whose kernel
  /// vector lies in W (header comment): the intersection of the enclosures w_{mu y_i} / w_mu over the pairs with
  /// w_mu excluding 0; the whole line where there is none. False if the enclosures are disjoint (no partner).
  bool partner(const std::vector<D>& w, std::array<D, 2>& y) const {
    for (int dir = 0; dir < 2; ++dir) {
      y[dir] = D{-HUGE_VAL, HUGE_VAL};
      for (std::size_t a = 0; a < n_; ++a) {
        if (w[a].contains_zero()) continue;
        for (std::size_t b = 0; b < n_; ++b) {
          const bool next = dir == 0 ? (monomials_[b].first == monomials_[a].first + 1 && monomials_[b].second == monomials_[a].second)
                                     : (monomials_[b].second == monomials_[a].second + 1 && monomials_[b].first == monomials_[a].first);
          if (!next) continue;
          const D q = divide(w[b], w[a]);
          y[dir] = D{std::max(y[dir].lo, q.lo), std::min(y[dir].hi, q.hi)};
        }
      }
      if (y[dir].lo > y[dir].hi) return false;
    }
    return true;
  }

  /// x / y for y excluding 0 (outward rounded).
  static D divide(const D& x, const D& y) {
    const double a = x.lo / y.lo, b = x.lo / y.hi, c = x.hi / y.lo, d = x.hi / y.hi;
    if (std::isnan(a) || std::isnan(b) || std::isnan(c) || std::isnan(d)) return D{-HUGE_VAL, HUGE_VAL};
    return D::widen(std::min(std::min(a, b), std::min(c, d)), std::max(std::max(a, b), std::max(c, d)));
  }

 private:
  std::size_t n_;
  bool self_;
  std::vector<std::pair<int, int>> monomials_;
  std::array<std::vector<std::vector<std::vector<D>>>, 3> grids_;  // [d][r * n + c][j][i]
  bool usable_ = false;
};

/// Solves A x = b (n x n, row-major, doubles) by Gaussian elimination with partial pivoting; false if singular or
/// not finite (floating point: preconditioners and Newton steps only).
inline bool solve_dense(std::vector<double> A, std::vector<double>& b, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (std::fabs(A[i * n + k]) > std::fabs(A[p * n + k])) p = i;
    if (!(std::fabs(A[p * n + k]) > 0) || !std::isfinite(A[p * n + k])) return false;
    if (p != k) {
      for (std::size_t j = 0; j < n; ++j) std::swap(A[k * n + j], A[p * n + j]);
      std::swap(b[k], b[p]);
    }
    for (std::size_t i = k + 1; i < n; ++i) {
      const double f = A[i * n + k] / A[k * n + k];
      for (std::size_t j = k; j < n; ++j) A[i * n + j] -= f * A[k * n + j];
      b[i] -= f * b[k];
    }
  }
  for (std::size_t k = n; k-- > 0;) {
    double s = b[k];
    for (std::size_t j = k + 1; j < n; ++j) s -= A[k * n + j] * b[j];
    b[k] = s / A[k * n + k];
    if (!std::isfinite(b[k])) return false;
  }
  return true;
}

/// The inverse of A (n x n, row-major) column by column; false if singular.
inline bool invert_dense(const std::vector<double>& A, std::vector<double>& C, std::size_t n) {
  C.assign(n * n, 0);
  for (std::size_t c = 0; c < n; ++c) {
    std::vector<double> e(n, 0);
    e[c] = 1;
    if (!solve_dense(A, e, n)) return false;
    for (std::size_t r = 0; r < n; ++r) C[r * n + c] = e[r];
  }
  return true;
}

/// The kernel system of the header comment on one span: z = (o, w without w_f).
class Kernel_span_system {
 public:
  using D = Double_interval;
  Kernel_span_system(const Kernel_partner_system& ks, int axis) : ks_(ks), axis_(axis), n_(ks.size()) {}

  /// A floating-point zero (o, w) at t near (t, o), w normalized at its largest entry f (chosen here), and the
  /// predicted box over the span T (Newton, then the tangent times the half width of T, doubled). False if Newton
  /// does not converge.
  bool predict(const D& T, double o, std::vector<D>& Z) {
    const double t = T.mid();
    std::vector<double> M, Mo, Mt;
    // a null vector of M(t, o) (floating_null_vector.h)
    values(t, o, M, Mo);
    std::vector<double> w(n_);
    {
      std::vector<std::vector<long double>> A(n_, std::vector<long double>(n_));
      for (std::size_t r = 0; r < n_; ++r)
        for (std::size_t c = 0; c < n_; ++c) A[r][c] = M[r * n_ + c];
      const std::vector<long double> x = null_vector(A);
      for (std::size_t k = 0; k < n_; ++k) w[k] = double(x[k]);
    }
    // normalize at the largest entry
    f_ = 0;
    for (std::size_t a = 1; a < n_; ++a)
      if (std::fabs(w[a]) > std::fabs(w[f_])) f_ = a;
    const double s = w[f_];
    if (!(std::fabs(s) > 0) || !std::isfinite(s)) return false;
    for (double& x : w) x /= s;
    // Newton on (o, w \ w_f)
    std::vector<double> J, G, z = pack(o, w);
    double step = HUGE_VAL;
    for (int it = 0; it < 10; ++it) {
      values(t, z[0], M, Mo);
      unpack(z, o, w);
      jacobian_mid(M, Mo, w, J);
      residual_mid(M, w, G);
      if (!solve_dense(J, G, n_)) return false;
      step = 0;
      for (std::size_t i = 0; i < n_; ++i) z[i] -= G[i], step += std::fabs(G[i]);
      if (!(step < 1)) return false;
      if (step < 1e-14 * (1 + std::fabs(z[0]))) break;
    }
    if (!(step <= 1e-9)) return false;
    // the tangent dz/dt = -J^-1 dG/dt (none needed on a single value of t)
    const double h = 0.5 * (T.hi - T.lo);
    std::vector<double> Gt(n_, 0);
    if (h > 0) {
      values(t, z[0], M, Mo, &Mt);
      unpack(z, o, w);
      jacobian_mid(M, Mo, w, J);
      for (std::size_t r = 0; r < n_; ++r)
        for (std::size_t c = 0; c < n_; ++c) Gt[r] += Mt[r * n_ + c] * w[c];
      if (!solve_dense(J, Gt, n_)) return false;
    }
    Z.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      const double r = 2 * std::fabs(Gt[i]) * h + 4 * h * h + 1e-12 * (1 + std::fabs(z[i]));
      Z[i] = D{z[i] - r, z[i] + r};
    }
    return true;
  }

  /// Krawczyk's operator over the span T on the box Z (strict inclusion: a unique zero curve in Z, regular);
  /// K receives the image. False if the inclusion fails.
  bool krawczyk(const D& T, const std::vector<D>& Z, std::vector<D>& K) const {
    const std::size_t n = n_;
    const D tm{T.mid(), T.mid()};
    std::vector<double> zm(n), C;
    for (std::size_t i = 0; i < n; ++i) zm[i] = Z[i].mid();
    // the preconditioner: the inverse of the Jacobian at the centre (floating point)
    double o;
    std::vector<double> w;
    unpack(zm, o, w);
    {
      std::vector<double> Md, Mod, J;
      values(tm.lo, o, Md, Mod);
      jacobian_mid(Md, Mod, w, J);
      if (!invert_dense(J, C, n)) return false;
    }
    // G at the centre, in interval arithmetic
    std::vector<D> M, Mo, Mt;
    const D Om{o, o};
    ks_.evaluate(0, axis_ == 0 ? tm : Om, axis_ == 0 ? Om : tm, M);
    std::vector<D> Gm(n, D{0, 0});
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c) Gm[r] = Gm[r] + M[r * n + c] * D{w[c], w[c]};
    // the Jacobian and dG/dt over T x Z
    std::vector<D> W(n);
    for (std::size_t a = 0, i = 1; a < n; ++a) W[a] = a == f_ ? D{1, 1} : Z[i++];
    const D O = Z[0];
    ks_.evaluate(0, axis_ == 0 ? T : O, axis_ == 0 ? O : T, M);
    ks_.evaluate(1 + (1 - axis_), axis_ == 0 ? T : O, axis_ == 0 ? O : T, Mo);
    if (T.hi > T.lo) ks_.evaluate(1 + axis_, axis_ == 0 ? T : O, axis_ == 0 ? O : T, Mt);
    else Mt.assign(n * n, D{0, 0});  // (the slope term vanishes on a single value of t)
    std::vector<D> JZ(n * n), Gt(n, D{0, 0});
    for (std::size_t r = 0; r < n; ++r) {
      D go{0, 0};
      for (std::size_t c = 0; c < n; ++c) go = go + Mo[r * n + c] * W[c], Gt[r] = Gt[r] + Mt[r * n + c] * W[c];
      JZ[r * n] = go;
      for (std::size_t a = 0, i = 1; a < n; ++a)
        if (a != f_) JZ[r * n + i++] = M[r * n + a];
    }
    K.resize(n);
    for (std::size_t r = 0; r < n; ++r) {
      D k{zm[r], zm[r]}, slope{0, 0};
      for (std::size_t c = 0; c < n; ++c) {
        const D cr{C[r * n + c], C[r * n + c]};
        k = k - cr * Gm[c];
        slope = slope + cr * Gt[c];
      }
      k = k - slope * (T - tm);
      for (std::size_t c = 0; c < n; ++c) {
        D g{r == c ? 1.0 : 0.0, r == c ? 1.0 : 0.0};
        for (std::size_t l = 0; l < n; ++l) g = g - D{C[r * n + l], C[r * n + l]} * JZ[l * n + c];
        k = k + g * (Z[c] - D{zm[c], zm[c]});
      }
      if (!(std::isfinite(k.lo) && std::isfinite(k.hi))) return false;
      K[r] = k;
    }
    for (std::size_t r = 0; r < n; ++r)
      if (!(Z[r].lo < K[r].lo && K[r].hi < Z[r].hi)) return false;
    return true;
  }

  /// The kernel vector enclosure (all N entries, w_f = 1) of a box z.
  std::vector<D> kernel(const std::vector<D>& Z) const {
    std::vector<D> W(n_);
    for (std::size_t a = 0, i = 1; a < n_; ++a) W[a] = a == f_ ? D{1, 1} : Z[i++];
    return W;
  }

 private:
  // M and dM/do at (t, o); dM/dt too if Mt is given (floating point)
  void values(double t, double o, std::vector<double>& M, std::vector<double>& Mo, std::vector<double>* Mt = nullptr) const {
    ks_.evaluate(0, axis_ == 0 ? t : o, axis_ == 0 ? o : t, M);
    ks_.evaluate(1 + (1 - axis_), axis_ == 0 ? t : o, axis_ == 0 ? o : t, Mo);
    if (Mt) ks_.evaluate(1 + axis_, axis_ == 0 ? t : o, axis_ == 0 ? o : t, *Mt);
  }
  std::vector<double> pack(double o, const std::vector<double>& w) const {
    std::vector<double> z{o};
    for (std::size_t a = 0; a < n_; ++a)
      if (a != f_) z.push_back(w[a]);
    return z;
  }
  void unpack(const std::vector<double>& z, double& o, std::vector<double>& w) const {
    o = z[0];
    w.assign(n_, 1.0);
    for (std::size_t a = 0, i = 1; a < n_; ++a)
      if (a != f_) w[a] = z[i++];
  }
  void jacobian_mid(const std::vector<double>& M, const std::vector<double>& Mo, const std::vector<double>& w,
                    std::vector<double>& J) const {
    J.assign(n_ * n_, 0);
    for (std::size_t r = 0; r < n_; ++r) {
      for (std::size_t c = 0; c < n_; ++c) J[r * n_] += Mo[r * n_ + c] * w[c];
      for (std::size_t a = 0, i = 1; a < n_; ++a)
        if (a != f_) J[r * n_ + i++] = M[r * n_ + a];
    }
  }
  void residual_mid(const std::vector<double>& M, const std::vector<double>& w, std::vector<double>& G) const {
    G.assign(n_, 0);
    for (std::size_t r = 0; r < n_; ++r)
      for (std::size_t c = 0; c < n_; ++c) G[r] += M[r * n_ + c] * w[c];
  }

  const Kernel_partner_system& ks_;
  int axis_;
  std::size_t n_;
  std::size_t f_ = 0;
};

/// Phantom status of the arc points over the span T of a graph piece (graph coordinate `axis`, cell `cell`) by the
/// kernel system (header comment); `other` a floating-point value of the other coordinate at the middle of T.
/// True: no arc point over T has a partner in `domain` (P and Q both inside for a self-intersection, (s, v) for
/// an intersection). False: not proved.
inline bool kernel_proves_phantom(const Kernel_partner_system& ks, const Parameter_box& domain, int axis,
                                  const Double_interval& T, double other, const Parameter_box& cell) {
  using D = Double_interval;
  if (!ks.usable()) return false;
  Kernel_span_system sys(ks, axis);
  std::vector<D> Z, K;

  if (!sys.predict(T, other, Z)) return false;
  bool proved = false;
  for (int attempt = 0; attempt < 3 && !proved; ++attempt) {
    if (sys.krawczyk(T, Z, K)) {
      proved = true;
      break;
    }

    if (K.size() != Z.size() || !(std::isfinite(K[0].lo) && std::isfinite(K[0].hi))) return false;
    for (std::size_t c = 0; c < Z.size(); ++c) {  // epsilon-inflation of the image (contracting entries shrink)
      const double r = 0.25 * (K[c].hi - K[c].lo) + 1e-15 * (1 + std::fabs(K[c].lo));
      Z[c] = D{K[c].lo - r, K[c].hi + r};
    }
  }
  if (!proved) return false;
  // the zero lies strictly inside the cell's range of the other coordinate: it is the arc point
  // (compared exactly: the cell's bounds are rationals, their double hull is wider)
  const Rational &lo = axis == 0 ? cell.v0 : cell.u0, &hi = axis == 0 ? cell.v1 : cell.u1;
  if (!(std::isfinite(K[0].lo) && std::isfinite(K[0].hi) && Rational(K[0].lo) > lo && Rational(K[0].hi) < hi))
    return false;
  std::array<D, 2> y;
  if (!ks.partner(sys.kernel(K), y)) return true;  // no vector of monomial form: no partner at all
  const D x0 = axis == 0 ? T : K[0], x1 = axis == 0 ? K[0] : T;
  const D du = D::hull(domain.u0, domain.u1), dv = D::hull(domain.v0, domain.v1);
  auto disjoint = [](const D& a, const D& b) { return a.hi < b.lo || b.hi < a.lo; };
  if (ks.self_intersection())  // P = (x0, x1 + k), Q = (x0 + l, x1), y = (l, k)
    return disjoint(x0 + y[0], du) || disjoint(x1 + y[1], dv);
  return disjoint(y[0], du) || disjoint(y[1], dv);  // y = (s, v)
}

}  // namespace internal
}  // namespace bezoutian

#endif

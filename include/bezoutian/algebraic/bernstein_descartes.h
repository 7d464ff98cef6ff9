// Certified real root isolation of a square-free integer polynomial on [0,1]
// by Descartes' rule of signs in the Bernstein basis (the Bernstein variant of
// the Vincent-Collins-Akritas method), with exact GMP integer arithmetic and a
// proved floating-point filter.
//
// Mathematical background (standard; e.g. Basu-Pollack-Roy, "Algorithms in
// Real Algebraic Geometry", ch. 10):
//  * G(t) = sum_k b_k C(n,k) t^k (1-t)^(n-k) on [0,1]. The number var(b) of sign
//    changes of (b_0..b_n), zeros skipped, bounds the number of roots of G in
//    the open interval (0,1) counted with multiplicity, and has the parity of
//    that number; var(b) = 0 means no root, var(b) = 1 exactly one simple root.
//  * var(b) is also the number of sign changes of the coefficients of
//    (1+x)^n G(1/(1+x)), which is how the coefficients are first computed.
//  * de Casteljau at 1/2 gives the Bernstein coefficients on both halves.
//  * For a square-free G the subdivision terminates: once an interval is
//    small compared to the root separation, var(b) is 0 or 1 (one- and
//    two-circle theorems).
//
// Internal header: the public API is in bezoutian/Root_isolation.h and
// bezoutian/Algebraic_real.h.
#ifndef BEZOUTIAN_ALGEBRAIC_BERNSTEIN_DESCARTES_H
#define BEZOUTIAN_ALGEBRAIC_BERNSTEIN_DESCARTES_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/mpz.h>

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

using Mpz_vector = std::vector<Mpz>;

/// Degree of a coefficient vector (index of the last nonzero entry, -1 for 0).
inline int degree_of(const Mpz_vector& c) {
  for (int i = static_cast<int>(c.size()) - 1; i >= 0; --i)
    if (c[i].sign() != 0) return i;
  return -1;
}

/// out = q^n f(p/q) for f = sum c_i x^i of degree n = c.size()-1, q > 0
/// (homogeneous Horner scheme; the sign of out is the sign of f(p/q)).
inline void evaluate_homogeneous(const Mpz_vector& c, mpz_srcptr p, mpz_srcptr q, mpz_ptr out) {
  const int n = static_cast<int>(c.size()) - 1;
  if (n < 0) { mpz_set_ui(out, 0); return; }
  Mpz qp(1L), t;
  mpz_set(out, c[n].get());
  for (int i = n - 1; i >= 0; --i) {
    mpz_mul(qp.get(), qp.get(), q);
    mpz_mul(out, out, p);
    mpz_mul(t.get(), c[i].get(), qp.get());
    mpz_add(out, out, t.get());
  }
}

/// Exact sign of f(p/q), q > 0.
inline int sign_at(const Mpz_vector& c, mpz_srcptr p, mpz_srcptr q) {
  Mpz v;
  evaluate_homogeneous(c, p, q, v.get());
  return v.sign();
}

/// out = 2^(k n) f(p / 2^k): the dyadic case, with shifts instead of products.
inline void evaluate_dyadic(const Mpz_vector& c, mpz_srcptr p, unsigned long k, mpz_ptr out) {
  const int n = static_cast<int>(c.size()) - 1;
  if (n < 0) { mpz_set_ui(out, 0); return; }
  Mpz t;
  mpz_set(out, c[n].get());
  for (int i = n - 1; i >= 0; --i) {
    mpz_mul(out, out, p);
    mpz_mul_2exp(t.get(), c[i].get(), k * static_cast<unsigned long>(n - i));
    mpz_add(out, out, t.get());
  }
}

/// Exact sign of f(p / 2^k).
inline int sign_at_dyadic(const Mpz_vector& c, mpz_srcptr p, unsigned long k) {
  Mpz v;
  evaluate_dyadic(c, p, k, v.get());
  return v.sign();
}

/// a(x) <- a(x+1) in place (n(n+1)/2 additions).
inline void taylor_shift_by_one(Mpz_vector& a) {
  const int n = static_cast<int>(a.size()) - 1;
  for (int i = 0; i < n; ++i)
    for (int j = n - 1; j >= i; --j) mpz_add(a[j].get(), a[j].get(), a[j + 1].get());
}

/// Divides all entries by their gcd (the content), if it is not 1.
inline void remove_content(Mpz_vector& a) {
  Mpz g;
  for (const Mpz& x : a) {
    if (x.sign() == 0) continue;
    mpz_gcd(g.get(), g.get(), x.get());
    if (mpz_cmp_ui(g.get(), 1) == 0) return;
  }
  if (g.sign() == 0) return;
  for (Mpz& x : a) mpz_divexact(x.get(), x.get(), g.get());
}

/// Divides all entries by the largest power of two dividing all of them.
inline void remove_common_power_of_two(Mpz_vector& a) {
  mp_bitcnt_t s = std::numeric_limits<mp_bitcnt_t>::max();
  for (const Mpz& x : a)
    if (x.sign() != 0) s = std::min(s, mpz_scan1(x.get(), 0));
  if (s == 0 || s == std::numeric_limits<mp_bitcnt_t>::max()) return;
  for (Mpz& x : a) mpz_tdiv_q_2exp(x.get(), x.get(), s);
}

/// Number of sign changes of a sequence of signs, zeros skipped.
template <class Signs>
int sign_variations_of(const Signs& s, std::size_t n) {
  int v = 0, last = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int si = s(i);
    if (si == 0) continue;
    if (last != 0 && si != last) ++v;
    last = si;
  }
  return v;
}

inline int sign_variations(const Mpz_vector& b) {
  return sign_variations_of([&](std::size_t i) { return b[i].sign(); }, b.size());
}

/// Integer Bernstein coefficients (up to a common positive factor) of the
/// degree-n polynomial sum c_i t^i on [0,1].
/// B_k = C(n,k) b_k is the coefficient of x^(n-k) in sum c_i (1+x)^(n-i), the
/// Taylor shift by one of the reversed polynomial; then b_k = B_k L / C(n,k)
/// with L = lcm_k C(n,k) makes every b_k an integer.
class Bernstein_converter {
 public:
  explicit Bernstein_converter(int n) : n_(n), factor_(n + 1) {
    Mpz lcm(1L), binom;
    std::vector<Mpz> binoms(n + 1);
    for (int k = 0; k <= n; ++k) {
      mpz_bin_uiui(binoms[k].get(), static_cast<unsigned long>(n), static_cast<unsigned long>(k));
      mpz_lcm(lcm.get(), lcm.get(), binoms[k].get());
    }
    for (int k = 0; k <= n; ++k) mpz_divexact(factor_[k].get(), lcm.get(), binoms[k].get());
  }
  int degree() const { return n_; }

  /// bern <- Bernstein coefficients of mono (size n+1) on [0,1], content removed.
  void operator()(const Mpz_vector& mono, Mpz_vector& bern) const {
    bern.resize(n_ + 1);
    for (int j = 0; j <= n_; ++j) mpz_set(bern[j].get(), mono[n_ - j].get());
    taylor_shift_by_one(bern);           // bern[j] = B_{n-j}
    std::reverse(bern.begin(), bern.end());  // bern[k] = B_k
    for (int k = 0; k <= n_; ++k) mpz_mul(bern[k].get(), bern[k].get(), factor_[k].get());
    remove_content(bern);
  }

 private:
  int n_;
  Mpz_vector factor_;
};

/// Exact de Casteljau subdivision at 1/2 without divisions: with
/// c^(j)_i = c^(j-1)_i + c^(j-1)_(i+1) (so c^(j)_i = 2^j b^(j)_i), the halves
/// are left_j = 2^(n-j) c^(j)_0 and right_k = 2^k c^(n-k)_k, both scaled by 2^n.
inline void de_casteljau_exact(const Mpz_vector& b, Mpz_vector& left, Mpz_vector& right, Mpz_vector& w) {
  const int n = static_cast<int>(b.size()) - 1;
  w.resize(n + 1);
  for (int i = 0; i <= n; ++i) mpz_set(w[i].get(), b[i].get());
  left.resize(n + 1);
  right.resize(n + 1);
  mpz_mul_2exp(left[0].get(), w[0].get(), static_cast<mp_bitcnt_t>(n));
  mpz_mul_2exp(right[n].get(), w[n].get(), static_cast<mp_bitcnt_t>(n));
  for (int j = 1; j <= n; ++j) {
    for (int i = 0; i <= n - j; ++i) mpz_add(w[i].get(), w[i].get(), w[i + 1].get());
    mpz_mul_2exp(left[j].get(), w[0].get(), static_cast<mp_bitcnt_t>(n - j));
    mpz_mul_2exp(right[n - j].get(), w[n - j].get(), static_cast<mp_bitcnt_t>(n - j));
  }
  remove_common_power_of_two(left);
  remove_common_power_of_two(right);
}

/// Bernstein coefficients in double precision with a proved bound `err` on
/// the absolute error of every entry (relative to the exact coefficients
/// multiplied by a power of two that is not stored: only signs matter).
struct Float_bernstein {
  std::vector<double> b;
  double err = 0;
};

/// Rounds exact coefficients to doubles scaled so that max |b| is in [1/2,1).
/// mpz_get_d_2exp truncates (relative error < 2^-52); entries that underflow
/// after scaling lose at most 2^-1074. Returns false if all entries are zero.
inline bool float_from_exact(const Mpz_vector& e, Float_bernstein& out) {
  const std::size_t m = e.size();
  out.b.resize(m);
  long emax = std::numeric_limits<long>::min();
  std::vector<double> mant(m);
  std::vector<long> ex(m);
  for (std::size_t i = 0; i < m; ++i) {
    mant[i] = mpz_get_d_2exp(&ex[i], e[i].get());
    if (mant[i] != 0) emax = std::max(emax, ex[i]);
  }
  if (emax == std::numeric_limits<long>::min()) return false;
  for (std::size_t i = 0; i < m; ++i) {
    const long s = ex[i] - emax;
    out.b[i] = (mant[i] == 0 || s < -1100) ? 0.0 : std::ldexp(mant[i], static_cast<int>(s));
  }
  out.err = 0x1p-51;  // >= 2^-52 * max|b| + 2^-1074
  return true;
}

/// Floating-point de Casteljau at 1/2. Each of the n averaging levels adds at
/// most u*M + 2^-1075 to the error (u = 2^-53, M = max |b|, averages never
/// exceed M(1+u)), so err_child <= err + n (2^-52 M + 2^-1074); the children are
/// rescaled by exact powers of two.
inline void de_casteljau_float(const Float_bernstein& in, Float_bernstein& left, Float_bernstein& right,
                               std::vector<double>& w) {
  const int n = static_cast<int>(in.b.size()) - 1;
  double M = 0;
  for (double x : in.b) M = std::max(M, std::fabs(x));
  w.assign(in.b.begin(), in.b.end());
  left.b.resize(n + 1);
  right.b.resize(n + 1);
  left.b[0] = w[0];
  right.b[n] = w[n];
  for (int j = 1; j <= n; ++j) {
    for (int i = 0; i <= n - j; ++i) w[i] = (w[i] + w[i + 1]) * 0.5;
    left.b[j] = w[0];
    right.b[n - j] = w[n - j];
  }
  const double err = (in.err + n * (0x1p-52 * M + 0x1p-1074)) * (1 + 0x1p-40);
  for (Float_bernstein* c : {&left, &right}) {
    c->err = err;
    double mc = 0;
    for (double x : c->b) mc = std::max(mc, std::fabs(x));
    mc = std::max(mc, err);
    int e;
    std::frexp(mc, &e);
    if (e < -200 || e > 200) {  // keep away from underflow; scaling by 2^-e is exact
      for (double& x : c->b) x = std::ldexp(x, -e);
      c->err = std::ldexp(c->err, -e);
    }
  }
}

/// A root found on [0,1]: the exact point k/2^d, or the open interval
/// (k/2^d, (k+1)/2^d) holding exactly one simple root, whose ends are not
/// roots; sign_lo is the sign of G at k/2^d (for intervals).
struct Dyadic_root {
  Mpz k;
  unsigned long d = 0;
  bool exact = false;
  int sign_lo = 0;
};

/// Counters describing one isolation run (for benchmarks and tests).
struct Isolation_statistics {
  std::size_t nodes = 0;          // subdivision nodes visited
  std::size_t exact_nodes = 0;    // nodes whose exact coefficients were computed
  std::size_t exact_midpoints = 0;  // exact evaluations at midpoints
  unsigned long max_depth = 0;
};

/// Isolates the roots in [0,1] of G = sum c_i t^i (integer coefficients, no
/// multiple root in [0,1]). Results are sorted increasingly.
class Bernstein_descartes_isolator {
 public:
  /// Safety net against misuse with a non-square-free polynomial (a multiple
  /// root makes the subdivision infinite): depth beyond this throws.
  static constexpr unsigned long max_depth = 200000;

  explicit Bernstein_descartes_isolator(Mpz_vector G) : G_(std::move(G)) {
    n_ = degree_of(G_);
    if (n_ < 0) throw Invalid_input("Bernstein_descartes_isolator: zero polynomial");
    G_.resize(n_ + 1);
  }

  const Isolation_statistics& statistics() const { return stats_; }

  /// Testing aid: with false, every node is decided by exact arithmetic.
  void set_float_filter(bool on) { float_filter_ = on; }

  std::vector<Dyadic_root> run() {
    std::vector<Dyadic_root> out;
    if (n_ == 0) return out;
    converter_.reset(new Bernstein_converter(n_));
    Mpz zero(0L);
    const int s0 = G_[0].sign();
    Mpz sum(0L);
    for (const Mpz& c : G_) mpz_add(sum.get(), sum.get(), c.get());
    const int s1 = sum.sign();
    if (s0 == 0) push_point(out, zero.get(), 0);
    // Root node: exact Bernstein coefficients.
    auto root = std::make_shared<Exact_node>();
    root->d = 0;
    root->mono = G_;
    (*converter_)(G_, root->b);
    ++stats_.exact_nodes;
    Node r;
    r.d = 0;
    r.s_lo = s0;
    r.s_hi = s1;
    r.exact = root;
    r.mono = root;
    stack_.clear();
    stack_.push_back(std::move(r));
    while (!stack_.empty()) {
      Node node = std::move(stack_.back());
      stack_.pop_back();
      if (node.marker) {
        push_point(out, node.k.get(), node.d);
        continue;
      }
      process(node, out);
    }
    if (s1 == 0) {
      Mpz one(1L);
      push_point(out, one.get(), 0);
    }
    return out;
  }

 private:
  struct Exact_node {
    Mpz k;
    unsigned long d = 0;
    Mpz_vector b;                          // Bernstein coefficients on [k/2^d, (k+1)/2^d]
    Mpz_vector mono;                       // local monomial form (may be empty)
    std::shared_ptr<Exact_node> child[2];  // exact halves, computed on demand
  };
  struct Node {
    Mpz k;
    unsigned long d = 0;
    int s_lo = 0, s_hi = 0;             // exact signs of G at the ends
    bool marker = false;                // "emit the exact root k/2^d"
    bool has_float = false;
    Float_bernstein f;
    std::shared_ptr<Exact_node> exact;  // exact coefficients of this node or of an ancestor
    std::shared_ptr<Exact_node> mono;   // nearest ancestor (or self) with its monomial form
  };

  void push_point(std::vector<Dyadic_root>& out, mpz_srcptr k, unsigned long d) {
    Dyadic_root r;
    mpz_set(r.k.get(), k);
    r.d = d;
    r.exact = true;
    out.push_back(std::move(r));
  }

  // Variation count from the filter: -1 if undecided. Dropping terms never
  // increases the number of sign changes, so >= 2 changes among the certain
  // entries already proves var >= 2.
  int float_variations(const Node& node) const {
    const std::vector<double>& b = node.f.b;
    const double err = node.f.err;
    bool uncertain = false;
    int v = 0, last = 0;
    for (int i = 0; i <= n_; ++i) {
      int s;
      if (i == 0) s = node.s_lo;
      else if (i == n_) s = node.s_hi;
      else if (b[i] > err) s = 1;
      else if (b[i] < -err) s = -1;
      else { uncertain = true; continue; }
      if (s == 0) continue;
      if (last != 0 && s != last) ++v;
      last = s;
    }
    if (uncertain && v < 2) return -1;
    return v;
  }

  // Exact Bernstein coefficients of the node: by exact de Casteljau from a
  // close exact ancestor, otherwise from the local monomial form of the
  // nearest ancestor A that has one: with r = k - 2^gap k_A,
  // P(t) = 2^(gap n) P_A((r + t)/2^gap) = sum_i a_i (r + t)^i 2^(gap(n-i)),
  // a Horner scheme in (r + t) whose multiplier r has only gap bits (from the
  // root, k would have d bits).
  std::shared_ptr<Exact_node> exact_of(const Node& node) {
    std::shared_ptr<Exact_node> cur = node.exact;
    if (cur && cur->d == node.d) return cur;
    if (cur && node.d - cur->d <= 2) {
      while (cur->d < node.d) {
        const unsigned long shift = node.d - cur->d - 1;
        const int bit = mpz_tstbit(node.k.get(), shift);
        if (!cur->child[0]) {
          auto l = std::make_shared<Exact_node>(), r = std::make_shared<Exact_node>();
          l->d = r->d = cur->d + 1;
          mpz_mul_2exp(l->k.get(), cur->k.get(), 1);
          mpz_add_ui(r->k.get(), l->k.get(), 1);
          de_casteljau_exact(cur->b, l->b, r->b, exact_work_);
          stats_.exact_nodes += 2;
          cur->child[0] = l;
          cur->child[1] = r;
        }
        cur = cur->child[bit];
      }
      return cur;
    }
    const Exact_node& A = *node.mono;
    const unsigned long gap = node.d - A.d;
    Mpz r;
    mpz_mul_2exp(r.get(), A.k.get(), gap);
    mpz_sub(r.get(), node.k.get(), r.get());
    auto e = std::make_shared<Exact_node>();
    e->d = node.d;
    mpz_set(e->k.get(), node.k.get());
    Mpz_vector& H = e->mono;
    H.resize(n_ + 1);
    Mpz t;
    mpz_set(H[0].get(), A.mono[n_].get());
    for (int i = n_ - 1; i >= 0; --i) {
      const int deg = n_ - 1 - i;  // current degree of H
      // H <- H * (r + t)
      mpz_set(H[deg + 1].get(), H[deg].get());
      for (int j = deg; j >= 1; --j) {
        mpz_mul(H[j].get(), H[j].get(), r.get());
        mpz_add(H[j].get(), H[j].get(), H[j - 1].get());
      }
      mpz_mul(H[0].get(), H[0].get(), r.get());
      mpz_mul_2exp(t.get(), A.mono[i].get(), gap * static_cast<unsigned long>(n_ - i));
      mpz_add(H[0].get(), H[0].get(), t.get());
    }
    remove_common_power_of_two(H);
    (*converter_)(H, e->b);
    ++stats_.exact_nodes;
    return e;
  }

  void process(Node& node, std::vector<Dyadic_root>& out) {
    ++stats_.nodes;
    stats_.max_depth = std::max(stats_.max_depth, node.d);
    if (node.d > max_depth)
      throw Error("bezoutian root isolation: subdivision too deep (polynomial not square-free?)");
    int var = (node.has_float && float_filter_) ? float_variations(node) : -1;
    bool have_exact = false;
    if (var < 0) {
      node.exact = exact_of(node);
      if (!node.exact->mono.empty()) node.mono = node.exact;
      have_exact = true;
      var = sign_variations(node.exact->b);
    }
    if (var == 0) return;
    if (var == 1 && node.s_lo != 0 && node.s_hi != 0) {
      Dyadic_root r;
      mpz_set(r.k.get(), node.k.get());
      r.d = node.d;
      r.exact = false;
      r.sign_lo = node.s_lo;
      out.push_back(std::move(r));
      return;
    }
    // Subdivide in floating point; exact coefficients (if any) stay attached
    // to the children as the ancestor to fall back on.
    Node left, right;
    left.d = right.d = node.d + 1;
    mpz_mul_2exp(left.k.get(), node.k.get(), 1);
    mpz_add_ui(right.k.get(), left.k.get(), 1);
    left.exact = right.exact = node.exact;
    left.mono = right.mono = node.mono;
    Float_bernstein src;
    const Float_bernstein* fsrc = nullptr;
    if (have_exact) {
      if (float_from_exact(node.exact->b, src)) fsrc = &src;
    } else if (node.has_float) {
      fsrc = &node.f;
    }
    int s_mid = 2;
    if (fsrc) {
      de_casteljau_float(*fsrc, left.f, right.f, float_work_);
      left.has_float = right.has_float = true;
      const double v = left.f.b[n_];
      if (v > left.f.err) s_mid = 1;
      else if (v < -left.f.err) s_mid = -1;
    }
    if (s_mid == 2) {
      ++stats_.exact_midpoints;
      s_mid = sign_at_dyadic(G_, right.k.get(), right.d);
    }
    left.s_lo = node.s_lo;
    left.s_hi = s_mid;
    right.s_lo = s_mid;
    right.s_hi = node.s_hi;
    stack_.push_back(std::move(right));
    if (s_mid == 0) {
      Node m;
      m.marker = true;
      mpz_add_ui(m.k.get(), left.k.get(), 1);  // midpoint (2k+1)/2^(d+1)
      m.d = node.d + 1;
      stack_.push_back(std::move(m));
    }
    stack_.push_back(std::move(left));
  }

  Mpz_vector G_;
  int n_ = 0;
  std::unique_ptr<Bernstein_converter> converter_;
  std::vector<Node> stack_;
  Isolation_statistics stats_;
  bool float_filter_ = true;
  Mpz_vector exact_work_;          // reused buffers (no allocation per node)
  std::vector<double> float_work_;
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ALGEBRAIC_BERNSTEIN_DESCARTES_H

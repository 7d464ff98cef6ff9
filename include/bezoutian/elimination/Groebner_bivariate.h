// Lexicographic Groebner bases of bivariate polynomial ideals over Q, and the eliminant they give: du-1989 §3.5
// (Groebner bases) applied to the curve intersection system as in its §4 ("the third method"). The reduced lex
// basis with t > s contains one polynomial in s alone, the generator of the elimination ideal I ∩ Q[s], whose roots
// are exactly the s-coordinates of the common complex zeros. Two algorithms: `lex_groebner_basis`, Buchberger's
// algorithm in exact rational arithmetic (the reference, and the fallback), and `modular_lex_groebner_basis`, the
// basis modulo word primes lifted by Chinese remaindering and rational reconstruction and then certified over Q
// (the one `groebner_eliminant` and the groebner strategy of Curve_intersection.h use).
#ifndef BEZOUTIAN_ELIMINATION_GROEBNER_BIVARIATE_H
#define BEZOUTIAN_ELIMINATION_GROEBNER_BIVARIATE_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#include <bezoutian/arithmetic/modular_arithmetic.h>
#include <bezoutian/elimination/internal/modular_groebner.h>
#include <bezoutian/arithmetic/rational_reconstruction.h>

#include <CGAL/Polynomial.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

namespace bezoutian {

/// A sparse bivariate polynomial over Q in (s, t) with the lexicographic order t > s: a monomial s^i t^j is
/// stored under the key (j, i), and the map is sorted with the largest monomial first.
class Lex_polynomial_2 {
 public:
  using Monomial = std::pair<int, int>;  // (exponent of t, exponent of s)
  using Terms = std::map<Monomial, Rational, std::greater<Monomial>>;

  Lex_polynomial_2() = default;
  /// From terms (zero coefficients are not allowed).
  explicit Lex_polynomial_2(Terms terms) : terms_(std::move(terms)) {}
  /// From a CGAL bivariate polynomial (inner variable s, outer variable t).
  template <class NT>
  explicit Lex_polynomial_2(const Polynomial_2<NT>& f) {
    if (CGAL::is_zero(f)) return;
    for (int j = 0; j <= f.degree(); ++j)
      for (int i = 0; !CGAL::is_zero(f[j]) && i <= f[j].degree(); ++i)
        if (!CGAL::is_zero(f[j][i])) terms_[{j, i}] = Rational(f[j][i]);
  }

  bool is_zero() const { return terms_.empty(); }
  const Terms& terms() const { return terms_; }
  const Monomial& leading_monomial() const { return terms_.begin()->first; }
  const Rational& leading_coefficient() const { return terms_.begin()->second; }
  bool is_univariate_in_s() const { return !terms_.empty() && leading_monomial().first == 0; }

  /// this += c * s^di t^dj * g
  void add_multiple(const Lex_polynomial_2& g, const Rational& c, int dj, int di) {
    for (const auto& term : g.terms_) {
      const Monomial m{term.first.first + dj, term.first.second + di};
      auto it = terms_.find(m);
      if (it == terms_.end()) {
        terms_.emplace(m, c * term.second);
      } else {
        it->second += c * term.second;
        if (CGAL::is_zero(it->second)) terms_.erase(it);
      }
    }
  }
  void make_monic() {
    if (terms_.empty()) return;
    const Rational l = leading_coefficient();
    for (auto& term : terms_) term.second /= l;
  }
  /// The univariate polynomial in s (requires is_univariate_in_s()).
  Polynomial_1<Rational> to_univariate() const {
    std::vector<Rational> c(std::size_t(leading_monomial().second + 1), Rational(0));
    for (const auto& term : terms_) c[std::size_t(term.first.second)] = term.second;
    return Polynomial_1<Rational>(c.begin(), c.end());
  }

 private:
  Terms terms_;
};

namespace internal {

inline bool divides(const Lex_polynomial_2::Monomial& a, const Lex_polynomial_2::Monomial& b) {
  return a.first <= b.first && a.second <= b.second;
}

inline Lex_polynomial_2 monomial(const Lex_polynomial_2::Monomial& m, const Rational& c) {
  Polynomial_2<Rational> p = CGAL::shift(CGAL::shift(Polynomial_2<Rational>(c), m.second, 0), m.first, 1);
  return Lex_polynomial_2(p);
}

// Full reduction of f by G (every term, not only the leading one).
inline Lex_polynomial_2 reduce(Lex_polynomial_2 f, const std::vector<Lex_polynomial_2>& G, std::size_t& budget) {
  Lex_polynomial_2 r;
  while (!f.is_zero()) {
    if (budget == 0) throw Error("groebner: the computation exceeds its budget (coefficient growth); use the default method");
    --budget;
    const auto lm = f.leading_monomial();
    const Rational lc = f.leading_coefficient();
    bool reduced = false;
    for (const auto& g : G) {
      if (g.is_zero() || !divides(g.leading_monomial(), lm)) continue;
      budget = budget > g.terms().size() ? budget - g.terms().size() : 0;  // term operations
      f.add_multiple(g, -lc / g.leading_coefficient(), lm.first - g.leading_monomial().first,
                     lm.second - g.leading_monomial().second);
      reduced = true;
      break;
    }
    if (!reduced) {  // the leading term is irreducible: move it to the remainder
      const Lex_polynomial_2 term = monomial(lm, lc);
      r.add_multiple(term, Rational(1), 0, 0);
      f.add_multiple(term, Rational(-1), 0, 0);
    }
  }
  return r;
}

}  // namespace internal

/// Reduced lexicographic (t > s) Groebner basis of the ideal generated by F (Buchberger's algorithm, pairs with
/// coprime leading monomials skipped: Buchberger's first criterion). `budget` bounds the number of reduction
/// steps; Error is thrown beyond it (never a hang).
inline std::vector<Lex_polynomial_2> lex_groebner_basis(const std::vector<Lex_polynomial_2>& F,
                                                        std::size_t budget = 1000000) {
  std::vector<Lex_polynomial_2> G;
  for (const auto& f : F) {
    Lex_polynomial_2 g = internal::reduce(f, G, budget);
    if (!g.is_zero()) {
      g.make_monic();
      G.push_back(g);
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < G.size(); ++i)
    for (std::size_t j = i + 1; j < G.size(); ++j) pairs.push_back({i, j});
  auto lcm_of = [&](const std::pair<std::size_t, std::size_t>& p) {
    const auto la = G[p.first].leading_monomial(), lb = G[p.second].leading_monomial();
    return Lex_polynomial_2::Monomial{std::max(la.first, lb.first), std::max(la.second, lb.second)};
  };
  while (!pairs.empty()) {
    // normal selection strategy: the pair with the smallest lcm of leading monomials first
    std::size_t best = 0;
    for (std::size_t k = 1; k < pairs.size(); ++k)
      if (lcm_of(pairs[k]) < lcm_of(pairs[best])) best = k;
    const auto pr = pairs[best];
    pairs.erase(pairs.begin() + std::ptrdiff_t(best));
    const auto &a = G[pr.first], &b = G[pr.second];
    if (a.is_zero() || b.is_zero()) continue;
    const auto la = a.leading_monomial(), lb = b.leading_monomial();
    if (std::min(la.first, lb.first) == 0 && std::min(la.second, lb.second) == 0)
      continue;  // coprime leading monomials: the S-polynomial reduces to 0 (Buchberger's first criterion)
    const Lex_polynomial_2::Monomial l{std::max(la.first, lb.first), std::max(la.second, lb.second)};
    Lex_polynomial_2 S;
    S.add_multiple(a, Rational(1) / a.leading_coefficient(), l.first - la.first, l.second - la.second);
    S.add_multiple(b, Rational(-1) / b.leading_coefficient(), l.first - lb.first, l.second - lb.second);
    Lex_polynomial_2 r = internal::reduce(S, G, budget);
    if (r.is_zero()) continue;
    r.make_monic();
    G.push_back(r);
    for (std::size_t i = 0; i + 1 < G.size(); ++i) pairs.push_back({i, G.size() - 1});
  }
  // minimal basis: drop elements whose leading monomial is divisible by another's; then reduce each
  std::vector<Lex_polynomial_2> M;
  for (std::size_t i = 0; i < G.size(); ++i) {
    bool redundant = false;
    for (std::size_t j = 0; j < G.size() && !redundant; ++j) {
      if (i == j || G[j].is_zero()) continue;
      const bool d = internal::divides(G[j].leading_monomial(), G[i].leading_monomial());
      redundant = d && (G[j].leading_monomial() != G[i].leading_monomial() || j < i);
    }
    if (!redundant && !G[i].is_zero()) M.push_back(G[i]);
  }
  std::vector<Lex_polynomial_2> R;
  for (std::size_t i = 0; i < M.size(); ++i) {
    std::vector<Lex_polynomial_2> others;
    for (std::size_t j = 0; j < M.size(); ++j)
      if (j != i) others.push_back(M[j]);
    Lex_polynomial_2 lead = internal::monomial(M[i].leading_monomial(), M[i].leading_coefficient());
    Lex_polynomial_2 tail = M[i];
    tail.add_multiple(lead, Rational(-1), 0, 0);
    Lex_polynomial_2 r = internal::reduce(tail, others, budget);
    r.add_multiple(lead, Rational(1), 0, 0);
    r.make_monic();
    R.push_back(r);
  }
  std::sort(R.begin(), R.end(), [](const Lex_polynomial_2& x, const Lex_polynomial_2& y) {
    return x.leading_monomial() < y.leading_monomial();
  });
  return R;
}

// ------------------------------------------------------------------------------------------------------------------
// Multi-modular lexicographic basis, certified over Q.
//
// 1. For word primes p: the reduced lex basis of <F mod p> (dense Buchberger, elimination/internal/modular_groebner.h).
// 2. Unlucky primes: a prime is discarded if it divides a leading coefficient of an input (its leading monomial
//    would change), or if its basis is not zero-dimensional. The other primes are grouped by the leading monomials of
//    their bases; Chinese remaindering and rational reconstruction (Wang) use the largest group (on a tie the group
//    seen first). For all but finitely many primes the basis mod p is the image of the basis over Q, so the true
//    group eventually wins the vote; the choice is never trusted, the certification below decides.
// 3. A reconstruction is tried when the group has grown by a quarter since the last try; it is accepted as a
//    candidate when the next prime of the group agrees with it (stable under one more prime), then certified.
// 4. Certification of the candidate B over Q (exact rational arithmetic), for two equations F1, F2:
//    (a) every F_i reduces to 0 modulo B: I ⊆ <B>;
//    (b) B is a Groebner basis: the S-polynomials of consecutive elements (sorted by leading monomial) reduce to 0.
//        In two variables the others are not needed: for k < l < m, LM(l) = s^i_l t^j_l divides
//        lcm(LM(k), LM(m)) = s^i_k t^j_m (j increasing, i decreasing along a reduced staircase), so Buchberger's
//        chain criterion removes (k, m) (CLO, Ideals, Varieties, and Algorithms, §2.10);
//        pairs with coprime leading monomials are removed by the first criterion;
//    (c) <B> ⊆ I by a dimension count: (a) gives dim Q[s,t]/I >= dim Q[s,t]/<B> = #standard monomials of B.
//        If gcd(lc_t F1, lc_t F2) = 1 (no common point at infinity in the t direction) then
//        dim Q[s,t]/I = deg_s Res_t(F1, F2): R = Res_t is in I and annihilates A = Q[s,t]/I, so over C
//        A = ⊕ A_λ over the roots λ of R, A_λ = A localized at s = λ. At λ one leading coefficient, say lc_t F1, is
//        a unit of the local ring O = C[s]_(s-λ); then O[t]/(F1) is free of rank deg_t F1 and A_λ is the cokernel
//        of the multiplication by F2 on it, of dimension ord_λ det = ord_λ R (Poisson's formula
//        R = ±lc_t(F1)^deg_t F2 det(F2 mod F1), Smith form over the discrete valuation ring O). Summing over λ,
//        dim A = deg R. The same with s and t exchanged. So #standard monomials == deg Res proves <B> = I and B is
//        THE reduced lex basis; a smaller count proves B wrong (an ideal larger than I: more primes are taken).
//        For r >= 3 equations (space curves) with pairwise coprime leading coefficients the same local argument
//        bounds dim Q[s,t]/I <= deg gcd_{i<j} Res_t(F_i, F_j) (Quotient_dimension); a count reaching the bound
//        proves B, a smaller one leaves it open.
//        When the leading coefficients have common roots in both directions, or the bound of r >= 3 equations is
//        not reached, the exact rational Buchberger algorithm (within its budget: Error beyond it) is used.
// If every check passes, the univariate element of B is exactly the generator of I ∩ Q[s].

/// How a basis of `modular_lex_groebner_basis` was obtained.
struct Groebner_certificate {
  std::size_t primes = 0;             ///< word primes tried
  std::size_t discarded_primes = 0;   ///< bad (a leading coefficient vanishes), positive-dimensional or outvoted
  std::size_t certification_attempts = 0;  ///< exact checks of reconstructed candidates
  int standard_monomials = -1;        ///< dim Q[s,t]/\<B\>, -1 for the exact fallback on a positive-dimensional ideal
  int dimension = -1;                 ///< proved dim Q[s,t]/\<F\> = deg Res (-1: not used)
  char eliminated = 0;                ///< 't': the bound deg_s Res_t(F1,F2); 's': deg_t Res_s(F1,F2); 0: none
  bool exact_fallback = false;        ///< computed by the exact rational Buchberger algorithm (lex_groebner_basis)
};

/// Outcome of the exact check of a candidate reduced lex basis B of <F>.
enum class Groebner_check {
  certified,             ///< B is the reduced lex basis of <F> (checks (a), (b), (c))
  not_reduced,           ///< B is not monic, reduced and zero-dimensional
  ideal_not_contained,   ///< (a) fails: some F_i does not reduce to 0 modulo B
  not_a_groebner_basis,  ///< (b) fails: an S-polynomial of B does not reduce to 0
  dimension_mismatch,    ///< (c) fails: #standard monomials != dim Q[s,t]/<F> (B generates a larger ideal)
  dimension_unknown      ///< (c) unavailable: leading coefficients not (pairwise) coprime in either direction, or
                         ///< for three or more equations a count below the resultant gcd's degree (not sharp)
};

namespace internal {

using Dense_Z = Dense_lex_polynomial<Integer>;
using Dense_Q = Dense_lex_polynomial<Rational>;

inline Rational to_rational(const Integer& x) { return Rational(x); }
inline Rational to_rational(const Rational& x) { return x; }

/// The primitive integer multiple of f (rows indexed by the power of t).
template <class NT>
Dense_Z primitive_integer_dense(const Polynomial_2<NT>& f) {
  Dense_Z r;
  if (CGAL::is_zero(f)) return r;
  Integer den(1), content(0);
  for (int j = 0; j <= f.degree(); ++j)
    for (int i = 0; i <= f[j].degree(); ++i) {
      const Rational c = to_rational(f[j][i]);
      if (!CGAL::is_zero(c)) den = den / CGAL::gcd(den, c.denominator()) * c.denominator();
    }
  r.rows.resize(std::size_t(f.degree() + 1));
  for (int j = 0; j <= f.degree(); ++j)
    for (int i = 0; i <= f[j].degree(); ++i) {
      const Rational c = to_rational(f[j][i]) * Rational(den);
      r.rows[std::size_t(j)].push_back(c.numerator());
      content = CGAL::gcd(content, c.numerator());
    }
  for (auto& row : r.rows)
    for (auto& x : row) x = CGAL::integral_division(x, content);
  for (auto& row : r.rows)
    while (!row.empty() && CGAL::is_zero(row.back())) row.pop_back();
  while (!r.rows.empty() && r.rows.back().empty()) r.rows.pop_back();
  return r;
}

inline Dense_Q to_dense(const Lex_polynomial_2& f) {
  Dense_Q r;
  if (f.is_zero()) return r;
  r.rows.resize(std::size_t(f.leading_monomial().first + 1));
  for (const auto& term : f.terms()) {
    auto& row = r.rows[std::size_t(term.first.first)];
    if (row.size() <= std::size_t(term.first.second)) row.resize(std::size_t(term.first.second + 1), Rational(0));
    row[std::size_t(term.first.second)] = term.second;
  }
  normalize(r, Rational_field());
  return r;
}

inline Lex_polynomial_2 to_lex(const Dense_Q& f) {
  Lex_polynomial_2::Terms terms;
  for (std::size_t j = 0; j < f.rows.size(); ++j)
    for (std::size_t i = 0; i < f.rows[j].size(); ++i)
      if (!CGAL::is_zero(f.rows[j][i])) terms.emplace(Lex_polynomial_2::Monomial{int(j), int(i)}, f.rows[j][i]);
  return Lex_polynomial_2(std::move(terms));
}

/// f(s, t) -> f(t, s).
inline Dense_Z transposed(const Dense_Z& f) {
  Dense_Z r;
  for (std::size_t j = 0; j < f.rows.size(); ++j)
    for (std::size_t i = 0; i < f.rows[j].size(); ++i) {
      if (r.rows.size() <= i) r.rows.resize(i + 1);
      auto& row = r.rows[i];
      if (row.size() <= j) row.resize(j + 1, Integer(0));
      row[j] = f.rows[j][i];
    }
  for (auto& row : r.rows)
    while (!row.empty() && CGAL::is_zero(row.back())) row.pop_back();
  while (!r.rows.empty() && r.rows.back().empty()) r.rows.pop_back();
  return r;
}

inline Polynomial_1<Integer> row_polynomial(const std::vector<Integer>& row) {
  return row.empty() ? Polynomial_1<Integer>(0) : Polynomial_1<Integer>(row.begin(), row.end());
}

/// gcd(lc_t f, lc_t g) = 1 in Q[s].
inline bool coprime_leading_coefficients(const Dense_Z& f, const Dense_Z& g) {
  return CGAL::gcd(row_polynomial(f.rows.back()), row_polynomial(g.rows.back())).degree() == 0;
}

/// deg_s Res_t(f, g) for f, g != 0, with Res_t the determinant of the Sylvester matrix in t (the empty
/// determinant 1 when both are free of t); -1 if it vanishes. exact = false: an upper bound only (the max-weight
/// assignment of the entries' degrees); exact = true: the degree of the exact (multi-modular) determinant.
inline int resultant_degree(const Dense_Z& f, const Dense_Z& g, bool exact) {
  const std::size_t m = f.rows.size() - 1, n = g.rows.size() - 1, N = m + n;
  if (N == 0) return 0;
  std::vector<Dense_polynomial_entry> A(N * N);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t k = 0; k <= m; ++k) A[r * N + r + k] = dense_entry(row_polynomial(f.rows[m - k]));
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t k = 0; k <= n; ++k) A[(n + r) * N + r + k] = dense_entry(row_polynomial(g.rows[n - k]));
  std::vector<std::vector<int>> w(N, std::vector<int>(N));
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) w[i][j] = A[i * N + j].du;
  const long bound = max_weight_assignment(w);
  if (!exact || bound < 0) return int(bound);
  std::vector<CGAL::Gmpz> coeffs;
  std::size_t Du = 0, Dv = 0;
  if (!dense_polynomial_matrix_determinant(A, N, coeffs, Du, Dv)) return -1;
  for (std::size_t k = Du + 1; k-- > 0;)
    if (!CGAL::is_zero(coeffs[k])) return int(k);  // Dv = 0: coefficient of s^k at index k
  return -1;
}

/// Res_t(f, g) exactly (multi-modular determinant of the Sylvester matrix), 0 if it vanishes.
inline Polynomial_1<Integer> resultant_polynomial(const Dense_Z& f, const Dense_Z& g) {
  const std::size_t m = f.rows.size() - 1, n = g.rows.size() - 1, N = m + n;
  if (N == 0) return Polynomial_1<Integer>(1);
  std::vector<Dense_polynomial_entry> A(N * N);
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t k = 0; k <= m; ++k) A[r * N + r + k] = dense_entry(row_polynomial(f.rows[m - k]));
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t k = 0; k <= n; ++k) A[(n + r) * N + r + k] = dense_entry(row_polynomial(g.rows[n - k]));
  std::vector<CGAL::Gmpz> coeffs;
  std::size_t Du = 0, Dv = 0;
  if (!dense_polynomial_matrix_determinant(A, N, coeffs, Du, Dv)) return Polynomial_1<Integer>(0);
  return Polynomial_1<Integer>(coeffs.begin(), coeffs.begin() + std::ptrdiff_t(Du + 1));
}

/// dim Q[s,t]/<F> from resultants (see (c) above): for two equations the exact deg Res (multi-modular determinant),
/// and the count is an equality; for r >= 3 equations whose leading
/// coefficients are pairwise coprime, dim Q[s,t]/<F> <= deg gcd_{i<j} Res_t(F_i, F_j), an upper bound only: at a
/// root λ at most one leading coefficient vanishes, and for F_a with a unit leading coefficient in O = C[s]_(s-λ)
/// the localized quotient is the cokernel of [F_b mod F_a]_b on the free module O[t]/(F_a), whose length is the
/// order of the gcd of its maximal minors (Smith form), at most min_b ord_λ Res_t(F_a, F_b); every pair has a member
/// with a unit leading coefficient.
struct Quotient_dimension {
  std::vector<const Dense_Z*> F;  // in the chosen direction (t eliminated)
  char direction = 0;             // 't', 's', or 0 if unavailable
  int value = -1;
  bool exact = false;
  bool equality = false;  // dim == deg Res (two equations); otherwise dim <= value

  explicit Quotient_dimension(const std::vector<Dense_Z>& G, std::vector<Dense_Z>& transposed_storage) {
    if (G.size() < 2) return;
    transposed_storage.clear();
    for (const auto& g : G) transposed_storage.push_back(transposed(g));
    auto pairwise_coprime = [](const std::vector<Dense_Z>& H) {
      for (std::size_t i = 0; i < H.size(); ++i)
        for (std::size_t j = i + 1; j < H.size(); ++j)
          if (!coprime_leading_coefficients(H[i], H[j])) return false;
      return true;
    };
    const std::vector<Dense_Z>* chosen = nullptr;
    if (pairwise_coprime(G)) {
      chosen = &G, direction = 't';
    } else if (pairwise_coprime(transposed_storage)) {
      chosen = &transposed_storage, direction = 's';
    } else {
      return;
    }
    for (const auto& g : *chosen) F.push_back(&g);
    if (F.size() == 2) {
      // exact degree (the max-weight bound alone would not prove Res != 0: coprime leading coefficients do not
      // exclude a common factor of positive degree in t)
      equality = true;
      value = resultant_degree(*F[0], *F[1], true);
      exact = true;
    } else {
      Polynomial_1<Integer> r(0);
      for (std::size_t i = 0; i < F.size(); ++i)
        for (std::size_t j = i + 1; j < F.size(); ++j) {
          const Polynomial_1<Integer> q = resultant_polynomial(*F[i], *F[j]);
          if (CGAL::is_zero(q)) continue;  // a common component of this pair: other pairs bound the dimension
          r = CGAL::is_zero(r) ? q : CGAL::gcd(r, q);
        }
      value = CGAL::is_zero(r) ? -1 : r.degree();
      exact = true;
    }
    if (value < 0) direction = 0;  // Res = 0 (a common component): the count does not apply
  }
  bool available() const { return direction != 0; }
  /// Proves dim == count (true); false: dim != count (two equations) or unknown (more equations). The candidate
  /// passed (a), so count <= dim <= value: equality throughout.
  bool equals(int count) const { return count == value; }
};

/// The k-th word prime (word_prime itself keeps the primes it has found).
inline u64 cached_word_prime(std::size_t k) { return word_prime(k); }

/// The primitive integer multiple of a rational polynomial.
inline Dense_Z primitive_integer_dense(const Dense_Q& f) {
  Integer den(1), content(0);
  for (const auto& row : f.rows)
    for (const auto& c : row)
      if (!CGAL::is_zero(c)) den = den / CGAL::gcd(den, c.denominator()) * c.denominator();
  Dense_Z r;
  for (const auto& row : f.rows) {
    r.rows.emplace_back();
    for (const auto& c : row) {
      r.rows.back().push_back(CGAL::integral_division(c.numerator() * den, c.denominator()));
      content = CGAL::gcd(content, r.rows.back().back());
    }
  }
  if (content > 1)
    for (auto& row : r.rows)
      for (auto& x : row) x = CGAL::integral_division(x, content);
  return r;
}

/// Whether f reduces to 0 modulo B (primitive integer polynomials; leading monomials L sorted increasing, a
/// zero-dimensional reduced staircase), by fraction-free reduction row by row: the row of t^j is reduced by the
/// element b_k with the largest j_k <= j, whose leading monomial s^i_k t^j_k has the smallest s-exponent among the
/// divisors of that row's monomials (i decreases along the staircase); the terms left in the row (s-degree < i_k)
/// are irreducible, so a nonzero row ends the reduction with a nonzero remainder. f is multiplied by nonzero
/// integers on the way (which does not change whether it lies in the ideal) and divided by its content after each
/// row. (Per-row denominators with pseudo-division modulo the univariate element were tried: pseudo-division's
/// lc^(deg f - deg g + 1) makes them 3-4 times slower.)
inline bool reduces_to_zero(Dense_Z f, const std::vector<Dense_Z>& B, const std::vector<Lex_monomial>& L) {
  for (int j = int(f.rows.size()) - 1; j >= 0; --j) {
    std::size_t k = L.size();
    while (k > 0 && L[k - 1].first > j) --k;
    if (k == 0) return false;  // no divisor (cannot happen for a zero-dimensional staircase)
    --k;
    const Dense_Z& b = B[k];
    const int jk = L[k].first, ik = L[k].second;
    const Integer& lambda = b.rows.back().back();
    auto& row = f.rows[std::size_t(j)];
    if (ik == 0 && b.rows.back().size() == 1) {
      // the divisor's top row is the constant lambda: the whole row at once, lambda t^j f_j = f_j t^(j-jk) (b - tail)
      Integer g = lambda;
      for (const auto& x : row)
        if (!CGAL::is_zero(x) && g != 1) g = CGAL::gcd(g, x);
      const Integer alpha = CGAL::integral_division(lambda, g);
      if (alpha != 1)
        for (int r = 0; r < j; ++r)
          for (auto& x : f.rows[std::size_t(r)])
            if (!CGAL::is_zero(x)) x *= alpha;
      for (int d = int(row.size()) - 1; d >= 0; --d) {
        if (CGAL::is_zero(row[std::size_t(d)])) continue;
        const Integer beta = CGAL::integral_division(row[std::size_t(d)], g);
        for (int jj = 0; jj < jk; ++jj) {
          const auto& br = b.rows[std::size_t(jj)];
          auto& fr = f.rows[std::size_t(jj + j - jk)];
          if (fr.size() < br.size() + std::size_t(d)) fr.resize(br.size() + std::size_t(d), Integer(0));
          for (std::size_t ii = 0; ii < br.size(); ++ii)
            if (!CGAL::is_zero(br[ii])) fr[ii + std::size_t(d)] -= beta * br[ii];
        }
      }
      row.clear();
    }
    for (int d = int(row.size()) - 1; d >= ik; --d) {
      if (CGAL::is_zero(row[std::size_t(d)])) continue;
      const Integer a = row[std::size_t(d)];
      const Integer g = CGAL::gcd(a, lambda);
      const Integer alpha = CGAL::integral_division(lambda, g), beta = CGAL::integral_division(a, g);
      if (alpha != 1)
        for (int r = 0; r <= j; ++r)
          for (auto& x : f.rows[std::size_t(r)])
            if (!CGAL::is_zero(x)) x *= alpha;
      const int shift_t = j - jk, shift_s = d - ik;
      for (int jj = 0; jj <= jk; ++jj) {
        const auto& br = b.rows[std::size_t(jj)];
        auto& fr = f.rows[std::size_t(jj + shift_t)];
        if (fr.size() < br.size() + std::size_t(shift_s)) fr.resize(br.size() + std::size_t(shift_s), Integer(0));
        for (std::size_t ii = 0; ii < br.size(); ++ii)
          if (!CGAL::is_zero(br[ii])) fr[ii + std::size_t(shift_s)] -= beta * br[ii];
      }
      row[std::size_t(d)] = 0;  // exact: beta lambda = alpha a
    }
    for (const auto& x : row)
      if (!CGAL::is_zero(x)) return false;
    Integer content(0);
    for (int r = 0; r < j && content != 1; ++r)
      for (const auto& x : f.rows[std::size_t(r)]) {
        if (CGAL::is_zero(x)) continue;
        content = CGAL::gcd(content, x);
        if (content == 1) break;
      }
    if (content > 1)
      for (int r = 0; r < j; ++r)
        for (auto& x : f.rows[std::size_t(r)])
          if (!CGAL::is_zero(x)) x = CGAL::integral_division(x, content);
  }
  return true;
}

/// The integer S-polynomial of b and c (integer leading coefficients λ_b, λ_c): λ_c m_b b - λ_b m_c c.
inline Dense_Z integer_s_polynomial(const Dense_Z& b, const Dense_Z& c) {
  const Lex_monomial lb{int(b.rows.size()) - 1, int(b.rows.back().size()) - 1};
  const Lex_monomial lc{int(c.rows.size()) - 1, int(c.rows.back().size()) - 1};
  const Lex_monomial l{std::max(lb.first, lc.first), std::max(lb.second, lc.second)};
  Dense_Z S;
  S.rows.resize(std::size_t(l.first + 1));
  auto add = [&](const Dense_Z& p, const Integer& factor, int dj, int di) {
    for (std::size_t j = 0; j < p.rows.size(); ++j) {
      auto& row = S.rows[j + std::size_t(dj)];
      if (row.size() < p.rows[j].size() + std::size_t(di)) row.resize(p.rows[j].size() + std::size_t(di), Integer(0));
      for (std::size_t i = 0; i < p.rows[j].size(); ++i) row[i + std::size_t(di)] += factor * p.rows[j][i];
    }
  };
  add(b, c.rows.back().back(), l.first - lb.first, l.second - lb.second);
  add(c, -b.rows.back().back(), l.first - lc.first, l.second - lc.second);
  for (auto& row : S.rows)
    while (!row.empty() && CGAL::is_zero(row.back())) row.pop_back();
  while (!S.rows.empty() && S.rows.back().empty()) S.rows.pop_back();
  return S;
}

/// Exact check of a candidate basis B (sorted by increasing leading monomial).
inline Groebner_check check_basis(const std::vector<Dense_Z>& F, const std::vector<Dense_Q>& B, Quotient_dimension& dim,
                                  int* standard_count = nullptr) {
  std::vector<Lex_monomial> L;
  for (const auto& b : B) {
    if (b.is_zero() || b.leading_coefficient() != 1) return Groebner_check::not_reduced;
    L.push_back(b.leading_monomial());
  }
  for (std::size_t k = 0; k + 1 < L.size(); ++k)
    if (!(L[k].first < L[k + 1].first && L[k].second > L[k + 1].second)) return Groebner_check::not_reduced;
  if (!zero_dimensional(L)) return Groebner_check::not_reduced;
  for (std::size_t k = 0; k < B.size(); ++k)  // reduced: every other term is a standard monomial
    for (std::size_t j = 0; j < B[k].rows.size(); ++j)
      for (std::size_t i = 0; i < B[k].rows[j].size(); ++i) {
        if (CGAL::is_zero(B[k].rows[j][i]) || Lex_monomial{int(j), int(i)} == L[k]) continue;
        for (const auto& l : L)
          if (monomial_divides(l, {int(j), int(i)})) return Groebner_check::not_reduced;
      }
  const int count = int(standard_monomials(L).size());
  if (standard_count) *standard_count = count;
  std::vector<Dense_Z> BZ;
  for (const auto& b : B) BZ.push_back(primitive_integer_dense(b));
  for (const auto& f : F)  // (a)
    if (!reduces_to_zero(f, BZ, L)) return Groebner_check::ideal_not_contained;
  for (std::size_t k = 0; k + 1 < B.size(); ++k) {  // (b)
    const Lex_monomial a = L[k], b = L[k + 1];
    if (std::min(a.first, b.first) == 0 && std::min(a.second, b.second) == 0) continue;
    if (!reduces_to_zero(integer_s_polynomial(BZ[k], BZ[k + 1]), BZ, L)) return Groebner_check::not_a_groebner_basis;
  }
  if (!dim.available()) return Groebner_check::dimension_unknown;  // (c)
  if (dim.equals(count)) return Groebner_check::certified;
  return dim.equality ? Groebner_check::dimension_mismatch : Groebner_check::dimension_unknown;
}

/// The coefficients of a reduced zero-dimensional basis mod p on its standard monomials: element k contributes its
/// coefficients of the standard monomials below LM(k), in increasing order (plain residues).
inline std::vector<u64> basis_values(const std::vector<Dense_lex_polynomial<u64>>& G, const std::vector<Lex_monomial>& S,
                                     const Montgomery_modulus& M) {
  std::vector<u64> v;
  for (const auto& g : G) {
    const Lex_monomial lm = g.leading_monomial();
    for (const auto& m : S) {
      if (!(m < lm)) break;
      const std::size_t j = std::size_t(m.first), i = std::size_t(m.second);
      v.push_back(j < g.rows.size() && i < g.rows[j].size() ? M.from_montgomery(g.rows[j][i]) : 0);
    }
  }
  return v;
}

/// The basis with leading monomials L and the coefficients `values` (layout of basis_values).
inline std::vector<Dense_Q> basis_from_values(const std::vector<Lex_monomial>& L, const std::vector<Lex_monomial>& S,
                                              const std::vector<Rational>& values) {
  std::vector<Dense_Q> B;
  std::size_t at = 0;
  for (const auto& lm : L) {
    Dense_Q b;
    b.rows.resize(std::size_t(lm.first + 1));
    b.rows.back().resize(std::size_t(lm.second + 1), Rational(0));
    b.rows.back().back() = Rational(1);
    for (const auto& m : S) {
      if (!(m < lm)) break;
      auto& row = b.rows[std::size_t(m.first)];
      if (row.size() <= std::size_t(m.second)) row.resize(std::size_t(m.second + 1), Rational(0));
      row[std::size_t(m.second)] = values[at++];
    }
    normalize(b, Rational_field());
    B.push_back(std::move(b));
  }
  return B;
}

}  // namespace internal

/// Exact check (a), (b), (c) of a candidate reduced lex basis B (any order) of the ideal generated by F (two
/// equations for (c)). `certified` proves that B is the reduced lex basis of <F>.
template <class NT>
Groebner_check check_lex_groebner_basis(const std::vector<Polynomial_2<NT>>& F, std::vector<Lex_polynomial_2> B) {
  std::vector<internal::Dense_Z> FZ, T;
  for (const auto& f : F)
    if (!CGAL::is_zero(f)) FZ.push_back(internal::primitive_integer_dense(f));
  std::sort(B.begin(), B.end(), [](const Lex_polynomial_2& x, const Lex_polynomial_2& y) {
    return x.is_zero() || (!y.is_zero() && x.leading_monomial() < y.leading_monomial());
  });
  std::vector<internal::Dense_Q> BQ;
  for (const auto& b : B) BQ.push_back(internal::to_dense(b));
  internal::Quotient_dimension dim(FZ, T);
  return internal::check_basis(FZ, BQ, dim);
}

/// Reduced lexicographic (t > s) Groebner basis of <F> ⊂ Q[s,t], sorted by increasing leading monomial, computed
/// modulo word primes and certified over Q (see the comment above: (a), (b), (c)); never an unproved basis. When the
/// dimension count (c) is not available (common roots of the leading coefficients in both directions; for three or
/// more equations, a count below the resultant bound) or no candidate is certified within `max_primes` primes, the
/// exact rational Buchberger algorithm `lex_groebner_basis` is used within `exact_budget` (Error beyond it;
/// exact_budget = 0: Error at once). `certificate` (optional) tells how.
template <class NT>
std::vector<Lex_polynomial_2> modular_lex_groebner_basis(const std::vector<Polynomial_2<NT>>& F,
                                                         Groebner_certificate* certificate = nullptr,
                                                         std::size_t exact_budget = 1000000,
                                                         std::size_t max_primes = 2000) {
  using namespace internal;
  Groebner_certificate local;
  Groebner_certificate& cert = certificate ? *certificate : local;
  cert = Groebner_certificate();
  std::vector<Dense_Z> FZ, T;
  for (const auto& f : F)
    if (!CGAL::is_zero(f)) FZ.push_back(primitive_integer_dense(f));
  Quotient_dimension dim(FZ, T);
  auto exact = [&]() {
    cert.exact_fallback = true;
    std::vector<Lex_polynomial_2> L;
    for (const auto& f : F) L.push_back(Lex_polynomial_2(f));
    std::vector<Lex_polynomial_2> B = lex_groebner_basis(L, exact_budget);
    std::vector<Lex_monomial> lm;
    for (const auto& b : B) lm.push_back(b.leading_monomial());
    cert.standard_monomials = zero_dimensional(lm) ? int(standard_monomials(lm).size()) : -1;
    return B;
  };
  if (FZ.empty()) return {};
  if (!dim.available()) return exact();
  cert.eliminated = dim.direction;

  struct Group {
    std::vector<Lex_monomial> L, S;
    Incremental_chinese_remainder crt;
    std::size_t count = 0, next_try = 1, first_failure = 0;
    bool has_candidate = false;
    std::vector<Rational> candidate;
  };
  std::vector<Group> groups;
  std::vector<Dense_lex_polynomial<u64>> image, G;
  for (std::size_t k = 0; k < max_primes; ++k) {
    const u64 p = cached_word_prime(k);
    const Montgomery_modulus M(p);
    const Prime_field K(M);
    ++cert.primes;
    image.clear();
    bool bad = false;
    for (const auto& f : FZ) {
      Dense_lex_polynomial<u64> g;
      for (const auto& row : f.rows) {
        g.rows.emplace_back();
        for (const auto& x : row) g.rows.back().push_back(M.to_montgomery(x));
      }
      bad = bad || K.is_zero(g.leading_coefficient());  // p divides a leading coefficient
      normalize(g, K);
      image.push_back(std::move(g));
    }
    std::vector<Lex_monomial> L;
    if (!bad && reduced_groebner_basis(image, K, G))
      for (const auto& g : G) L.push_back(g.leading_monomial());
    if (bad || !zero_dimensional(L)) {
      ++cert.discarded_primes;
      continue;
    }
    std::size_t gi = 0;
    while (gi < groups.size() && groups[gi].L != L) ++gi;
    if (gi == groups.size()) {
      groups.emplace_back();
      groups.back().L = L;
      groups.back().S = standard_monomials(L);
    }
    Group& grp = groups[gi];
    const std::vector<u64> values = basis_values(G, grp.S, M);
    if (grp.crt.size() != values.size()) grp.crt = Incremental_chinese_remainder(values.size());
    grp.crt.add(p, values);
    ++grp.count;
    std::size_t best = 0;
    for (std::size_t b = 1; b < groups.size(); ++b)
      if (groups[b].count > groups[best].count) best = b;
    if (best != gi) continue;
    if (grp.has_candidate) {  // does the candidate agree with the new prime?
      bool agree = true;
      for (std::size_t v = 0; v < values.size() && agree; ++v) {
        const u64 d = M.to_montgomery(grp.candidate[v].denominator());
        agree = d != 0 && M.mul(M.to_montgomery(grp.candidate[v].numerator()), M.inverse(d)) == M.to_montgomery(values[v]);
      }
      grp.has_candidate = false;
      if (agree) {
        ++cert.certification_attempts;
        const std::vector<Dense_Q> B = basis_from_values(grp.L, grp.S, grp.candidate);
        int count = -1;
        const Groebner_check c = check_basis(FZ, B, dim, &count);

        if (c == Groebner_check::certified) {
          cert.standard_monomials = count;
          cert.dimension = dim.value;
          for (std::size_t b = 0; b < groups.size(); ++b)
            if (b != gi) cert.discarded_primes += groups[b].count;
          std::vector<Lex_polynomial_2> out;
          for (const auto& b : B) out.push_back(to_lex(b));
          return out;
        }
        if (c == Groebner_check::dimension_unknown) break;  // r >= 3 equations, bound not sharp: exact algorithm
        grp.next_try = grp.count * 2;  // a wrong candidate: wait for many more primes
      }
    }
    if (grp.count < grp.next_try) continue;
    // rational reconstruction, starting with the value that failed last time. The coefficients share most of
    // their denominators: each value u is multiplied by the lcm L of the denominators found so far, so that
    // Wang's Euclidean algorithm mostly stops after a step or two (u L = n/d, value n/(d L)).
    std::vector<Rational> cand(values.size());
    bool ok = true;
    Integer den_lcm(1), u;
    for (std::size_t v = 0; v < values.size() && ok; ++v) {
      const std::size_t w = (grp.first_failure + v) % values.size();
      u = grp.crt.symmetric(w) * den_lcm;
      ok = rational_reconstruction(u, grp.crt.product(), cand[w]);
      if (!ok) {
        grp.first_failure = w;
        break;
      }
      if (den_lcm != 1) cand[w] /= Rational(den_lcm);
      const Integer d = cand[w].denominator();
      if (d != 1) den_lcm *= CGAL::integral_division(d, CGAL::gcd(d, den_lcm));
    }
    if (ok) {
      grp.candidate = std::move(cand);
      grp.has_candidate = true;
    } else {
      grp.next_try = grp.count + std::max<std::size_t>(1, grp.count / 4);
    }
  }
  return exact();
}

/// The generator of the elimination ideal <F> ∩ Q[s] (outer variable t eliminated): the univariate element of
/// the reduced lex basis (certified multi-modular computation, modular_lex_groebner_basis), or 0 if the ideal has
/// positive dimension (a common component). `budget` bounds the exact fallback (Error beyond it).
template <class NT>
Polynomial_1<Rational> groebner_eliminant(const std::vector<Polynomial_2<NT>>& F, std::size_t budget = 1000000) {
  for (const auto& g : modular_lex_groebner_basis(F, nullptr, budget))
    if (g.is_univariate_in_s()) return g.to_univariate();
  return Polynomial_1<Rational>(0);
}

}  // namespace bezoutian

#endif  // BEZOUTIAN_ELIMINATION_GROEBNER_BIVARIATE_H

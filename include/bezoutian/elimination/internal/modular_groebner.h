// Lexicographic (t > s) Groebner bases of bivariate ideals over a coefficient field given as a policy object: the
// prime field Z/p (word primes in Montgomery form, for the multi-modular algorithm of Groebner_bivariate.h) and Q
// (for the exact certification of a reconstructed basis). Polynomials are dense: one row of s-coefficients per power
// of t. du-1989 §3.5 (Groebner bases, Buchberger's algorithm).
//
// Internal header: not part of the public API.
#ifndef BEZOUTIAN_ELIMINATION_INTERNAL_MODULAR_GROEBNER_H
#define BEZOUTIAN_ELIMINATION_INTERNAL_MODULAR_GROEBNER_H

#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/arithmetic/modular_arithmetic.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

/// Z/p, residues in Montgomery form.
struct Prime_field {
  using T = u64;
  const Montgomery_modulus* M;
  explicit Prime_field(const Montgomery_modulus& m) : M(&m) {}
  static bool is_zero(T a) { return a == 0; }
  T zero() const { return 0; }
  T one() const { return M->one(); }
  T mul(T a, T b) const { return M->mul(a, b); }
  T neg(T a) const { return M->neg(a); }
  T inverse(T a) const { return M->inverse(a); }
  void sub_mul(T& x, T c, T g) const { x = M->sub(x, M->mul(c, g)); }  // x -= c g
};

/// Q, CGAL::Gmpq.
struct Rational_field {
  using T = Rational;
  static bool is_zero(const T& a) { return CGAL::is_zero(a); }
  T zero() const { return T(0); }
  T one() const { return T(1); }
  T mul(const T& a, const T& b) const { return a * b; }
  T neg(const T& a) const { return -a; }
  T inverse(const T& a) const { return T(1) / a; }
  void sub_mul(T& x, const T& c, const T& g) const { x -= c * g; }
};

/// Exponents (of t, of s) of a monomial s^i t^j; std::pair's order is the lex order t > s.
using Lex_monomial = std::pair<int, int>;

/// Dense bivariate polynomial sum rows[j][i] s^i t^j. Normalized: the top row and every row's last entry are
/// nonzero (an empty row in between stands for a zero row); the zero polynomial has no rows.
template <class T>
struct Dense_lex_polynomial {
  std::vector<std::vector<T>> rows;
  bool is_zero() const { return rows.empty(); }
  Lex_monomial leading_monomial() const { return {int(rows.size()) - 1, int(rows.back().size()) - 1}; }
  const T& leading_coefficient() const { return rows.back().back(); }
};

template <class K>
void normalize(Dense_lex_polynomial<typename K::T>& f, const K& k) {
  (void)k;
  for (auto& row : f.rows)
    while (!row.empty() && K::is_zero(row.back())) row.pop_back();
  while (!f.rows.empty() && f.rows.back().empty()) f.rows.pop_back();
}

template <class K>
void make_monic(Dense_lex_polynomial<typename K::T>& f, const K& k) {
  if (f.is_zero()) return;
  const typename K::T c = k.inverse(f.leading_coefficient());
  for (auto& row : f.rows)
    for (auto& x : row)
      if (!K::is_zero(x)) x = k.mul(x, c);
}

inline bool monomial_divides(const Lex_monomial& a, const Lex_monomial& b) {
  return a.first <= b.first && a.second <= b.second;
}

/// f -= c s^di t^dj g.
template <class K>
void subtract_shifted(Dense_lex_polynomial<typename K::T>& f, const typename K::T& c, int dj, int di,
                      const Dense_lex_polynomial<typename K::T>& g, const K& k) {
  if (f.rows.size() < g.rows.size() + std::size_t(dj)) f.rows.resize(g.rows.size() + std::size_t(dj));
  for (std::size_t jj = 0; jj < g.rows.size(); ++jj) {
    const auto& gr = g.rows[jj];
    if (gr.empty()) continue;
    auto& fr = f.rows[jj + std::size_t(dj)];
    if (fr.size() < gr.size() + std::size_t(di)) fr.resize(gr.size() + std::size_t(di), k.zero());
    for (std::size_t ii = 0; ii < gr.size(); ++ii)
      if (!K::is_zero(gr[ii])) k.sub_mul(fr[ii + std::size_t(di)], c, gr[ii]);
  }
}

/// Full normal form of f modulo G (monic, nonzero): every term divisible by a leading monomial of G is reduced. One
/// sweep from the largest monomial down suffices, since subtracting c m g from f changes only monomials smaller than
/// the eliminated term m LM(g) (lex order is compatible with multiplication).
template <class K>
Dense_lex_polynomial<typename K::T> normal_form(Dense_lex_polynomial<typename K::T> f,
                                                const std::vector<Dense_lex_polynomial<typename K::T>>& G, const K& k) {
  std::vector<Lex_monomial> lm;
  for (const auto& g : G) lm.push_back(g.leading_monomial());
  for (int j = int(f.rows.size()) - 1; j >= 0; --j) {
    for (int i = int(f.rows[std::size_t(j)].size()) - 1; i >= 0; --i) {
      if (K::is_zero(f.rows[std::size_t(j)][std::size_t(i)])) continue;
      std::size_t d = 0;
      while (d < G.size() && !monomial_divides(lm[d], {j, i})) ++d;
      if (d == G.size()) continue;
      const typename K::T c = f.rows[std::size_t(j)][std::size_t(i)];
      subtract_shifted(f, c, j - lm[d].first, i - lm[d].second, G[d], k);
      f.rows[std::size_t(j)][std::size_t(i)] = k.zero();  // exact: G[d] is monic
    }
  }
  normalize(f, k);
  return f;
}

/// S-polynomial of monic a, b: the lcm-multiples' difference.
template <class K>
Dense_lex_polynomial<typename K::T> s_polynomial(const Dense_lex_polynomial<typename K::T>& a,
                                                 const Dense_lex_polynomial<typename K::T>& b, const K& k) {
  const Lex_monomial la = a.leading_monomial(), lb = b.leading_monomial();
  const Lex_monomial l{std::max(la.first, lb.first), std::max(la.second, lb.second)};
  Dense_lex_polynomial<typename K::T> S;
  subtract_shifted(S, k.neg(k.one()), l.first - la.first, l.second - la.second, a, k);
  subtract_shifted(S, k.one(), l.first - lb.first, l.second - lb.second, b, k);
  normalize(S, k);
  return S;
}

/// Reduced Groebner basis (lex, t > s) of the ideal generated by F over the field K, sorted by increasing leading
/// monomial. Buchberger's algorithm with Gebauer and Moeller's installation of the criteria (Becker and Weispfenning,
/// Groebner Bases, §5.5, algorithms UPDATE and GROEBNERNEW2): on adding h, the new pairs (h, g) are thinned by the
/// chain criterion and the coprime criterion, old pairs (g1, g2) with LM(h) | lcm strictly are dropped, and basis
/// elements whose leading monomial LM(h) divides leave the basis (their pairs stay). Pairs are taken smallest lcm
/// first (normal strategy). `budget` bounds the number of S-polynomials; false is returned beyond it.
template <class K>
bool reduced_groebner_basis(const std::vector<Dense_lex_polynomial<typename K::T>>& F, const K& k,
                            std::vector<Dense_lex_polynomial<typename K::T>>& out, std::size_t budget = 100000) {
  using Poly = Dense_lex_polynomial<typename K::T>;
  std::vector<Poly> pool;                              // every polynomial ever in the basis
  std::vector<Lex_monomial> lm;                        // their leading monomials
  std::vector<std::size_t> G;                          // the current basis (indices into pool)
  std::vector<std::pair<std::size_t, std::size_t>> B;  // pending pairs
  auto lcm = [&](std::size_t i, std::size_t j) {
    return Lex_monomial{std::max(lm[i].first, lm[j].first), std::max(lm[i].second, lm[j].second)};
  };
  auto coprime = [&](std::size_t i, std::size_t j) {
    return std::min(lm[i].first, lm[j].first) == 0 && std::min(lm[i].second, lm[j].second) == 0;
  };
  std::vector<Poly> basis;  // the current basis' polynomials, for normal forms
  auto current = [&]() {
    basis.clear();
    for (std::size_t g : G) basis.push_back(pool[g]);
    return basis;
  };
  auto update = [&](Poly p) {
    make_monic(p, k);
    const std::size_t h = pool.size();
    lm.push_back(p.leading_monomial());
    pool.push_back(std::move(p));
    std::vector<std::size_t> C = G, D;
    for (std::size_t c = 0; c < C.size(); ++c) {
      const std::size_t g1 = C[c];
      bool keep = coprime(h, g1);
      if (!keep) {
        keep = true;
        const Lex_monomial l1 = lcm(h, g1);
        for (std::size_t e = c + 1; e < C.size() && keep; ++e) keep = !monomial_divides(lcm(h, C[e]), l1);
        for (std::size_t e = 0; e < D.size() && keep; ++e) keep = !monomial_divides(lcm(h, D[e]), l1);
      }
      if (keep) D.push_back(g1);
    }
    std::vector<std::pair<std::size_t, std::size_t>> Bn;
    for (const auto& pr : B) {
      const Lex_monomial l = lcm(pr.first, pr.second);
      if (!monomial_divides(lm[h], l) || lcm(pr.first, h) == l || lcm(h, pr.second) == l) Bn.push_back(pr);
    }
    for (std::size_t g : D)
      if (!coprime(h, g)) Bn.push_back({g, h});
    B.swap(Bn);
    std::vector<std::size_t> Gn;
    for (std::size_t g : G)
      if (!monomial_divides(lm[h], lm[g])) Gn.push_back(g);
    Gn.push_back(h);
    G.swap(Gn);
  };
  for (const auto& f : F) {
    Poly g = normal_form(f, current(), k);
    if (!g.is_zero()) update(std::move(g));
  }
  while (!B.empty()) {
    std::size_t best = 0;
    for (std::size_t q = 1; q < B.size(); ++q)
      if (lcm(B[q].first, B[q].second) < lcm(B[best].first, B[best].second)) best = q;
    const auto pr = B[best];
    B.erase(B.begin() + std::ptrdiff_t(best));
    if (budget-- == 0) return false;
    Poly r = normal_form(s_polynomial(pool[pr.first], pool[pr.second], k), current(), k);
    if (!r.is_zero()) update(std::move(r));
  }
  std::vector<Poly> M;
  for (std::size_t g : G) M.push_back(pool[g]);
  // G is minimal (no leading monomial divisible by another's): each element is reduced by the others
  std::sort(M.begin(), M.end(),
            [](const Poly& x, const Poly& y) { return x.leading_monomial() < y.leading_monomial(); });
  out.clear();
  for (std::size_t i = 0; i < M.size(); ++i) {
    std::vector<Poly> others;
    for (std::size_t j = 0; j < M.size(); ++j)
      if (j != i) others.push_back(M[j]);
    out.push_back(normal_form(M[i], others, k));  // the leading term is not divisible by another's: it stays
  }
  return true;
}

/// The leading monomials of a basis sorted by increasing leading monomial, and whether they describe a
/// zero-dimensional ideal (a pure power of s and a pure power of t among them).
inline bool zero_dimensional(const std::vector<Lex_monomial>& L) {
  return !L.empty() && L.front().first == 0 && L.back().second == 0;
}

/// Standard monomials (not divisible by any leading monomial) of a zero-dimensional staircase L (sorted, minimal:
/// t-exponents increasing, s-exponents decreasing), in increasing lex order.
inline std::vector<Lex_monomial> standard_monomials(const std::vector<Lex_monomial>& L) {
  std::vector<Lex_monomial> S;
  if (!zero_dimensional(L)) return S;
  for (std::size_t k = 0; k < L.size(); ++k) {
    const int j_end = k + 1 < L.size() ? L[k + 1].first : L[k].first;
    for (int j = L[k].first; j < j_end; ++j)
      for (int i = 0; i < L[k].second; ++i) S.push_back({j, i});
  }
  return S;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ELIMINATION_INTERNAL_MODULAR_GROEBNER_H

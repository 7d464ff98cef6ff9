// Certified isolation of the real roots of a univariate polynomial, with
// exact multiplicities, on a closed interval [a,b] or on the whole real line.
//
// Algorithm: square-free factorization f = c prod g_i^(m_i) (a modular
// square-free certificate, else Yun's algorithm with certified multi-modular
// gcds, algebraic/internal/bernstein_descartes_gcd.h); for each factor, Descartes' rule of signs in the Bernstein
// basis on [a,b] with exact integer de Casteljau subdivision and a proved
// floating-point filter (algebraic/bernstein_descartes.h); rational roots are
// made exact (algebraic/internal/bernstein_descartes_support.h). See doc/algebraic_numbers.md.
#ifndef BEZOUTIAN_ALGEBRAIC_ROOT_ISOLATION_H
#define BEZOUTIAN_ALGEBRAIC_ROOT_ISOLATION_H

#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/algebraic/bernstein_descartes.h>
#include <bezoutian/algebraic/internal/bernstein_descartes_support.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <vector>

namespace bezoutian {

/// A real root and its multiplicity as a root of the input polynomial.
struct Isolated_root {
  Algebraic_real root;
  int multiplicity = 1;
};

/// Thrown when asked for the roots of the zero polynomial (every number is a root).
class Zero_polynomial_error : public Invalid_input {
 public:
  Zero_polynomial_error() : Invalid_input("bezoutian: the zero polynomial has every number as a root") {}
};

namespace internal {

inline void check_interval(const Rational& a, const Rational& b) {
  if (a > b) throw Invalid_input("bezoutian root isolation: empty interval (a > b)");
}

// h <- h / (q x - p), an exact division in Z[x] when p/q is a root of h.
inline void divide_by_linear_factor(Mpz_vector& h, const Rational& r) {
  mpz_srcptr p = mpq_numref(r.mpq()), q = mpq_denref(r.mpq());
  const int n = static_cast<int>(h.size()) - 1;
  // (q x - p) sum s_i x^i: h_n = q s_(n-1), h_i = q s_(i-1) - p s_i, h_0 = -p s_0
  Mpz_vector s(n);
  mpz_divexact(s[n - 1].get(), h[n].get(), q);
  Mpz t;
  for (int i = n - 1; i >= 1; --i) {
    mpz_mul(t.get(), p, s[i].get());
    mpz_add(t.get(), t.get(), h[i].get());
    mpz_divexact(s[i - 1].get(), t.get(), q);
  }
  h.swap(s);
}

// Roots of one canonical square-free factor g of degree >= 2 in [a,b]. The
// modular test proves most factors free of rational roots; otherwise each
// root is checked, and found rational roots are divided out of the tested
// polynomial so that the test can succeed for the remaining ones.
inline void make_roots(const Polynomial_1<Integer>& g, const std::shared_ptr<const Mpz_vector>& cp,
                       const std::vector<Rational_isolating_interval>& ivs, int multiplicity,
                       std::vector<Isolated_root>& out) {
  const Mpz_vector& c = *cp;
  Mpz_vector h;  // g without the rational roots found so far
  bool tested = false, no_rational = false;
  int found = 0, next_test = 1;  // re-run the modular test after 1, 2, 4, ... found roots
  for (const Rational_isolating_interval& iv : ivs) {
    if (!iv.exact) continue;
    if (h.empty()) h = c;
    divide_by_linear_factor(h, iv.lo);
  }
  std::vector<Algebraic_real> xs;
  for (const Rational_isolating_interval& iv : ivs)
    xs.push_back(iv.exact ? Algebraic_real(iv.lo) : Algebraic_real_access::from_interval(g, cp, iv.lo, iv.hi, iv.sign_lo));
  if (h.empty()) h = c;
  no_rational = h.size() < 3 ? h.size() < 2 : has_no_rational_root_modular(h);
  tested = true;
  if (!no_rational) {
    // Rational roots with small denominators first (cheap: a short refinement and one exact sign), so that the
    // modular test usually proves the remaining roots irrational without refining them to 1/lc^2.
    for (Algebraic_real& x : xs) {
      if (x.is_rational()) continue;
      Algebraic_real_access::try_small_rational(x, 32);
      if (x.is_rational()) {
        divide_by_linear_factor(h, x.rational_value());
        ++found;
      }
    }
    if (found > 0) no_rational = h.size() < 3 ? h.size() < 2 : has_no_rational_root_modular(h);
    next_test = 2 * found + 1;
    found = 0;
  }
  for (std::size_t k = 0; k < ivs.size(); ++k) {
    const Rational_isolating_interval& iv = ivs[k];
    if (iv.exact) {
      out.push_back({xs[k], multiplicity});
      continue;
    }
    Algebraic_real x = xs[k];
    if (x.is_rational()) {
      out.push_back({x, multiplicity});
      continue;
    }
    if (!tested) {
      no_rational = h.size() < 3 ? h.size() < 2 : has_no_rational_root_modular(h);
      tested = true;
    }
    if (!no_rational) {
      Algebraic_real_access::resolve_rationality(x, true);
      if (x.is_rational()) {
        divide_by_linear_factor(h, x.rational_value());
        if (++found >= next_test) {
          tested = false;
          next_test *= 2;
        }
      }
    }
    out.push_back({x, multiplicity});
  }
}

inline void isolate_factor(const Polynomial_1<Integer>& g, int multiplicity, const Rational& a, const Rational& b,
                           std::vector<Isolated_root>& out) {
  const auto cp = std::make_shared<const Mpz_vector>(coefficients_of(g));
  make_roots(g, cp, isolate_square_free(*cp, a, b), multiplicity, out);
}

// Isolating intervals of all real roots of a square-free g of degree >= 2:
// the roots in [-1,1] directly, the others as x = 1/y for the roots y of the
// reversed polynomial y^n g(1/y) in [-1,0) and (0,1] (y = 0 is not a root:
// the reversed constant term is lc(g)). Both are well conditioned, unlike one
// Bernstein subdivision of the whole Fujiwara interval. An interval (0,h)
// of y maps to (1/h, 2^L) with the strict root bound 2^L.
inline std::vector<Rational_isolating_interval> isolate_square_free_on_line(const Mpz_vector& c) {
  std::vector<Rational_isolating_interval> out = isolate_square_free(c, Rational(-1), Rational(1));
  const Mpz_vector rc(c.rbegin(), c.rend());
  Rational B(1);
  bool have_bound = false;
  auto bound = [&]() -> const Rational& {
    if (!have_bound) {
      mpz_mul_2exp(mpq_numref(B.mpq()), mpq_numref(B.mpq()), static_cast<mp_bitcnt_t>(root_bound_exponent(c)));
      have_bound = true;
    }
    return B;
  };
  for (int side = 0; side < 2; ++side) {
    const Rational a = side == 0 ? Rational(-1) : Rational(0), b = side == 0 ? Rational(0) : Rational(1);
    for (const Rational_isolating_interval& iv : isolate_square_free(rc, a, b)) {
      Rational_isolating_interval x;
      if (iv.exact) {
        if (CGAL::abs(iv.lo) == Rational(1)) continue;  // x = +-1, found above
        x.lo = x.hi = Rational(1) / iv.lo;
        x.exact = true;
      } else {  // y in (l,h) with l,h of one sign <=> x in (1/h, 1/l)
        x.lo = CGAL::is_zero(iv.hi) ? Rational(-bound()) : Rational(1) / iv.hi;
        x.hi = CGAL::is_zero(iv.lo) ? bound() : Rational(1) / iv.lo;
        x.sign_lo = sign_at(c, x.lo);
      }
      out.push_back(std::move(x));
    }
  }
  std::sort(out.begin(), out.end(), [](const Rational_isolating_interval& u, const Rational_isolating_interval& v) {
    return u.lo < v.lo;  // the intervals are disjoint
  });
  return out;
}

// All roots of the factors in [a,b] (a <= b), sorted.
inline std::vector<Isolated_root> isolate_on(const std::vector<std::pair<Polynomial_1<Integer>, int>>& factors,
                                             const Rational& a, const Rational& b) {
  std::vector<Isolated_root> out;
  for (const auto& fm : factors) {
    const Polynomial_1<Integer>& g = fm.first;
    if (a == b) {
      if (sign_at(coefficients_of(g), a) == 0) out.push_back({Algebraic_real(a), fm.second});
      continue;
    }
    if (g.degree() == 1) {
      const Rational r(-g[0], g[1]);
      if (a <= r && r <= b) out.push_back({Algebraic_real(r), fm.second});
      continue;
    }
    isolate_factor(g, fm.second, a, b, out);
  }
  // Roots of distinct factors are distinct (the factors are coprime), so the
  // comparisons terminate; each factor's list is already sorted.
  if (factors.size() > 1)
    std::stable_sort(out.begin(), out.end(),
                     [](const Isolated_root& x, const Isolated_root& y) { return x.root.compare(y.root) < 0; });
  return out;
}

inline std::vector<Isolated_root> isolate_all(const std::vector<std::pair<Polynomial_1<Integer>, int>>& factors) {
  std::vector<Isolated_root> out;
  for (const auto& fm : factors) {
    const Polynomial_1<Integer>& g = fm.first;
    if (g.degree() == 1) {
      out.push_back({Algebraic_real(Rational(-g[0], g[1])), fm.second});
      continue;
    }
    const auto cp = std::make_shared<const Mpz_vector>(coefficients_of(g));
    make_roots(g, cp, isolate_square_free_on_line(*cp), fm.second, out);
  }
  if (factors.size() > 1)
    std::stable_sort(out.begin(), out.end(),
                     [](const Isolated_root& x, const Isolated_root& y) { return x.root.compare(y.root) < 0; });
  return out;
}

}  // namespace internal

/// All distinct real roots of f in the closed interval [a,b] (a <= b), sorted
/// increasingly, each with its exact multiplicity as a root of f. Roots at a
/// or b are included; every rational root is returned as an exact rational.
/// A nonzero constant has no roots. Throws Zero_polynomial_error if f == 0
/// and Invalid_input if a > b.
inline std::vector<Isolated_root> isolate_real_roots(const Polynomial_1<Integer>& f, const Rational& a,
                                                     const Rational& b) {
  if (CGAL::is_zero(f)) throw Zero_polynomial_error();
  internal::check_interval(a, b);
  return internal::isolate_on(internal::square_free_factors(f), a, b);
}

/// Same for rational coefficients (the denominators are cleared first).
inline std::vector<Isolated_root> isolate_real_roots(const Polynomial_1<Rational>& f, const Rational& a,
                                                     const Rational& b) {
  return isolate_real_roots(internal::integer_multiple(f), a, b);
}

/// All distinct real roots of f, sorted, with multiplicities (the search
/// interval comes from Fujiwara's root bound). Throws Zero_polynomial_error if f == 0.
inline std::vector<Isolated_root> isolate_real_roots(const Polynomial_1<Integer>& f) {
  if (CGAL::is_zero(f)) throw Zero_polynomial_error();
  return internal::isolate_all(internal::square_free_factors(f));
}

inline std::vector<Isolated_root> isolate_real_roots(const Polynomial_1<Rational>& f) {
  return isolate_real_roots(internal::integer_multiple(f));
}

/// Number of distinct real roots of f in [a,b] (cheaper than isolating:
/// no rational-root detection, no sorting). Throws like isolate_real_roots.
inline std::size_t count_real_roots(const Polynomial_1<Integer>& f, const Rational& a, const Rational& b) {
  if (CGAL::is_zero(f)) throw Zero_polynomial_error();
  internal::check_interval(a, b);
  std::size_t n = 0;
  for (const auto& fm : internal::square_free_factors(f)) {
    const internal::Mpz_vector c = internal::coefficients_of(fm.first);
    if (a == b) n += internal::sign_at(c, a) == 0 ? 1 : 0;
    else n += internal::isolate_square_free(c, a, b).size();
  }
  return n;
}

inline std::size_t count_real_roots(const Polynomial_1<Rational>& f, const Rational& a, const Rational& b) {
  return count_real_roots(internal::integer_multiple(f), a, b);
}

/// Number of distinct real roots of f.
inline std::size_t count_real_roots(const Polynomial_1<Integer>& f) {
  if (CGAL::is_zero(f)) throw Zero_polynomial_error();
  std::size_t n = 0;
  for (const auto& fm : internal::square_free_factors(f))
    n += fm.first.degree() == 1 ? 1 : internal::isolate_square_free_on_line(internal::coefficients_of(fm.first)).size();
  return n;
}

inline std::size_t count_real_roots(const Polynomial_1<Rational>& f) {
  return count_real_roots(internal::integer_multiple(f));
}

/// Function object form of isolate_real_roots (CGAL style).
struct Isolate_real_roots {
  template <class NT>
  std::vector<Isolated_root> operator()(const Polynomial_1<NT>& f, const Rational& a, const Rational& b) const {
    return isolate_real_roots(f, a, b);
  }
  template <class NT>
  std::vector<Isolated_root> operator()(const Polynomial_1<NT>& f) const {
    return isolate_real_roots(f);
  }
};

}  // namespace bezoutian

#endif  // BEZOUTIAN_ALGEBRAIC_ROOT_ISOLATION_H

// The Bezout (Cayley) matrix of two univariate polynomials and what it gives:
// the resultant as its determinant, the gcd and the number of common roots
// from its rank and a bottom-up elimination (du-1989 §3.2.1, after
// Goldman-Sederberg-Anderson [Goldm84] and de Montaudouin-Tiller [Montau]),
// and the implicit equation of a rational plane curve (du-1989 eq. 4.1).
//
// Conventions (see also doc/classical_resultants.md):
//  - f = sum a_i t^i, g = sum b_i t^i, N = max(deg f, deg g) (the "Bezout
//    degree"); the shorter polynomial is padded with zero leading coefficients
//    (method (a) of du-1989 §3.2.1). The matrix is N x N.
//  - Entry (p, q), 0 <= p, q < N, is du-1989 eq. 3.4 / 3.5:
//        c_pq = sum_{k = max(0, p+q+1-N)}^{min(p,q)} (a_k b_{p+q+1-k} - a_{p+q+1-k} b_k),
//    which is the coefficient of t^p s^q in
//        (f(s) g(t) - f(t) g(s)) / (t - s).
//    (du-1989 eq. 3.1 divides f(t)g(s) - g(t)f(s) by t - s instead, which is
//    the negative; we follow the explicit formula 3.4.) Row p belongs to t^p,
//    column q to s^q; the matrix is symmetric.
//  - Sign: for m = deg f, n = deg g and N = max(m, n),
//        det C = (-1)^{N(N+1)/2} lc^{|m-n|} Res(f, g)            if m >= n, lc = lc(f),
//        det C = (-1)^{N(N+1)/2 + n(m+1)} lc^{|m-n|} Res(f, g)   if m <  n, lc = lc(g),
//    with Res the Sylvester resultant in CGAL's convention
//    (Res(f, g) = lc(f)^n prod_{f(x)=0} g(x)); `bezout_resultant` removes the
//    sign and the extraneous factor exactly and equals CGAL::resultant.
//    Note: du-1989 §3.2.1 names the extraneous factor of method (a) a_0^{m-n}
//    and that of method (b) (g multiplied by t^{m-n}) a_m^{m-n}; with the
//    seed's own indexing (a_m the leading coefficient) it is the other way
//    round, as the tests check.
#ifndef BEZOUTIAN_ELIMINATION_BEZOUT_MATRIX_H
#define BEZOUTIAN_ELIMINATION_BEZOUT_MATRIX_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/elimination/exact_linear_algebra.h>
#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace bezoutian {

namespace internal {

template <class NT>
NT bezout_coefficient(const Polynomial_1<NT>& f, int i) {
  return (i >= 0 && i <= f.degree()) ? f[i] : NT(0);
}

template <class NT>
int bezout_degree(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) {
  return std::max(CGAL::is_zero(f) ? 0 : f.degree(), CGAL::is_zero(g) ? 0 : g.degree());
}

} // namespace internal

/// The Bezout (Cayley) matrix of f and g, du-1989 eq. 3.4: the N x N symmetric
/// matrix, N = max(deg f, deg g), whose entry (p, q) is the coefficient of
/// t^p s^q in (f(s) g(t) - f(t) g(s)) / (t - s). NT is any commutative ring
/// (numbers, or polynomials in parameters). Two constants give the 0x0 matrix.
template <class NT>
std::vector<std::vector<NT>> bezout_matrix(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) {
  const int N = internal::bezout_degree(f, g);
  std::vector<std::vector<NT>> C(N, std::vector<NT>(N, NT(0)));
  for (int p = 0; p < N; ++p)
    for (int q = p; q < N; ++q) {  // symmetric: fill the upper triangle and mirror
      NT c(0);
      const int lo = std::max(0, p + q + 1 - N), hi = std::min(p, q);
      for (int k = lo; k <= hi; ++k) {
        const int j = p + q + 1 - k;
        c += internal::bezout_coefficient(f, k) * internal::bezout_coefficient(g, j) -
             internal::bezout_coefficient(f, j) * internal::bezout_coefficient(g, k);
      }
      C[p][q] = c;
      C[q][p] = c;
    }
  return C;
}

/// The resultant of f and g computed as the determinant of their Bezout
/// matrix (du-1989 §3.2.1), with the sign and, for unequal degrees, the
/// extraneous factor lc^{|deg f - deg g|} (lc the leading coefficient of the
/// polynomial of larger degree) removed by exact division. Equals CGAL's
/// Polynomial_traits_d::Resultant (Sylvester convention) exactly, also for
/// constants (Res(c, g) = c^{deg g}, Res of two nonzero constants = 1) and the
/// zero polynomial (Res = 0). NT must be an integral domain with exact
/// division (Integer, Rational, CGAL polynomials over them).
template <class NT>
NT bezout_resultant(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) {
  if (CGAL::is_zero(f) || CGAL::is_zero(g)) return NT(0);
  const int m = f.degree(), n = g.degree(), N = std::max(m, n);
  NT D = internal::exact_determinant(bezout_matrix(f, g));
  long sign_exponent = long(N) * (N + 1) / 2;
  if (m > n) D = CGAL::integral_division(D, CGAL::ipower(f.lcoeff(), m - n));
  if (m < n) {
    D = CGAL::integral_division(D, CGAL::ipower(g.lcoeff(), n - m));
    sign_exponent += long(n) * (m + 1);
  }
  return (sign_exponent % 2 == 0) ? D : NT(-D);
}

/// What the Bezout matrix says about the common roots of f and g.
template <class NT>
struct Bezout_gcd_result {
  /// N = max(deg f, deg g), the size of the Bezout matrix.
  std::size_t matrix_size = 0;
  /// Rank of the Bezout matrix over the fraction field of NT; equals N - deg gcd(f, g).
  std::size_t rank = 0;
  /// deg gcd(f, g) = N - rank: the number of common roots counted with multiplicity.
  std::size_t gcd_degree = 0;
  /// A gcd of f and g over the fraction field of NT, made canonical with
  /// CGAL::canonicalize (primitive with positive leading coefficient over
  /// Integer, monic over Rational).
  Polynomial_1<NT> gcd;
};

/// The gcd of f and g by bottom-up elimination on their Bezout matrix
/// (Goldman-Sederberg-Anderson, du-1989 §3.2.1, eq. 3.6).
///
/// Reason: with h = gcd(f, g), f = h f1, g = h g1, the Bezoutian factors as
/// h(t) h(s) Bez(f1, g1)(t, s) with Bez(f1, g1) nonsingular, so the rows of the
/// Bezout matrix (read as polynomials in s) span exactly h * (polynomials of
/// degree < N - deg h): the rank is N - deg h and the row-space element of
/// least degree is h itself. Elimination proceeds from the last column
/// (highest power) down, choosing as pivot the lowest unused row with a
/// nonzero entry (the seed starts from c_{N-1,N-1} and walks up; row
/// pivoting is needed because c_{N-1,N-1} can vanish without common roots, e.g.
/// f = t^2 + 1, g = t^2 + 2). The last pivot row, cleared of all higher
/// columns, is a multiple of h. Fraction-free (Bareiss) updates keep every
/// division exact. Throws Invalid_input if f and g are both zero.
template <class NT>
Bezout_gcd_result<NT> bezout_gcd(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) {
  if (CGAL::is_zero(f) && CGAL::is_zero(g)) throw Invalid_input("bezout_gcd: both polynomials are zero");
  std::vector<std::vector<NT>> A = bezout_matrix(f, g);
  const int N = int(A.size());
  Bezout_gcd_result<NT> result;
  result.matrix_size = std::size_t(N);
  std::vector<bool> used(N, false);
  NT previous(1);
  int last_row = -1, last_column = -1;
  for (int k = N - 1; k >= 0; --k) {
    int p = -1;
    for (int i = N - 1; i >= 0; --i)
      if (!used[i] && !CGAL::is_zero(A[i][k])) {
        p = i;
        break;
      }
    if (p < 0) continue;
    used[p] = true;
    for (int i = 0; i < N; ++i) {
      if (used[i]) continue;
      for (int j = 0; j < N; ++j)
        if (j != k) A[i][j] = CGAL::integral_division(A[p][k] * A[i][j] - A[i][k] * A[p][j], previous);
      A[i][k] = NT(0);
    }
    previous = A[p][k];
    ++result.rank;
    last_row = p;
    last_column = k;
  }
  if (last_row < 0) {
    // Zero matrix: f and g are proportional (or one is zero), gcd = the one of degree N.
    const bool f_has_degree_N = !CGAL::is_zero(f) && f.degree() == N;
    result.gcd = CGAL::canonicalize(f_has_degree_N ? f : g);
  } else {
    std::vector<NT> h(A[last_row].begin(), A[last_row].begin() + (last_column + 1));
    result.gcd = CGAL::canonicalize(Polynomial_1<NT>(h.begin(), h.end()));
  }
  result.gcd_degree = std::size_t(CGAL::is_zero(result.gcd) ? 0 : result.gcd.degree());
  return result;
}

/// Rank of the Bezout matrix of f and g over the fraction field of NT.
template <class NT>
std::size_t bezout_rank(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) {
  return internal::fraction_free_rank(bezout_matrix(f, g));
}

/// Number of common roots of f and g (over the algebraic closure, counted with
/// multiplicity) = deg gcd(f, g) = max(deg f, deg g) - rank of the Bezout
/// matrix (de Montaudouin-Tiller, du-1989 §3.2.1).
template <class NT>
std::size_t number_of_common_roots(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) {
  if (CGAL::is_zero(f) && CGAL::is_zero(g)) throw Invalid_input("number_of_common_roots: both polynomials are zero");
  return std::size_t(internal::bezout_degree(f, g)) - bezout_rank(f, g);
}

/// Bezout matrix of X(t) - x W(t) and Y(t) - y W(t) for the rational plane
/// curve t -> (X(t)/W(t), Y(t)/W(t)), in the vector form of du-1989 eq. 4.1:
///     c_pq = sum_{k = max(0, p+q+1-N)}^{min(p,q)} | p, v_k, v_{p+1+q-k} |,
/// p = (x, y, 1), v_k = (a_k, b_k, d_k) the coefficients of t^k in X, Y, W,
/// N = max(deg X, deg Y, deg W). The entries are polynomials of total degree
/// <= 1 in x (variable 0) and y (variable 1); the matrix equals
/// bezout_matrix(X - x W, Y - y W) computed over Polynomial_2<NT>.
template <class NT>
std::vector<std::vector<Polynomial_2<NT>>> rational_curve_bezout_matrix(const Polynomial_1<NT>& X,
                                                                        const Polynomial_1<NT>& Y,
                                                                        const Polynomial_1<NT>& W) {
  using P2 = Polynomial_2<NT>;
  if (CGAL::is_zero(W)) throw Invalid_input("rational_curve_bezout_matrix: the weight polynomial W is zero");
  int N = 0;
  for (const Polynomial_1<NT>* c : {&X, &Y, &W})
    if (!CGAL::is_zero(*c)) N = std::max(N, c->degree());
  if (N == 0) throw Invalid_input("rational_curve_bezout_matrix: the curve is constant (all components of degree 0)");
  const P2 x = CGAL::shift(P2(1), 1, 0), y = CGAL::shift(P2(1), 1, 1);
  auto a = [&](int i) { return internal::bezout_coefficient(X, i); };
  auto b = [&](int i) { return internal::bezout_coefficient(Y, i); };
  auto d = [&](int i) { return internal::bezout_coefficient(W, i); };
  // |p, v_i, v_j| expanded along its first column p = (x, y, 1).
  auto bracket = [&](int i, int j) {
    return x * P2(b(i) * d(j) - b(j) * d(i)) - y * P2(a(i) * d(j) - a(j) * d(i)) + P2(a(i) * b(j) - a(j) * b(i));
  };
  std::vector<std::vector<P2>> C(N, std::vector<P2>(N, P2(0)));
  for (int p = 0; p < N; ++p)
    for (int q = p; q < N; ++q) {
      P2 c(0);
      for (int k = std::max(0, p + q + 1 - N); k <= std::min(p, q); ++k) c += bracket(k, p + q + 1 - k);
      C[p][q] = c;
      C[q][p] = c;
    }
  return C;
}

/// The implicit equation det Bez_t(X - x W, Y - y W) of the rational plane
/// curve (X/W, Y/W) (du-1989 eq. 4.1, §4.1): a polynomial in x (variable 0)
/// and y (variable 1) of total degree <= N = max(deg X, deg Y, deg W), equal to
/// (-1)^{N(N+1)/2} Res_t(X - x W, Y - y W) when X - x W and Y - y W both have
/// degree N in t. It vanishes on the curve; for a proper parametrization
/// without base points it is irreducible of degree N.
template <class NT>
Polynomial_2<NT> bezout_implicit_equation(const Polynomial_1<NT>& X, const Polynomial_1<NT>& Y,
                                          const Polynomial_1<NT>& W) {
  return internal::exact_determinant(rational_curve_bezout_matrix(X, Y, W));
}

/// Functor forms.
struct Bezout_matrix {
  template <class NT>
  std::vector<std::vector<NT>> operator()(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) const {
    return bezout_matrix(f, g);
  }
};
struct Bezout_resultant {
  template <class NT>
  NT operator()(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) const {
    return bezout_resultant(f, g);
  }
};
struct Bezout_gcd {
  template <class NT>
  Bezout_gcd_result<NT> operator()(const Polynomial_1<NT>& f, const Polynomial_1<NT>& g) const {
    return bezout_gcd(f, g);
  }
};
struct Bezout_implicit_equation {
  template <class NT>
  Polynomial_2<NT> operator()(const Polynomial_1<NT>& X, const Polynomial_1<NT>& Y, const Polynomial_1<NT>& W) const {
    return bezout_implicit_equation(X, Y, W);
  }
};

} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_BEZOUT_MATRIX_H

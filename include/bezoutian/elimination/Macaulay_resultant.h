// Macaulay's resultant of n homogeneous polynomials in n variables and the
// u-resultant (du-1989 §3.2.3, §3.2.4 and Appendix A, after Macaulay [Mac02]).
//
// Construction (du-1989 eq. 3.33-3.37, 3.50-3.52): for forms F_1..F_n of
// degrees d_1..d_n >= 1 in x_1..x_n, let d = 1 + sum (d_i - 1) and list the
// monomials of degree d. A monomial x^a belongs to the first i with
// a_i >= d_i (it is "reduced" in x_1..x_{i-1}); its row holds the coefficients
// of (x^a / x_i^{d_i}) F_i. This is the matrix M = M_n(n, d) of the seed, with
// one convention fixed here: rows are listed in the same order as the columns
// (row and column of x^a share an index), so M is the identity for
// F_i = x_i^{d_i}. Columns (and rows) are in lexicographically descending
// order, x_1 most significant (x_1^d first), as in du-1989 eq. 3.48.
//
// The extraneous minor Delta M (du-1989 eq. 3.49-3.52) keeps the rows and
// columns of the monomials divisible by at least two of the x_i^{d_i}; it does
// not involve the coefficients of F_n (seed Appendix A). Macaulay's theorem:
//     Res(F_1, ..., F_n) = det M / det Delta M,
// normalized by Res(x_1^{d_1}, ..., x_n^{d_n}) = 1, homogeneous of degree
// prod_{j != i} d_j in the coefficients of F_i, zero iff the F_i have a common
// projective zero (du-1989 Theorem 3.5). For n = 2 it is the Sylvester
// resultant of binary forms; for linear forms it is the determinant of the
// coefficient matrix.
//
// When det Delta M vanishes for the given coefficients (it is a nonzero
// polynomial in the generic coefficients, but can vanish on special input),
// the resultant is recovered exactly through Canny's generalized
// characteristic polynomial: replacing F_i by F_i + lambda x_i^{d_i} turns M
// into M + lambda I and Delta M into Delta M + lambda I (rows and columns are
// listed alike), Macaulay's identity holds over NT[lambda], the quotient
// det(M + lambda I) / det(Delta M + lambda I) is Res(F + lambda X), and its
// value at lambda = 0 is Res(F).
#ifndef BEZOUTIAN_ELIMINATION_MACAULAY_RESULTANT_H
#define BEZOUTIAN_ELIMINATION_MACAULAY_RESULTANT_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/elimination/exact_linear_algebra.h>
#include <bezoutian/arithmetic/number_types.h>

#include <CGAL/Exponent_vector.h>
#include <CGAL/Polynomial_traits_d.h>
#include <CGAL/Polynomial_type_generator.h>

#include <cstddef>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {

/// A homogeneous polynomial (form) of a fixed degree in a fixed number of
/// variables with coefficients in a commutative ring R (numbers, or
/// polynomials in parameters such as the u of the u-resultant).
template <class R>
class Homogeneous_form {
 public:
  using Coefficient = R;
  using Exponent = std::vector<int>;

  Homogeneous_form(std::size_t number_of_variables, int degree) : n_(number_of_variables), degree_(degree) {
    if (number_of_variables == 0) throw Invalid_input("Homogeneous_form: no variables");
    if (degree < 0) throw Invalid_input("Homogeneous_form: negative degree");
  }

  std::size_t number_of_variables() const { return n_; }
  int degree() const { return degree_; }
  const std::map<Exponent, R>& terms() const { return terms_; }

  /// Adds c x^e; throws Invalid_input if e has the wrong length, a negative
  /// entry, or a total degree other than degree().
  void add_term(const Exponent& e, const R& c) {
    if (e.size() != n_) throw Invalid_input("Homogeneous_form: exponent vector of the wrong length");
    int s = 0;
    for (int a : e) {
      if (a < 0) throw Invalid_input("Homogeneous_form: negative exponent");
      s += a;
    }
    if (s != degree_) throw Invalid_input("Homogeneous_form: term of degree " + std::to_string(s) +
                                          " in a form of degree " + std::to_string(degree_));
    if (CGAL::is_zero(c)) return;
    auto it = terms_.find(e);
    if (it == terms_.end()) {
      terms_.emplace(e, c);
    } else {
      it->second += c;
      if (CGAL::is_zero(it->second)) terms_.erase(it);
    }
  }

  /// Coefficient of x^e (0 when absent).
  R coefficient(const Exponent& e) const {
    auto it = terms_.find(e);
    return it == terms_.end() ? R(0) : it->second;
  }

 private:
  std::size_t n_;
  int degree_;
  std::map<Exponent, R> terms_;
};

/// The form of a CGAL polynomial P in d = Polynomial_traits_d<P>::d variables
/// (variable i = CGAL index i). degree < 0 means the total degree of P (then P
/// must be nonzero). Throws Invalid_input if P is not homogeneous of that degree.
template <class PolynomialD>
Homogeneous_form<typename CGAL::Polynomial_traits_d<PolynomialD>::Innermost_coefficient_type> homogeneous_form(
    const PolynomialD& P, int degree = -1) {
  using PT = CGAL::Polynomial_traits_d<PolynomialD>;
  using IC = typename PT::Innermost_coefficient_type;
  std::vector<std::pair<CGAL::Exponent_vector, IC>> terms;
  typename PT::Monomial_representation()(P, std::back_inserter(terms));
  if (degree < 0) {
    if (CGAL::is_zero(P)) throw Invalid_input("homogeneous_form: the zero polynomial needs an explicit degree");
    degree = typename PT::Total_degree()(P);
  }
  Homogeneous_form<IC> F(std::size_t(PT::d), degree);
  for (const auto& t : terms) {
    if (CGAL::is_zero(t.second)) continue;
    std::vector<int> e(std::size_t(PT::d));
    for (int i = 0; i < PT::d; ++i) e[i] = t.first[i];
    F.add_term(e, t.second);  // throws if the degree differs: not homogeneous
  }
  return F;
}

/// All exponent vectors of total degree d in n variables, lexicographically
/// descending (x_1^d first, x_n^d last).
inline std::vector<std::vector<int>> monomials_of_degree(std::size_t n, int d) {
  std::vector<std::vector<int>> out;
  std::vector<int> e(n, 0);
  // Recursive fill: position i takes every value from the remaining degree down to 0.
  struct Filler {
    static void fill(std::vector<std::vector<int>>& out, std::vector<int>& e, std::size_t i, int remaining) {
      if (i + 1 == e.size()) {
        e[i] = remaining;
        out.push_back(e);
        return;
      }
      for (int a = remaining; a >= 0; --a) {
        e[i] = a;
        fill(out, e, i + 1, remaining - a);
      }
    }
  };
  if (n > 0 && d >= 0) Filler::fill(out, e, 0, d);
  return out;
}

/// The Macaulay matrix M of F_1..F_n and its labels (du-1989 §3.2.3).
template <class R>
struct Macaulay_matrix {
  /// d = 1 + sum (d_i - 1).
  int degree = 0;
  /// Monomials of degree d labelling the columns and, in the same order, the rows.
  std::vector<std::vector<int>> monomials;
  /// row_polynomial[r] = i (0-based) when row r holds (x^a / x_i^{d_i}) F_i.
  std::vector<std::size_t> row_polynomial;
  /// The square matrix (entry [r][c] = coefficient of monomial c in row r's polynomial).
  std::vector<std::vector<R>> matrix;
  /// Indices of the monomials divisible by at least two x_i^{d_i}: the rows
  /// and columns of the extraneous minor Delta M (du-1989 eq. 3.50-3.52).
  std::vector<std::size_t> extraneous_indices;

  /// The extraneous minor Delta M (empty when there is none; det = 1).
  std::vector<std::vector<R>> extraneous_minor() const {
    std::vector<std::vector<R>> D;
    D.reserve(extraneous_indices.size());
    for (std::size_t r : extraneous_indices) {
      std::vector<R> row;
      row.reserve(extraneous_indices.size());
      for (std::size_t c : extraneous_indices) row.push_back(matrix[r][c]);
      D.push_back(std::move(row));
    }
    return D;
  }
};

namespace internal {

template <class R>
void check_square_system(const std::vector<Homogeneous_form<R>>& F, const char* who) {
  if (F.empty()) throw Invalid_input(std::string(who) + ": no polynomials");
  for (const auto& f : F) {
    if (f.number_of_variables() != F.size())
      throw Invalid_input(std::string(who) + ": needs n forms in n variables");
    if (f.degree() < 1) throw Invalid_input(std::string(who) + ": every form must have degree >= 1");
  }
}

} // namespace internal

/// Macaulay matrix of n forms F_1..F_n in n variables, all of degree >= 1.
template <class R>
Macaulay_matrix<R> macaulay_matrix(const std::vector<Homogeneous_form<R>>& F) {
  internal::check_square_system(F, "macaulay_matrix");
  const std::size_t n = F.size();
  Macaulay_matrix<R> M;
  M.degree = 1;
  for (const auto& f : F) M.degree += f.degree() - 1;
  M.monomials = monomials_of_degree(n, M.degree);
  const std::size_t N = M.monomials.size();
  std::map<std::vector<int>, std::size_t> column;
  for (std::size_t c = 0; c < N; ++c) column.emplace(M.monomials[c], c);
  M.matrix.assign(N, std::vector<R>(N, R(0)));
  M.row_polynomial.resize(N);
  for (std::size_t r = 0; r < N; ++r) {
    const std::vector<int>& a = M.monomials[r];
    std::size_t first = n, count = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (a[i] >= F[i].degree()) {
        if (first == n) first = i;
        ++count;
      }
    // first < n always: sum a_i = d > sum (d_i - 1) forces some a_i >= d_i.
    if (count >= 2) M.extraneous_indices.push_back(r);
    M.row_polynomial[r] = first;
    std::vector<int> shift = a;
    shift[first] -= F[first].degree();
    for (const auto& t : F[first].terms()) {
      std::vector<int> e = t.first;
      for (std::size_t i = 0; i < n; ++i) e[i] += shift[i];
      M.matrix[r][column.at(e)] = t.second;
    }
  }
  return M;
}

/// Macaulay's resultant Res(F_1, ..., F_n) = det M / det Delta M, exact, with
/// the generalized characteristic polynomial when det Delta M vanishes (see
/// the header comment). R must be an integral domain with exact division
/// (Integer, Rational, CGAL polynomials over them). Throws Invalid_input on a
/// malformed system (not n forms in n variables, a form of degree 0).
template <class R>
R macaulay_resultant(const std::vector<Homogeneous_form<R>>& F) {
  const Macaulay_matrix<R> M = macaulay_matrix(F);
  const std::vector<std::vector<R>> D = M.extraneous_minor();
  const R det_D = internal::exact_determinant(D);
  if (!CGAL::is_zero(det_D)) return CGAL::integral_division(internal::exact_determinant(M.matrix), det_D);
  // Generalized characteristic polynomial: M + lambda I and Delta M + lambda I.
  using RL = Polynomial_1<R>;
  const RL lambda = CGAL::shift(RL(1), 1);
  auto add_lambda = [&](const std::vector<std::vector<R>>& A) {
    std::vector<std::vector<RL>> B(A.size(), std::vector<RL>(A.size(), RL(0)));
    for (std::size_t i = 0; i < A.size(); ++i)
      for (std::size_t j = 0; j < A.size(); ++j) B[i][j] = RL(A[i][j]) + (i == j ? lambda : RL(0));
    return B;
  };
  const RL numerator = internal::exact_determinant(add_lambda(M.matrix));
  const RL denominator = internal::exact_determinant(add_lambda(D));
  const RL quotient = CGAL::integral_division(numerator, denominator);
  return quotient.evaluate(R(0));
}

/// Macaulay's resultant of n CGAL polynomials in n variables (each homogeneous
/// of degree >= 1); returns an element of their innermost coefficient type.
template <class PolynomialD>
typename CGAL::Polynomial_traits_d<PolynomialD>::Innermost_coefficient_type macaulay_resultant(
    const std::vector<PolynomialD>& F) {
  using IC = typename CGAL::Polynomial_traits_d<PolynomialD>::Innermost_coefficient_type;
  std::vector<Homogeneous_form<IC>> G;
  G.reserve(F.size());
  for (const auto& f : F) G.push_back(homogeneous_form(f));
  return macaulay_resultant(G);
}

/// The u-resultant of n-1 forms F_1..F_{n-1} in n variables (du-1989 §3.2.4,
/// van der Waerden's form): Res(F_1, ..., F_{n-1}, u_1 x_1 + ... + u_n x_n),
/// a form of degree D = d_1 ... d_{n-1} in u, returned as a polynomial of the
/// same type as the input, its variable i standing for u_{i+1}. When the
/// system has finitely many projective zeros s^(k) it factors as
/// c prod_k (u . s^(k)) (with multiplicities), so the linear factors give the
/// common zeros (Theorem 3.6); it vanishes identically iff there are
/// infinitely many. The linear form is placed last, so Delta M does not involve
/// u. Computed with u_n = 1 (a polynomial in n-1 variables, for n = 3 the fast
/// bivariate determinant) and rehomogenized to degree D.
template <class PolynomialD>
PolynomialD u_resultant(const std::vector<PolynomialD>& F) {
  using PT = CGAL::Polynomial_traits_d<PolynomialD>;
  using IC = typename PT::Innermost_coefficient_type;
  constexpr int n = PT::d;
  static_assert(n >= 2, "u_resultant: needs at least two variables");
  using RU = typename CGAL::Polynomial_type_generator<IC, n - 1>::Type;  // polynomials in u_1..u_{n-1}
  using RPT = CGAL::Polynomial_traits_d<RU>;
  if (F.size() != std::size_t(n - 1)) throw Invalid_input("u_resultant: needs n-1 forms in n variables");
  std::vector<Homogeneous_form<RU>> G;
  long D = 1;
  for (const auto& f : F) {
    const Homogeneous_form<IC> h = homogeneous_form(f);
    if (h.degree() < 1) throw Invalid_input("u_resultant: every form must have degree >= 1");
    D *= h.degree();
    Homogeneous_form<RU> g(std::size_t(n), h.degree());
    for (const auto& t : h.terms()) g.add_term(t.first, RU(t.second));
    G.push_back(std::move(g));
  }
  Homogeneous_form<RU> L(std::size_t(n), 1);
  for (int i = 0; i < n; ++i) {
    std::vector<int> e(std::size_t(n), 0);
    e[i] = 1;
    L.add_term(e, i + 1 < n ? CGAL::shift(RU(1), 1, i) : RU(1));
  }
  G.push_back(std::move(L));
  const RU r = macaulay_resultant(G);
  // Rehomogenize: u^b -> u^b u_n^{D - |b|}.
  std::vector<std::pair<CGAL::Exponent_vector, IC>> terms, out;
  typename RPT::Monomial_representation()(r, std::back_inserter(terms));
  for (const auto& t : terms) {
    if (CGAL::is_zero(t.second)) continue;
    std::vector<int> e(std::size_t(n), 0);
    long s = 0;
    for (int i = 0; i + 1 < n; ++i) {
      e[i] = t.first[i];
      s += e[i];
    }
    if (s > D) throw Error("u_resultant: internal error, degree exceeds d_1...d_{n-1}");
    e[n - 1] = int(D - s);
    out.emplace_back(CGAL::Exponent_vector(e.begin(), e.end()), t.second);
  }
  return typename PT::Construct_polynomial()(out.begin(), out.end());
}

/// Functor forms.
struct Macaulay_resultant {
  template <class R>
  R operator()(const std::vector<Homogeneous_form<R>>& F) const {
    return macaulay_resultant(F);
  }
  template <class PolynomialD>
  typename CGAL::Polynomial_traits_d<PolynomialD>::Innermost_coefficient_type operator()(
      const std::vector<PolynomialD>& F) const {
    return macaulay_resultant(F);
  }
};
struct U_resultant {
  template <class PolynomialD>
  PolynomialD operator()(const std::vector<PolynomialD>& F) const {
    return u_resultant(F);
  }
};

} // namespace bezoutian

#endif // BEZOUTIAN_ELIMINATION_MACAULAY_RESULTANT_H

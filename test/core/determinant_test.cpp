// Tests of the exact polynomial-matrix determinant engine and of the
// normalization of polynomials. Reference values come from outside the code
// under test: CGAL's own (Berkowitz) determinant, CGAL's resultant (as the
// determinant of the Sylvester matrix), closed forms (triangular, Vandermonde,
// product of factors) and multiplicativity of det; for the square-free part,
// exact identities checked with CGAL's own division and gcd.
#include "test_support.h"

#include <bezoutian/elimination/Implicit_equation.h>
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#include <bezoutian/algebraic/Polynomial_normalization.h>
#include <bezoutian/io/Geometry_document.h>

#include <CGAL/Polynomial/determinant.h>

#include <catch2/catch.hpp>

#include <random>
#include <thread>
#include <vector>

namespace {

using bezoutian::Integer;
using bezoutian::Rational;
using P1 = bezoutian::Polynomial_1<Integer>;
using P2 = bezoutian::Polynomial_2<Integer>;
using P1Q = bezoutian::Polynomial_1<Rational>;
using P2Q = bezoutian::Polynomial_2<Rational>;
template <class T> using Matrix = std::vector<std::vector<T>>;

const P1 u_var = P1(Integer(0), Integer(1));           // u
const P2 U = P2(u_var);                                 // u as a bivariate polynomial
const P2 V = P2(P1(Integer(0)), P1(Integer(1)));        // v

struct Random {
  std::mt19937_64 gen;
  explicit Random(unsigned seed) : gen(seed) {}
  long integer(long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(gen); }
  Integer big(int bits) { // uniform in (-2^bits, 2^bits)
    Integer x(0);
    for (int b = 0; b < bits; b += 30) x = x * Integer(1L << 30) + Integer(integer(0, (1L << 30) - 1));
    mpz_fdiv_r_2exp(x.mpz(), x.mpz(), bits);
    return integer(0, 1) ? x : Integer(-x);
  }
  P1 poly1(int deg, long c) {
    std::vector<Integer> v;
    for (int k = 0; k <= deg; ++k) v.push_back(Integer(integer(-c, c)));
    return P1(v.begin(), v.end());
  }
  P2 poly2(int du, int dv, long c) {
    std::vector<P1> v;
    for (int l = 0; l <= dv; ++l) v.push_back(poly1(du, c));
    return P2(v.begin(), v.end());
  }
  P2 poly2_big(int du, int dv, int bits) {
    std::vector<P1> rows;
    for (int l = 0; l <= dv; ++l) {
      std::vector<Integer> v;
      for (int k = 0; k <= du; ++k) v.push_back(big(bits));
      rows.emplace_back(v.begin(), v.end());
    }
    return P2(rows.begin(), rows.end());
  }
  P2Q poly2_rational(int du, int dv) {
    std::vector<P1Q> rows;
    for (int l = 0; l <= dv; ++l) {
      std::vector<Rational> v;
      for (int k = 0; k <= du; ++k) v.push_back(Rational(Integer(integer(-9, 9)), Integer(integer(1, 12))));
      rows.emplace_back(v.begin(), v.end());
    }
    return P2Q(rows.begin(), rows.end());
  }
};

// CGAL's generic determinant (CGAL/Polynomial/determinant.h) as a third opinion.
template <class NT> NT cgal_determinant(const Matrix<NT>& M) {
  const int n = int(M.size());
  if (n == 0) return NT(1);
  CGAL::internal::Simple_matrix<NT> S(n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) S[i][j] = M[i][j];
  return CGAL::internal::determinant(S);
}

template <class NT> Matrix<NT> multiply(const Matrix<NT>& A, const Matrix<NT>& B) {
  const std::size_t n = A.size();
  Matrix<NT> C(n, std::vector<NT>(n, NT(0)));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k) C[i][j] += A[i][k] * B[k][j];
  return C;
}

// Sylvester matrix of f, g (outer variable), entries are the coefficients.
template <class Poly> Matrix<typename Poly::NT> sylvester(const Poly& f, const Poly& g) {
  using C = typename Poly::NT;
  const int m = f.degree(), n = g.degree();
  Matrix<C> S(m + n, std::vector<C>(m + n, C(0)));
  for (int i = 0; i < n; ++i)
    for (int k = 0; k <= m; ++k) S[i][i + k] = f[m - k];
  for (int i = 0; i < m; ++i)
    for (int k = 0; k <= n; ++k) S[n + i][i + k] = g[n - k];
  return S;
}

} // namespace

TEST_CASE("determinant: random small univariate matrices agree with Berkowitz and CGAL", "[determinant]") {
  Random rnd(20260101);
  for (int trial = 0; trial < 25; ++trial) {
    const int n = int(rnd.integer(2, 6));
    Matrix<P1> M(n, std::vector<P1>(n));
    for (auto& row : M)
      for (auto& e : row) e = rnd.integer(0, 5) == 0 ? P1(0) : rnd.poly1(int(rnd.integer(0, 4)), 5);
    const P1 d = bezoutian::polynomial_matrix_determinant(M);
    CHECK(d == bezoutian::berkowitz_determinant(M));
    CHECK(d == cgal_determinant(M));
  }
}

TEST_CASE("determinant: random small bivariate matrices agree with Berkowitz and CGAL", "[determinant]") {
  Random rnd(20260102);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = int(rnd.integer(2, trial < 15 ? 5 : 6));
    Matrix<P2> M(n, std::vector<P2>(n));
    for (auto& row : M)
      for (auto& e : row)
        e = rnd.integer(0, 6) == 0 ? P2(0) : rnd.poly2(int(rnd.integer(0, 3)), int(rnd.integer(0, 3)), 5);
    const P2 d = bezoutian::polynomial_matrix_determinant(M);
    CHECK(d == bezoutian::berkowitz_determinant(M));
    if (n <= 4) CHECK(d == cgal_determinant(M));
  }
}

TEST_CASE("determinant: rational bivariate matrices", "[determinant]") {
  Random rnd(20260103);
  for (int trial = 0; trial < 6; ++trial) {
    const int n = int(rnd.integer(2, 4));
    Matrix<P2Q> M(n, std::vector<P2Q>(n));
    for (auto& row : M)
      for (auto& e : row) e = rnd.poly2_rational(int(rnd.integer(0, 2)), int(rnd.integer(0, 2)));
    CHECK(bezoutian::polynomial_matrix_determinant(M) == bezoutian::berkowitz_determinant(M));
  }
  // Univariate rational: diag(1/2 u, 1/3) has det u/6.
  Matrix<P1Q> D{{P1Q(Rational(0), Rational(1, 2)), P1Q(Rational(0))}, {P1Q(Rational(0)), P1Q(Rational(1, 3))}};
  CHECK(bezoutian::polynomial_matrix_determinant(D) == P1Q(Rational(0), Rational(1, 6)));
}

TEST_CASE("determinant: Sylvester matrices give CGAL's resultant", "[determinant]") {
  Random rnd(20260104);
  // Univariate entries: f, g in Z[u][v], Sylvester matrix in v.
  for (int trial = 0; trial < 4; ++trial) {
    const P2 f = rnd.poly2(3, int(rnd.integer(2, 4)), 7), g = rnd.poly2(2, int(rnd.integer(2, 4)), 7);
    CHECK(bezoutian::polynomial_matrix_determinant(sylvester(f, g)) == CGAL::resultant(f, g));
  }
  // 19x19 Sylvester matrix: above 16 rows the degree bound comes from row/column maxima.
  {
    const P2 f = rnd.poly2(3, 10, 9), g = rnd.poly2(2, 9, 9);
    const Matrix<P1> S = sylvester(f, g);
    REQUIRE(S.size() == 19);
    CHECK(bezoutian::polynomial_matrix_determinant(S) == CGAL::resultant(f, g));
  }
  // Bivariate entries: f, g in Z[u,v][w].
  using P3 = CGAL::Polynomial<P2>;
  for (int trial = 0; trial < 2; ++trial) {
    std::vector<P2> cf, cg;
    for (int i = 0; i <= 3; ++i) cf.push_back(rnd.poly2(1, 2, 4));
    for (int i = 0; i <= 2; ++i) cg.push_back(rnd.poly2(2, 1, 4));
    const P3 f(cf.begin(), cf.end()), g(cg.begin(), cg.end());
    CHECK(bezoutian::polynomial_matrix_determinant(sylvester(f, g)) == CGAL::resultant(f, g));
  }
}

TEST_CASE("determinant: structured matrices with closed-form determinants", "[determinant]") {
  Random rnd(20260105);
  SECTION("det(A B) = det A det B") {
    Matrix<P2> A(4, std::vector<P2>(4)), B(4, std::vector<P2>(4));
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) A[i][j] = rnd.poly2(2, 1, 4), B[i][j] = rnd.poly2(1, 2, 4);
    const P2 dA = bezoutian::polynomial_matrix_determinant(A), dB = bezoutian::polynomial_matrix_determinant(B);
    CHECK(dA == bezoutian::berkowitz_determinant(A));
    CHECK(dB == bezoutian::berkowitz_determinant(B));
    CHECK(bezoutian::polynomial_matrix_determinant(multiply(A, B)) == dA * dB);
  }
  SECTION("unimodular factor: the degree bound overestimates, cancellation is exact") {
    // E = unit lower triangular times unit upper triangular with large polynomial entries: det E = 1.
    Matrix<P2> L(5, std::vector<P2>(5, P2(0))), Up(5, std::vector<P2>(5, P2(0))), A(5, std::vector<P2>(5));
    for (int i = 0; i < 5; ++i) {
      L[i][i] = Up[i][i] = P2(1);
      for (int j = 0; j < i; ++j) L[i][j] = rnd.poly2(3, 3, 9), Up[j][i] = rnd.poly2(3, 3, 9);
      for (int j = 0; j < 5; ++j) A[i][j] = rnd.poly2(1, 1, 3);
    }
    const Matrix<P2> E = multiply(L, Up);
    CHECK(bezoutian::polynomial_matrix_determinant(E) == P2(1));
    CHECK(bezoutian::polynomial_matrix_determinant(multiply(A, E)) == bezoutian::berkowitz_determinant(A));
  }
  SECTION("triangular") {
    Matrix<P2> T(6, std::vector<P2>(6, P2(0)));
    P2 prod(1);
    for (int i = 0; i < 6; ++i) {
      for (int j = i; j < 6; ++j) T[i][j] = rnd.poly2(2, 2, 9);
      prod *= T[i][i];
    }
    CHECK(bezoutian::polynomial_matrix_determinant(T) == prod);
    // transpose too
    Matrix<P2> Tt(6, std::vector<P2>(6));
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) Tt[i][j] = T[j][i];
    CHECK(bezoutian::polynomial_matrix_determinant(Tt) == prod);
  }
  SECTION("Vandermonde matrix in polynomial nodes") {
    const int n = 5;
    std::vector<P2> x;
    for (int i = 0; i < n; ++i) x.push_back(rnd.poly2(1, 1, 6) + P2(i) * U * V);
    Matrix<P2> W(n, std::vector<P2>(n));
    for (int i = 0; i < n; ++i) {
      P2 p(1);
      for (int j = 0; j < n; ++j) W[i][j] = p, p *= x[i];
    }
    P2 expected(1);
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) expected *= x[j] - x[i];
    CHECK(bezoutian::polynomial_matrix_determinant(W) == expected);
  }
  SECTION("structural zeros on the diagonal need pivoting") {
    // Pattern of the seed's 3x3 Bezoutian (buse-elkadi-galligo-2008 Theorem 4): B[k][l] = 0 and B[lk][lk] = 0.
    Matrix<P2> B{{rnd.poly2(2, 2, 5), P2(0), rnd.poly2(2, 2, 5)},
                 {P2(0), rnd.poly2(2, 2, 5), rnd.poly2(2, 2, 5)},
                 {rnd.poly2(2, 2, 5), rnd.poly2(2, 2, 5), P2(0)}};
    CHECK(bezoutian::polynomial_matrix_determinant(B) == bezoutian::berkowitz_determinant(B));
    // A permutation-like matrix with zero diagonal: det = sign * product.
    Matrix<P2> Z(4, std::vector<P2>(4, P2(0)));
    const P2 a = U + 1, b = V - 2, c = U * V + 3, d = U - V;
    Z[0][1] = a, Z[1][0] = b, Z[2][3] = c, Z[3][2] = d; // two transpositions: sign +1
    CHECK(bezoutian::polynomial_matrix_determinant(Z) == a * b * c * d);
    Z[0][1] = P2(0), Z[0][2] = a, Z[2][3] = P2(0), Z[2][1] = c; // cycle (0 2 1) times (3 ...)
    CHECK(bezoutian::polynomial_matrix_determinant(Z) == bezoutian::berkowitz_determinant(Z));
    // Zero diagonal and rank-deficient modulo small values: pivoting at evaluation points.
    Matrix<P2> Y{{P2(0), U, V}, {U, P2(0), U * V}, {V, U * V, P2(0)}};
    CHECK(bezoutian::polynomial_matrix_determinant(Y) == P2(2) * U * U * V * V);
  }
  SECTION("singular matrices") {
    Matrix<P2> S(4, std::vector<P2>(4));
    for (auto& row : S)
      for (auto& e : row) e = rnd.poly2(2, 2, 9);
    S[2] = S[0];
    CHECK(CGAL::is_zero(bezoutian::polynomial_matrix_determinant(S)));
    for (auto& e : S[2]) e = rnd.poly2(2, 2, 9); // rows independent again
    for (int i = 0; i < 4; ++i) S[i][3] = S[i][0] * (U - 2) + S[i][1] * V; // dependent columns
    CHECK(CGAL::is_zero(bezoutian::polynomial_matrix_determinant(S)));
    Matrix<P2> R = S;
    R[1] = std::vector<P2>(4, P2(0)); // a row of zeros
    CHECK(CGAL::is_zero(bezoutian::polynomial_matrix_determinant(R)));
    CHECK(CGAL::is_zero(bezoutian::polynomial_matrix_determinant(Matrix<P2>(5, std::vector<P2>(5, P2(0))))));
  }
  SECTION("sizes 0 and 1, constants, one variable only") {
    CHECK(bezoutian::polynomial_matrix_determinant(Matrix<P2>{}) == P2(1));
    CHECK(bezoutian::polynomial_matrix_determinant(Matrix<P1>{}) == P1(1));
    CHECK(bezoutian::berkowitz_determinant(Matrix<Integer>{}) == Integer(1));
    const P2 f = rnd.poly2(3, 2, 9);
    CHECK(bezoutian::polynomial_matrix_determinant(Matrix<P2>{{f}}) == f);
    Matrix<P2> C{{P2(3), P2(5)}, {P2(7), P2(11)}};
    CHECK(bezoutian::polynomial_matrix_determinant(C) == P2(-2));
    Matrix<P2> Vonly{{V * V + 1, V}, {P2(2), V * V * V - 4}};
    CHECK(bezoutian::polynomial_matrix_determinant(Vonly) == (V * V + 1) * (V * V * V - 4) - 2 * V);
    CHECK(bezoutian::berkowitz_determinant(Matrix<Integer>{{Integer(2), Integer(1)}, {Integer(1), Integer(1)}}) ==
          Integer(1));
  }
  SECTION("non-square input is rejected") {
    Matrix<P2> bad{{P2(1), P2(2)}, {P2(3)}};
    CHECK_THROWS_AS(bezoutian::polynomial_matrix_determinant(bad), std::invalid_argument);
    CHECK_THROWS_AS(bezoutian::berkowitz_determinant(bad), std::invalid_argument);
  }
}

TEST_CASE("determinant: large (200-bit) coefficients", "[determinant]") {
  Random rnd(20260106);
  Matrix<P2> M(4, std::vector<P2>(4));
  for (auto& row : M)
    for (auto& e : row) e = rnd.poly2_big(2, 2, 200);
  const P2 d = bezoutian::polynomial_matrix_determinant(M);
  CHECK(d == bezoutian::berkowitz_determinant(M));
  CHECK(d == cgal_determinant(M));
  Matrix<P1> N(6, std::vector<P1>(6));
  for (auto& row : N)
    for (auto& e : row) e = rnd.poly2_big(3, 0, 200)[0];
  CHECK(bezoutian::polynomial_matrix_determinant(N) == cgal_determinant(N));
}

TEST_CASE("determinant: more primes than the cached table, entries above the degree bound", "[determinant]") {
  Random rnd(20260107);
  // 8x8 with 520-bit coefficients: the coefficient bound needs more than 64 word primes.
  Matrix<P1> N(8, std::vector<P1>(8));
  for (auto& row : N)
    for (auto& e : row) e = rnd.poly2_big(1, 0, 520)[0];
  CHECK(bezoutian::polynomial_matrix_determinant(N) == bezoutian::berkowitz_determinant(N));
  // An entry of high degree that lies on no permutation of nonzero entries:
  // the evaluation grid is smaller than its degree.
  const P2 f = rnd.poly2(1, 1, 5), g = rnd.poly2(9, 11, 5), h = rnd.poly2(2, 1, 5);
  Matrix<P2> T{{f, g}, {P2(0), h}};
  CHECK(bezoutian::polynomial_matrix_determinant(T) == f * h);
  Matrix<P1> T1{{f[0], g[3]}, {P1(0), h[1]}};
  CHECK(bezoutian::polynomial_matrix_determinant(T1) == f[0] * h[1]);
}

TEST_CASE("determinant: modular helpers", "[determinant]") {
  using namespace bezoutian::internal;
  // Known primes / composites (2^61 - 1 is a Mersenne prime; 2^62 - 57 is the largest prime below 2^62).
  CHECK(is_prime_u64((u64(1) << 61) - 1));
  CHECK(word_prime(0) == (u64(1) << 62) - 57);
  CHECK(!is_prime_u64(u64(3215031751))); // strong pseudoprime to bases 2, 3, 5, 7
  CHECK(!is_prime_u64(u64(4294967291) * u64(4294967279)));
  // CRT of residues of a known integer gives it back with its sign.
  std::vector<u64> primes{word_prime(0), word_prime(1), word_prime(2)};
  Chinese_remainder crt(primes);
  Integer x("-123456789012345678901234567890123456789");
  std::vector<u64> r;
  for (u64 p : primes) r.push_back(Montgomery_modulus(p).from_montgomery(Montgomery_modulus(p).to_montgomery(x)));
  Integer y;
  crt.combine(r.data(), y);
  CHECK(y == x);
}

TEST_CASE("determinant: thousands of word primes, every one found, from several threads", "[determinant][primes]") {
  using namespace bezoutian::internal;
  // 5000 primes asked for in the order of a determinant loop and again from 4 threads at once: each is found once
  // and kept, so this stays fast (a search from the start on every call took 2.8 s for 800). Checked against GMP's
  // own primality test: each is prime, they decrease, and no prime lies between two consecutive ones (sampled).
  const std::size_t n = 5000;
  std::vector<u64> primes;
  for (std::size_t i = 0; i < n; ++i) primes.push_back(word_prime(i));
  auto gmp_prime = [](u64 x) {
    mpz_t z;
    mpz_init_set_ui(z, static_cast<unsigned long>(x));
    const int r = mpz_probab_prime_p(z, 30);
    mpz_clear(z);
    return r > 0;
  };
  for (std::size_t i = 0; i < n; i += 97) {
    CHECK(gmp_prime(primes[i]));
    if (i + 1 < n) {
      CHECK(primes[i + 1] < primes[i]);
      for (u64 c = primes[i] - 2; c > primes[i + 1]; c -= 2) CHECK_FALSE(gmp_prime(c));
    }
  }
  std::vector<std::vector<u64>> seen(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = 0; i < n + 1000; i += 1 + t) seen[t].push_back(word_prime(i));
    });
  for (auto& th : threads) th.join();
  for (std::size_t t = 0; t < 4; ++t)
    for (std::size_t k = 0; k < seen[t].size(); ++k) {
      const std::size_t i = k * (1 + t);
      if (i < n && seen[t][k] != primes[i]) FAIL("thread " << t << " got another prime at index " << i);
    }
}

TEST_CASE("normalization: primitive part and sign convention", "[determinant][normalization]") {
  // D = -6 (u v^2 + 3 u - 1) * ... : leading term (largest power of v, then of u) is -6 u v^2.
  const P2 g = U * V * V + 3 * U - 1;
  CHECK(bezoutian::normalized_primitive_part(P2(-6) * g) == g);
  CHECK(bezoutian::normalized_primitive_part(P2(4) * g) == g);
  CHECK(bezoutian::normalized_primitive_part(-g) == g);
  // Leading term decided by v first: v - 5u^3 has leading term v (coefficient +1).
  const P2 h = V - 5 * U * U * U;
  CHECK(bezoutian::normalized_primitive_part(-h) == h);
  CHECK(bezoutian::lexicographic_leading_coefficient(P2(-10) * h) == Integer(-10));
  // Among the terms of highest v-degree, the highest u-degree decides: v(2u^2 - u) -> +.
  const P2 k = V * (2 * U * U - U) + 7;
  CHECK(bezoutian::normalized_primitive_part(P2(-3) * k) == k);
  CHECK(CGAL::is_zero(bezoutian::normalized_primitive_part(P2(0))));
  CHECK(bezoutian::normalized_primitive_part(P2(-17)) == P2(1));
  CHECK(bezoutian::integer_content(P2(12) * U - P2(18) * V) == Integer(6));
}

TEST_CASE("normalization: square-free part", "[determinant][normalization]") {
  using Square_free = CGAL::Polynomial_traits_d<P2>::Make_square_free;
  const P2 f = U * V - 2 * V + 3;           // irreducible
  const P2 g = V * V + U * U * U - 7 * U;    // irreducible, coprime to f
  const P2 a = U + 1;                       // factor in u alone (content with respect to v)
  CHECK(bezoutian::normalized_square_free_part(f * f * g) == bezoutian::normalized_primitive_part(f * g));
  CHECK(bezoutian::normalized_square_free_part(P2(-12) * f * f * g) == bezoutian::normalized_primitive_part(f * g));
  CHECK(bezoutian::normalized_square_free_part(a * a * a * f * g * g) ==
        bezoutian::normalized_primitive_part(a * f * g));
  CHECK(bezoutian::normalized_square_free_part(g) == bezoutian::normalized_primitive_part(g));
  CHECK(bezoutian::normalized_square_free_part(P2(5)) == P2(1));
  CHECK(CGAL::is_zero(bezoutian::normalized_square_free_part(P2(0))));
  // Leading coefficient in v with repeated factors and integer roots 0, 1, 2
  // (the evaluation windows must avoid them); multiplicities 3 and 2.
  const P2 h = U * (U - 1) * (U - 1) * (U - 2) * V * V + 5 * V - U + 4;
  CHECK(bezoutian::normalized_square_free_part(f * f * f * h * h) == bezoutian::normalized_primitive_part(f * h));
  CHECK(bezoutian::normalized_square_free_part(h * h * g) == bezoutian::normalized_primitive_part(h * g));
  // Cross-check with CGAL's own Make_square_free on random products (small, CGAL is slow).
  Random rnd(20260108);
  for (int trial = 0; trial < 4; ++trial) {
    const P2 p = rnd.poly2(2, 1, 4) + V * V, q = rnd.poly2(1, 2, 4), r = rnd.poly2(1, 1, 3);
    const P2 D = p * p * q * (trial % 2 ? r * r * r : r);
    CHECK(bezoutian::normalized_square_free_part(D) == bezoutian::normalized_primitive_part(Square_free()(D)));
  }
}

TEST_CASE("normalization: square-free part of determinants", "[determinant][normalization]") {
  // A determinant (bi-degree (12,12)), its square times a factor in u, and a
  // matrix whose determinant is a square by construction: det(A) det(A) = det(diag(A, A)).
  Random rnd(20260109);
  Matrix<P2> A(4, std::vector<P2>(4));
  for (auto& row : A)
    for (auto& e : row) e = rnd.poly2(3, 3, 50);
  const P2 D = bezoutian::polynomial_matrix_determinant(A);
  const P2 pD = bezoutian::normalized_primitive_part(D);
  CHECK(bezoutian::normalized_square_free_part(D) == pD);
  CHECK(bezoutian::normalized_square_free_part(D * D * (U * U - 4) * (U * U - 4)) ==
        bezoutian::normalized_primitive_part(D * (U * U - 4)));
  Matrix<P2> AA(8, std::vector<P2>(8, P2(0)));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) AA[i][j] = AA[4 + i][4 + j] = A[i][j];
  const P2 D2 = bezoutian::polynomial_matrix_determinant(AA);
  CHECK(D2 == D * D);
  CHECK(bezoutian::normalized_square_free_part(D2) == pD);
}

TEST_CASE("exact division in Z[u][v]", "[determinant][normalization]") {
  using namespace bezoutian::internal;
  Random rnd(20260110);
  const P2 a = rnd.poly2(4, 3, 1000) + V * V * V * V, b = rnd.poly2(3, 5, 1000) + V * V * V * V * V * V;
  Dense_polynomial_entry Q;
  REQUIRE(exact_quotient(dense_entry(a * b), dense_entry(b), Q));
  CHECK(to_polynomial_2(Q) == a);
  CHECK(!exact_quotient(dense_entry(a * b + 1), dense_entry(b), Q));
  CHECK(!exact_quotient(dense_entry(a * b + U * V), dense_entry(b), Q));
  CHECK(!exact_quotient(dense_entry(a), dense_entry(b), Q)); // degree too small
  // Divisible over Q but not over Z is impossible for primitive divisors; 3a/(b) with b primitive:
  REQUIRE(exact_quotient(dense_entry(P2(3) * a * b), dense_entry(b), Q));
  CHECK(to_polynomial_2(Q) == P2(3) * a);
}

TEST_CASE("normalization: v-content when the first coefficients share only a constant", "[determinant][normalization]") {
  // gcd(3, 3u) = 3 but the v^2 coefficient is 1: the content is 1, not 3. Stopping the gcd at the first
  // constant made the primitive part of the modular candidate wrong (regression: teapot case below).
  const P2 s = V * V + 3 * U * V + 3; // irreducible (discriminant 9u^2 - 12 is not a square)
  CHECK(CGAL::abs(bezoutian::internal::v_content(s)[0]) == Integer(1));
  CHECK(bezoutian::internal::v_content(P2(6) * U * V + P2(4) * U) == P1(Integer(0), Integer(2)));
  CHECK(bezoutian::normalized_square_free_part(s * s) == s);
  CHECK(bezoutian::normalized_square_free_part(V * V * V * s * s * (U * U - 3)) ==
        bezoutian::normalized_primitive_part(V * s * (U * U - 3)));
  const P2 t = P2(4) * V * V + 6 * V + 6 * U; // integer content 2 in v^0, v^1; primitive overall
  CHECK(bezoutian::normalized_square_free_part(t * t * s) == bezoutian::normalized_primitive_part(t * s));
  // The last resort of the modular algorithm (CGAL's Make_square_free) agrees.
  CHECK(bezoutian::normalized_primitive_part(bezoutian::internal::generic_square_free_part(t * t * s)) ==
        bezoutian::normalized_primitive_part(t * s));
}

TEST_CASE("normalization: square-free part of the teapot body/body intersection", "[determinant][normalization]") {
  // Teapot body patches 4 and 5 (teapot32.bpt) share a boundary curve. D(u,t) is the regression case of
  // doc/determinant.md, "A hard case": a modular square-free part that must terminate. Checks by exact identities
  // computed with CGAL: S | D, every irreducible factor of D/S divides S (so D | S^k), S has no repeated factor.
  const auto doc = bezoutian::io::read_geometry_file(bezoutian_test::source_file("examples/data/teapot_body_handle.json"));
  REQUIRE(doc.patches.size() >= 2);
  const auto e = bezoutian::intersection_equation(doc.patches[0], doc.patches[1]);
  const P2& D = e.determinant;
  const P2& S = e.square_free;
  REQUIRE(!CGAL::is_zero(D));
  CHECK(S == bezoutian::normalized_square_free_part(D));
  CHECK(S.degree() == 25); // deg_t of the radical (FLINT's fmpz_mpoly_factor, computed offline)
  // S | D exactly.
  const P2 Q = CGAL::integral_division(D, S);
  CHECK(Q * S == D);
  // D | S^k: strip from D/S, one CGAL gcd with S at a time, the factors it shares with S.
  P2 R = Q;
  int k = 1;
  while (R.degree() > 0 || R[0].degree() > 0) {
    const P2 h = CGAL::gcd(R, S);
    REQUIRE((h.degree() > 0 || h[0].degree() > 0)); // a factor of D/S not in S would stop here
    R = CGAL::integral_division(R, h);
    ++k;
  }
  CHECK(k == 12); // D has a factor of multiplicity 12 in u alone (and t^3, from the shared boundary)
  // The shared boundary t = 0 of patch 5 lies on patch 4: t | D, hence t | S.
  CHECK(CGAL::is_zero(S[0]));
  // S square-free: its v-content c is square-free (CGAL's univariate gcd), and at u = x with
  // lc_v(S)(x) != 0 a repeated factor g of positive v-degree would give g(x,v) | gcd(f, f'), f = S(x,v).
  const P1 c = bezoutian::internal::v_content(S);
  CHECK(CGAL::gcd(c, CGAL::differentiate(c)).degree() == 0);
  std::vector<Integer> f_coefficients;
  for (const P1& a : S) f_coefficients.push_back(a.evaluate(Integer(1)));
  const P1 f(f_coefficients.begin(), f_coefficients.end());
  REQUIRE(f.degree() == S.degree());
  CHECK(CGAL::gcd(f, CGAL::differentiate(f)).degree() == 0);
}

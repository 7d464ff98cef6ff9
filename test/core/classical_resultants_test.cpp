// Tests of the classical elimination toolbox of du-1989 §3.2-3.3: Bezout
// matrix and resultant, gcd from the Bezout matrix, Sylvester resultant,
// Macaulay resultant and u-resultant, Goldman's special resolvent, and the
// implicitization of rational plane curves (eq. 4.1).
//
// Reference values come from outside the code under test: CGAL's Resultant and
// gcd, the Bezoutian computed by exact polynomial division, the seed's worked
// examples (eq. 3.48, Examples 3.2.2, 3.2.4, 3.3.1), constructed common roots,
// and classical identities (homogeneity, invariance under linear changes of
// variables, restriction to a hyperplane).
#include <bezoutian/elimination/Bezout_matrix.h>
#include <bezoutian/elimination/Goldman_resolvent.h>
#include <bezoutian/elimination/Macaulay_resultant.h>
#include <bezoutian/elimination/Sylvester_resultant.h>

#include <catch2/catch.hpp>

#include <array>
#include <random>
#include <vector>

using namespace bezoutian;

namespace {

using Z = Integer;
using Q = Rational;
using PZ = Polynomial_1<Z>;
using PQ = Polynomial_1<Q>;
using P2Z = Polynomial_2<Z>;
using P3Z = CGAL::Polynomial_type_generator<Z, 3>::Type;
using P3Q = CGAL::Polynomial_type_generator<Q, 3>::Type;
using P4Z = CGAL::Polynomial_type_generator<Z, 4>::Type;
using Matrix_Z = std::vector<std::vector<Z>>;

template <class Poly>
typename CGAL::Polynomial_traits_d<Poly>::Coefficient_type cgal_resultant(const Poly& f, const Poly& g) {
  return typename CGAL::Polynomial_traits_d<Poly>::Resultant()(f, g);
}

int uniform(std::mt19937& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }

/// Random integer polynomial of exact degree d, coefficients in [-bound, bound].
PZ random_polynomial(std::mt19937& rng, int d, int bound) {
  std::vector<Z> c(std::size_t(d) + 1);
  for (auto& x : c) x = uniform(rng, -bound, bound);
  while (c[d] == 0) c[d] = uniform(rng, -bound, bound);
  return PZ(c.begin(), c.end());
}

PZ variable_t() { return CGAL::shift(PZ(1), 1); }

template <class Poly>
Poly variable(int i) {
  return CGAL::shift(Poly(1), 1, i);
}

/// A and B (nonzero) are proportional over the fraction field.
template <class Poly>
bool proportional(const Poly& A, const Poly& B) {
  using PT = CGAL::Polynomial_traits_d<Poly>;
  typename PT::Innermost_leading_coefficient ilc;
  if (CGAL::is_zero(A) || CGAL::is_zero(B)) return false;
  return A * Poly(ilc(B)) == B * Poly(ilc(A));
}

/// Random homogeneous form of degree d in the variables of Poly, coefficients in [-bound, bound].
template <class Poly>
Poly random_form(std::mt19937& rng, int d, int bound) {
  constexpr int n = CGAL::Polynomial_traits_d<Poly>::d;
  Poly F(0);
  for (const auto& e : monomials_of_degree(std::size_t(n), d)) {
    Poly m(uniform(rng, -bound, bound));
    for (int i = 0; i < n; ++i) m *= CGAL::ipower(variable<Poly>(i), e[i]);
    F += m;
  }
  return F;
}

/// Value of a CGAL polynomial at an integer point.
template <class Poly>
Z evaluate_at(const Poly& F, const std::vector<Z>& p) {
  using PT = CGAL::Polynomial_traits_d<Poly>;
  std::vector<std::pair<CGAL::Exponent_vector, Z>> terms;
  typename PT::Monomial_representation()(F, std::back_inserter(terms));
  Z s(0);
  for (const auto& t : terms) {
    Z m = t.second;
    for (int i = 0; i < PT::d; ++i) m *= CGAL::ipower(p[i], t.first[i]);
    s += m;
  }
  return s;
}

/// The form m(p) F - F(p) m, which vanishes at p (m a monomial with m(p) != 0).
template <class Poly>
Poly force_root(const Poly& F, const std::vector<Z>& p, const std::vector<int>& monomial) {
  constexpr int n = CGAL::Polynomial_traits_d<Poly>::d;
  Poly m(1);
  for (int i = 0; i < n; ++i) m *= CGAL::ipower(variable<Poly>(i), monomial[i]);
  return F * Poly(evaluate_at(m, p)) - m * Poly(evaluate_at(F, p));
}

/// (f(s) g(t) - f(t) g(s)) / (t - s) by exact division, t = variable 0, s = variable 1.
P2Z bezoutian_by_division(const PZ& f, const PZ& g) {
  auto in_s = [](const PZ& p) {
    std::vector<PZ> c;
    for (int i = 0; i <= p.degree(); ++i) c.push_back(PZ(p[i]));
    return P2Z(c.begin(), c.end());
  };
  const P2Z ft(f), gt(g), fs = in_s(f), gs = in_s(g);
  const P2Z t_minus_s = P2Z(variable_t()) - variable<P2Z>(1);
  return CGAL::integral_division(fs * gt - ft * gs, t_minus_s);
}

Z coefficient(const P2Z& B, int p, int q) {  // coefficient of t^p s^q
  if (q > B.degree()) return Z(0);
  const PZ& c = B[q];
  return (CGAL::is_zero(c) || p > c.degree()) ? Z(0) : c[p];
}

} // namespace

// ---------------------------------------------------------------- Bezout ----

TEST_CASE("Bezout matrix entries (du-1989 eq. 3.4) are the coefficients of the Bezoutian", "[classical][bezout]") {
  std::mt19937 rng(1989);
  for (int m = 0; m <= 6; ++m)
    for (int n = 0; n <= 6; ++n) {
      const PZ f = random_polynomial(rng, m, 9), g = random_polynomial(rng, n, 9);
      const auto C = bezout_matrix(f, g);
      const P2Z B = bezoutian_by_division(f, g);
      const int N = std::max(m, n);
      REQUIRE(C.size() == std::size_t(N));
      for (int p = 0; p < N; ++p)
        for (int q = 0; q < N; ++q) {
          REQUIRE(C[p][q] == coefficient(B, p, q));
          REQUIRE(C[p][q] == C[q][p]);
        }
      // Nothing beyond degree N-1 in either variable.
      for (int q = 0; q <= B.degree(); ++q) REQUIRE((q < N || CGAL::is_zero(B[q])));
    }
}

TEST_CASE("Bezout resultant equals CGAL's resultant and the Sylvester determinant on 200 random pairs",
          "[classical][bezout]") {
  std::mt19937 rng(20261122);
  int equal = 0, unequal = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int m = uniform(rng, 1, 12);
    const int n = (trial % 2 == 0) ? m : uniform(rng, 1, 12);
    (m == n ? equal : unequal)++;
    const PZ f = random_polynomial(rng, m, 20), g = random_polynomial(rng, n, 20);
    const Z reference = cgal_resultant(f, g);
    INFO("degrees " << m << ", " << n);
    REQUIRE(bezout_resultant(f, g) == reference);
    REQUIRE(sylvester_resultant(f, g) == reference);
    REQUIRE(Bezout_resultant()(g, f) == cgal_resultant(g, f));
  }
  REQUIRE(equal >= 100);
  REQUIRE(unequal >= 80);
}

TEST_CASE("Bezout resultant over the rationals", "[classical][bezout]") {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const int m = uniform(rng, 1, 6), n = uniform(rng, 1, 6);
    auto random_q = [&](int d) {
      std::vector<Q> c(std::size_t(d) + 1);
      for (auto& x : c) x = Q(uniform(rng, -9, 9), uniform(rng, 1, 7));
      if (c[d] == 0) c[d] = Q(1, 3);
      return PQ(c.begin(), c.end());
    };
    const PQ f = random_q(m), g = random_q(n);
    REQUIRE(bezout_resultant(f, g) == cgal_resultant(f, g));
    REQUIRE(sylvester_resultant(f, g) == cgal_resultant(f, g));
  }
}

TEST_CASE("Bezout determinant: sign convention and the extraneous factor of unequal degrees",
          "[classical][bezout]") {
  std::mt19937 rng(31);
  const PZ t = variable_t();
  for (int trial = 0; trial < 40; ++trial) {
    const int m = uniform(rng, 1, 8), n = uniform(rng, 0, 8);
    const PZ f = random_polynomial(rng, m, 9), g = random_polynomial(rng, n, 9);
    const int N = std::max(m, n);
    const Z res = cgal_resultant(f, g);
    const Z det = internal::bareiss_determinant(bezout_matrix(f, g));
    // Documented relation (Bezout_matrix.h): det C = (-1)^{N(N+1)/2 [+ n(m+1) if m < n]} lc^{|m-n|} Res.
    long e = long(N) * (N + 1) / 2 + (m < n ? long(n) * (m + 1) : 0);
    const Z lc = (m >= n) ? f.lcoeff() : g.lcoeff();
    const Z expected = CGAL::ipower(lc, std::abs(m - n)) * res;
    REQUIRE(det == (e % 2 == 0 ? expected : Z(-expected)));
    if (m > n && f[0] != 0) {
      // du-1989 §3.2.1, method (b): g replaced by t^{m-n} g gives the factor a_0^{m-n}
      // (the seed attributes a_0^{m-n} to method (a); method (a) gives a_m^{m-n}, checked above).
      const PZ gb = g * CGAL::ipower(t, m - n);
      const Z det_b = internal::bareiss_determinant(bezout_matrix(f, gb));
      REQUIRE(CGAL::abs(det_b) == CGAL::abs(CGAL::ipower(f[0], m - n) * res));
    }
  }
}

TEST_CASE("Sylvester matrix with formal degrees", "[classical][sylvester]") {
  std::mt19937 rng(4);
  for (int trial = 0; trial < 20; ++trial) {
    const int m = uniform(rng, 0, 6), n = uniform(rng, 1, 6);
    const PZ f = random_polynomial(rng, m, 9), g = random_polynomial(rng, n, 9);
    // f read with formal degree m + 1 (leading coefficient 0): Res_{m+1,n}(f, g) = (-1)^n lc(g) Res(f, g).
    const Z padded = internal::bareiss_determinant(sylvester_matrix(f, g, m + 1, n));
    const Z expected = g.lcoeff() * cgal_resultant(f, g);
    REQUIRE(padded == (n % 2 == 0 ? expected : Z(-expected)));
    REQUIRE(Sylvester_resultant()(f, g) == cgal_resultant(f, g));
  }
  REQUIRE_THROWS_AS(sylvester_matrix(variable_t() * variable_t(), PZ(1), 1, 0), Invalid_input);
}

TEST_CASE("Bezout and Sylvester resultants agree with CGAL on constants and zero", "[classical][bezout]") {
  const PZ t = variable_t();
  const std::vector<PZ> cases = {PZ(0), PZ(3), PZ(-2), t + 1, 2 * t * t - 3, t * t * t};
  for (const PZ& f : cases)
    for (const PZ& g : cases) {
      REQUIRE(bezout_resultant(f, g) == cgal_resultant(f, g));
      REQUIRE(sylvester_resultant(f, g) == cgal_resultant(f, g));
    }
}

TEST_CASE("gcd and number of common roots from the Bezout matrix (Goldman-Sederberg-Anderson)", "[classical][bezout]") {
  std::mt19937 rng(84);
  for (int trial = 0; trial < 60; ++trial) {
    const int dg = uniform(rng, 0, 5), da = uniform(rng, 0, 6), db = uniform(rng, 0, 6);
    const PZ g = random_polynomial(rng, dg, 5), a = random_polynomial(rng, da, 5), b = random_polynomial(rng, db, 5);
    const PZ f = g * a, h = g * b;
    const PZ reference = CGAL::gcd(f, h);
    INFO("deg g = " << dg << ", deg a = " << da << ", deg b = " << db);
    const auto r = bezout_gcd(f, h);
    const std::size_t N = std::size_t(std::max(f.degree(), h.degree()));
    REQUIRE(r.matrix_size == N);
    REQUIRE(r.gcd_degree == std::size_t(reference.degree()));
    REQUIRE(r.rank == N - std::size_t(reference.degree()));
    REQUIRE(number_of_common_roots(f, h) == std::size_t(reference.degree()));
    REQUIRE(bezout_rank(f, h) == r.rank);
    REQUIRE(r.gcd.degree() >= dg);  // g divides the gcd
    REQUIRE(CGAL::canonicalize(reference) == r.gcd);
  }
}

TEST_CASE("gcd from the Bezout matrix: vanishing corner pivot, multiple roots, proportional input", "[classical][bezout]") {
  const PZ t = variable_t();
  // c_{N-1,N-1} = 0 without a common root: row pivoting is needed.
  const PZ f = t * t + 1, g = t * t + 2;
  REQUIRE(bezout_matrix(f, g)[1][1] == 0);
  REQUIRE(bezout_gcd(f, g).gcd_degree == 0);
  REQUIRE(bezout_gcd(f, g).rank == 2);
  const auto r = Bezout_gcd()(f * (t - 1), g * (t - 1));
  REQUIRE(Bezout_matrix()(f, g) == bezout_matrix(f, g));
  REQUIRE(r.gcd == t - 1);
  // Multiple common root.
  const PZ m = (t - 1) * (t - 1) * (t + 2);
  const auto s = bezout_gcd(m * (3 * t + 1), m * (t * t - 5));
  REQUIRE(s.gcd == m);
  REQUIRE(number_of_common_roots(m * (3 * t + 1), m * (t * t - 5)) == 3);
  // Proportional polynomials and the zero polynomial: zero Bezout matrix.
  REQUIRE(bezout_gcd(PZ(3) * m, PZ(-2) * m).gcd == m);
  REQUIRE(bezout_gcd(PZ(0), m).gcd == m);
  REQUIRE(bezout_gcd(PZ(5), m).gcd == PZ(1));
  REQUIRE_THROWS_AS(bezout_gcd(PZ(0), PZ(0)), Invalid_input);
  // Over the rationals the gcd comes out monic.
  const PQ fq = PQ(Q(1, 2)) * PQ(Q(-1), Q(1)) * PQ(Q(3), Q(0), Q(1)), gq = PQ(Q(-1), Q(1)) * PQ(Q(2, 3), Q(5));
  REQUIRE(bezout_gcd(fq, gq).gcd == PQ(Q(-1), Q(1)));
}

// ------------------------------------------------------------- Sylvester ----

TEST_CASE("Sylvester resultant of binary forms", "[classical][sylvester]") {
  std::mt19937 rng(5);
  const P2Z x1 = variable<P2Z>(0), x2 = variable<P2Z>(1);
  for (int trial = 0; trial < 30; ++trial) {
    const int d1 = uniform(rng, 1, 5), d2 = uniform(rng, 1, 5);
    const PZ f = random_polynomial(rng, d1, 9), g = random_polynomial(rng, d2, 9);
    auto homogenize = [&](const PZ& p) {
      P2Z F(0);
      for (int i = 0; i <= p.degree(); ++i) F += P2Z(p[i]) * CGAL::ipower(x1, i) * CGAL::ipower(x2, p.degree() - i);
      return F;
    };
    const P2Z F = homogenize(f), G = homogenize(g);
    // Chart x2 = 1 with nonzero leading coefficients: CGAL's resultant of the dehomogenized pair.
    REQUIRE(homogeneous_sylvester_resultant(F, G) == cgal_resultant(f, g));
    // A common zero at infinity (1 : 0): both forms divisible by x2.
    REQUIRE(homogeneous_sylvester_resultant(F * x2, G * x2) == 0);
    // A common zero (2 : 3).
    REQUIRE(homogeneous_sylvester_resultant(F * (3 * x1 - 2 * x2), G * (3 * x1 - 2 * x2)) == 0);
    // Only one of them at infinity: no common zero; Res(F x2, G) = Res(F, G) Res(x2, G) = Res(F,G) * g_{d2}... up to sign.
    const Z r = homogeneous_sylvester_resultant(F * x2, G);
    REQUIRE(CGAL::abs(r) == CGAL::abs(cgal_resultant(f, g) * g.lcoeff()));
  }
  REQUIRE(homogeneous_sylvester_resultant(CGAL::ipower(x1, 3), CGAL::ipower(x2, 2)) == 1);
  REQUIRE(Homogeneous_sylvester_resultant()(x1 - x2, x1 + x2) == 2);
  REQUIRE_THROWS_AS(homogeneous_sylvester_matrix(x1 * x1 + x2, x1), Invalid_input);
  REQUIRE_THROWS_AS(homogeneous_sylvester_matrix(P2Z(0), x1), Invalid_input);
}

// -------------------------------------------------------------- Macaulay ----

TEST_CASE("Macaulay resultant of linear forms is the determinant of the coefficient matrix", "[classical][macaulay]") {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<P3Z> F3;
    Matrix_Z A3(3, std::vector<Z>(3));
    for (int i = 0; i < 3; ++i) {
      P3Z f(0);
      for (int j = 0; j < 3; ++j) {
        A3[i][j] = uniform(rng, -9, 9);
        f += P3Z(A3[i][j]) * variable<P3Z>(j);
      }
      F3.push_back(f);
    }
    const Z det3 = A3[0][0] * (A3[1][1] * A3[2][2] - A3[1][2] * A3[2][1]) -
                   A3[0][1] * (A3[1][0] * A3[2][2] - A3[1][2] * A3[2][0]) +
                   A3[0][2] * (A3[1][0] * A3[2][1] - A3[1][1] * A3[2][0]);
    REQUIRE(macaulay_resultant(F3) == det3);
    REQUIRE(Macaulay_resultant()(F3) == det3);

    std::vector<P4Z> F4;
    Matrix_Z A4(4, std::vector<Z>(4));
    for (int i = 0; i < 4; ++i) {
      P4Z f(0);
      for (int j = 0; j < 4; ++j) {
        A4[i][j] = uniform(rng, -9, 9);
        f += P4Z(A4[i][j]) * variable<P4Z>(j);
      }
      F4.push_back(f);
    }
    // Laplace expansion along the first row.
    Z det4(0);
    for (int j = 0; j < 4; ++j) {
      Matrix_Z minor;
      for (int i = 1; i < 4; ++i) {
        std::vector<Z> row;
        for (int k = 0; k < 4; ++k)
          if (k != j) row.push_back(A4[i][k]);
        minor.push_back(row);
      }
      const Z m = minor[0][0] * (minor[1][1] * minor[2][2] - minor[1][2] * minor[2][1]) -
                  minor[0][1] * (minor[1][0] * minor[2][2] - minor[1][2] * minor[2][0]) +
                  minor[0][2] * (minor[1][0] * minor[2][1] - minor[1][1] * minor[2][0]);
      det4 += (j % 2 == 0 ? A4[0][j] : Z(-A4[0][j])) * m;
    }
    REQUIRE(macaulay_resultant(F4) == det4);
  }
}

TEST_CASE("Macaulay resultant in two variables is CGAL's resultant", "[classical][macaulay]") {
  std::mt19937 rng(12);
  const P2Z x1 = variable<P2Z>(0), x2 = variable<P2Z>(1);
  for (int trial = 0; trial < 20; ++trial) {
    const int d1 = uniform(rng, 1, 5), d2 = uniform(rng, 1, 5);
    const PZ f = random_polynomial(rng, d1, 9), g = random_polynomial(rng, d2, 9);
    auto homogenize = [&](const PZ& p) {
      P2Z F(0);
      for (int i = 0; i <= p.degree(); ++i) F += P2Z(p[i]) * CGAL::ipower(x1, i) * CGAL::ipower(x2, p.degree() - i);
      return F;
    };
    REQUIRE(macaulay_resultant(std::vector<P2Z>{homogenize(f), homogenize(g)}) == cgal_resultant(f, g));
  }
}

TEST_CASE("Macaulay resultant of three forms: common root, homogeneity, restriction, linear change",
          "[classical][macaulay]") {
  std::mt19937 rng(13);
  const std::vector<std::array<int, 3>> degree_cases = {{1, 1, 1}, {2, 2, 2}, {2, 1, 2}, {1, 2, 3}, {3, 2, 1}, {2, 2, 1}};
  for (const auto& d : degree_cases) {
    INFO("degrees " << d[0] << ", " << d[1] << ", " << d[2]);
    std::vector<P3Z> F;
    for (int i = 0; i < 3; ++i) F.push_back(random_form<P3Z>(rng, d[i], 5));
    const Z R = macaulay_resultant(F);
    REQUIRE(R != 0);  // random forms have no common zero

    // Construct a common projective zero p: the resultant vanishes.
    const std::vector<Z> p = {Z(uniform(rng, 1, 4)), Z(uniform(rng, -4, -1)), Z(uniform(rng, 1, 3))};
    std::vector<P3Z> G;
    for (int i = 0; i < 3; ++i) {
      G.push_back(force_root(F[i], p, {d[i], 0, 0}));
      REQUIRE(evaluate_at(G[i], p) == 0);
    }
    REQUIRE(macaulay_resultant(G) == 0);
    // Common zero at infinity-like coordinate points too: (0 : 0 : 1).
    std::vector<P3Z> H;
    for (int i = 0; i < 3; ++i) H.push_back(force_root(F[i], {Z(0), Z(0), Z(1)}, {0, 0, d[i]}));
    REQUIRE(macaulay_resultant(H) == 0);

    // Homogeneous of degree prod_{j != i} d_j in the coefficients of F_i.
    for (int i = 0; i < 3; ++i) {
      std::vector<P3Z> S = F;
      S[i] *= P3Z(3);
      const int e = d[(i + 1) % 3] * d[(i + 2) % 3];
      REQUIRE(macaulay_resultant(S) == CGAL::ipower(Z(3), e) * R);
    }

    // Linear change of variables x -> A x: Res(F o A) = det(A)^{d1 d2 d3} Res(F).
    Matrix_Z A(3, std::vector<Z>(3));
    for (auto& row : A)
      for (auto& a : row) a = uniform(rng, -2, 2);
    const Z detA = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                   A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    std::vector<P3Z> images;
    for (int i = 0; i < 3; ++i) {
      P3Z im(0);
      for (int j = 0; j < 3; ++j) im += P3Z(A[i][j]) * variable<P3Z>(j);
      images.push_back(im);
    }
    std::vector<P3Z> FA;
    for (const auto& f : F)
      FA.push_back(typename CGAL::Polynomial_traits_d<P3Z>::Substitute()(f, images.begin(), images.end()));
    REQUIRE(macaulay_resultant(FA) == CGAL::ipower(detA, d[0] * d[1] * d[2]) * R);
  }

  // Restriction: Res(F1, F2, x3) = Res(F1(x1, x2, 0), F2(x1, x2, 0)) (Sylvester of binary forms).
  for (int trial = 0; trial < 5; ++trial) {
    const int d1 = uniform(rng, 1, 3), d2 = uniform(rng, 1, 3);
    const P3Z F1 = random_form<P3Z>(rng, d1, 5), F2 = random_form<P3Z>(rng, d2, 5);
    auto restrict_to_x3_zero = [](const P3Z& F) {
      const P2Z x1 = variable<P2Z>(0), x2 = variable<P2Z>(1);
      std::vector<P2Z> im = {x1, x2, P2Z(0)};
      return typename CGAL::Polynomial_traits_d<P3Z>::Substitute()(F, im.begin(), im.end());
    };
    REQUIRE(macaulay_resultant(std::vector<P3Z>{F1, F2, variable<P3Z>(2)}) ==
            homogeneous_sylvester_resultant(restrict_to_x3_zero(F1), restrict_to_x3_zero(F2)));
  }
}

TEST_CASE("Macaulay matrix of du-1989 Example 3.2.3 (eq. 3.48)", "[classical][macaulay]") {
  const P3Z x = variable<P3Z>(0), y = variable<P3Z>(1), z = variable<P3Z>(2);
  const P3Z P1 = x * x + x * y + 2 * x * z + y * z - z * z;
  const P3Z P2 = x * x + 3 * x * z - y * y + 2 * y * z - z * z;
  const P3Z P3 = x + 2 * y + z;
  const std::vector<Homogeneous_form<Z>> F = {homogeneous_form(P1), homogeneous_form(P2), homogeneous_form(P3)};
  const auto M = macaulay_matrix(F);
  // Seed: rows xP1, yP1, zP1, xP2, yP2, zP2, xyP3, xzP3, yzP3, z^2P3; columns
  // x^3, x^2y, x^2z, xy^2, xyz, xz^2, y^3, y^2z, yz^2, z^3.
  const int seed[10][10] = {{1, 1, 2, 0, 1, -1, 0, 0, 0, 0},  {0, 1, 0, 1, 2, 0, 0, 1, -1, 0},
                            {0, 0, 1, 0, 1, 2, 0, 0, 1, -1},  {1, 0, 3, -1, 2, -1, 0, 0, 0, 0},
                            {0, 1, 0, 0, 3, 0, -1, 2, -1, 0}, {0, 0, 1, 0, 0, 3, 0, -1, 2, -1},
                            {0, 1, 0, 2, 1, 0, 0, 0, 0, 0},   {0, 0, 1, 0, 2, 1, 0, 0, 0, 0},
                            {0, 0, 0, 0, 1, 0, 0, 2, 1, 0},   {0, 0, 0, 0, 0, 1, 0, 0, 2, 1}};
  const std::vector<std::vector<int>> columns = {{3, 0, 0}, {2, 1, 0}, {2, 0, 1}, {1, 2, 0}, {1, 1, 1},
                                                 {1, 0, 2}, {0, 3, 0}, {0, 2, 1}, {0, 1, 2}, {0, 0, 3}};
  REQUIRE(M.degree == 3);
  REQUIRE(M.monomials == columns);
  // Seed row of (polynomial, multiplier).
  const std::vector<std::pair<std::size_t, std::vector<int>>> seed_rows = {
      {0, {1, 0, 0}}, {0, {0, 1, 0}}, {0, {0, 0, 1}}, {1, {1, 0, 0}}, {1, {0, 1, 0}},
      {1, {0, 0, 1}}, {2, {1, 1, 0}}, {2, {1, 0, 1}}, {2, {0, 1, 1}}, {2, {0, 0, 2}}};
  const int d[3] = {2, 2, 1};
  for (std::size_t r = 0; r < 10; ++r) {
    std::vector<int> multiplier = M.monomials[r];
    const std::size_t i = M.row_polynomial[r];
    multiplier[i] -= d[i];
    std::size_t k = 0;
    while (seed_rows[k] != std::make_pair(i, multiplier)) ++k;
    for (std::size_t c = 0; c < 10; ++c) REQUIRE(M.matrix[r][c] == seed[k][c]);
  }
  // The system has the zero (-3, 1, 1): resultant 0, rank 8, and the monomial vector is a null vector.
  REQUIRE(macaulay_resultant(F) == 0);
  REQUIRE(Macaulay_resultant()(F) == 0);
  REQUIRE(internal::fraction_free_rank(M.matrix) == 8);
  for (std::size_t r = 0; r < 10; ++r) {
    Z s(0);
    for (std::size_t c = 0; c < 10; ++c)
      s += M.matrix[r][c] * evaluate_at(CGAL::ipower(x, columns[c][0]) * CGAL::ipower(y, columns[c][1]) *
                                            CGAL::ipower(z, columns[c][2]),
                                        {Z(-3), Z(1), Z(1)});
    REQUIRE(s == 0);
  }
  // Delta M: monomials x^2 z and y^2 z (divisible by two of x^2, y^2, z).
  REQUIRE(M.extraneous_indices.size() == 2);
  REQUIRE(internal::bareiss_determinant(M.extraneous_minor()) == -1);
}

TEST_CASE("Extraneous minor of three quadrics (du-1989 Example 3.2.2, Delta M(3,4))", "[classical][macaulay]") {
  std::mt19937 rng(14);
  std::vector<P3Z> F;
  for (int i = 0; i < 3; ++i) F.push_back(random_form<P3Z>(rng, 2, 9));
  std::vector<Homogeneous_form<Z>> G;
  for (const auto& f : F) G.push_back(homogeneous_form(f));
  const auto M = macaulay_matrix(G);
  REQUIRE(M.monomials.size() == 15);
  REQUIRE(M.extraneous_indices.size() == 3);
  std::vector<std::vector<int>> labels;
  for (std::size_t i : M.extraneous_indices) labels.push_back(M.monomials[i]);
  REQUIRE(labels == std::vector<std::vector<int>>{{2, 2, 0}, {2, 0, 2}, {0, 2, 2}});
  auto a = [&](int i, const std::vector<int>& e) { return G[i].coefficient(e); };
  const std::vector<int> xx = {2, 0, 0}, yy = {0, 2, 0}, zz = {0, 0, 2};
  const Matrix_Z seed = {{a(0, xx), 0, a(0, zz)}, {0, a(0, xx), a(0, yy)}, {0, a(1, xx), a(1, yy)}};
  REQUIRE(M.extraneous_minor() == seed);
}

TEST_CASE("Macaulay resultant when the extraneous minor vanishes (generalized characteristic polynomial)",
          "[classical][macaulay]") {
  std::mt19937 rng(15);
  const P3Z x = variable<P3Z>(0), y = variable<P3Z>(1), z = variable<P3Z>(2);
  for (int trial = 0; trial < 4; ++trial) {
    // Three quadrics with no x^2 term in F1: det Delta M = a_xx (a_xx b_yy - a_yy b_xx) = 0.
    std::vector<P3Z> F;
    for (int i = 0; i < 3; ++i) F.push_back(random_form<P3Z>(rng, 2, 5));
    F[0] -= P3Z(homogeneous_form(F[0]).coefficient({2, 0, 0})) * x * x;
    if (homogeneous_form(F[0]).coefficient({0, 0, 2}) == 0) F[0] += z * z;  // a_zz != 0 for the reference
    std::vector<Homogeneous_form<Z>> G;
    for (const auto& f : F) G.push_back(homogeneous_form(f));
    REQUIRE(internal::bareiss_determinant(macaulay_matrix(G).extraneous_minor()) == 0);
    const Z R = macaulay_resultant(F);
    // Reference: a permutation P of the variables (Res(F o P) = det(P)^8 Res(F) = Res(F))
    // after which the extraneous minor is nonzero and the direct formula applies.
    const std::vector<std::vector<P3Z>> permutations = {{z, y, x}, {y, x, z}, {x, z, y}, {y, z, x}, {z, x, y}};
    bool compared = false;
    for (const auto& images : permutations) {
      std::vector<P3Z> FP;
      for (const auto& f : F)
        FP.push_back(typename CGAL::Polynomial_traits_d<P3Z>::Substitute()(f, images.begin(), images.end()));
      std::vector<Homogeneous_form<Z>> GP;
      for (const auto& f : FP) GP.push_back(homogeneous_form(f));
      if (internal::bareiss_determinant(macaulay_matrix(GP).extraneous_minor()) == 0) continue;
      REQUIRE(R == macaulay_resultant(FP));
      compared = true;
      break;
    }
    REQUIRE(compared);
    REQUIRE(R != 0);
  }
}

TEST_CASE("Macaulay resultant rejects malformed systems", "[classical][macaulay]") {
  const P3Z x = variable<P3Z>(0), y = variable<P3Z>(1), z = variable<P3Z>(2);
  REQUIRE_THROWS_AS(macaulay_resultant(std::vector<P3Z>{x, y}), Invalid_input);
  REQUIRE_THROWS_AS(macaulay_resultant(std::vector<P3Z>{x * x + y, y, z}), Invalid_input);
  REQUIRE_THROWS_AS(macaulay_resultant(std::vector<P3Z>{P3Z(0), y, z}), Invalid_input);
  REQUIRE_THROWS_AS(macaulay_resultant(std::vector<P3Z>{P3Z(2), y, z}), Invalid_input);
}

// ----------------------------------------------------------- u-resultant ----

TEST_CASE("u-resultant of du-1989 Example 3.2.4 factors into the four common points", "[classical][u-resultant]") {
  const P3Z x1 = variable<P3Z>(0), x2 = variable<P3Z>(1), x3 = variable<P3Z>(2);
  const P3Z P1 = x1 * x1 + x1 * x2 + 2 * x1 * x3 + x2 * x3 - x3 * x3;
  const P3Z P2 = x1 * x1 + 3 * x1 * x3 - x2 * x2 + 2 * x2 * x3 - x3 * x3;
  const P3Z Ru = u_resultant(std::vector<P3Z>{P1, P2});
  const P3Z &u1 = x1, &u2 = x2, &u3 = x3;  // the result's variables are u_1, u_2, u_3
  const P3Z seed = -(u1 - u2 + u3) * (-3 * u1 + u2 + u3) * (u2 + u3) * (u1 - u2);
  // Exactly the seed's product, constant -1 included (normalization Res(x_1^{d_1}, ..) = 1).
  REQUIRE(Ru == seed);
}

TEST_CASE("u-resultant of conics and lines with known common points", "[classical][u-resultant]") {
  std::mt19937 rng(16);
  const P3Z x = variable<P3Z>(0), y = variable<P3Z>(1), w = variable<P3Z>(2);
  auto line_through = [&](const std::array<Z, 3>& p, const std::array<Z, 3>& q) {  // cross product
    return P3Z(p[1] * q[2] - p[2] * q[1]) * x + P3Z(p[2] * q[0] - p[0] * q[2]) * y + P3Z(p[0] * q[1] - p[1] * q[0]) * w;
  };
  auto u_dot = [&](const std::array<Z, 3>& p) { return P3Z(p[0]) * x + P3Z(p[1]) * y + P3Z(p[2]) * w; };
  auto value = [&](const P3Z& R, const std::array<Z, 3>& u) { return evaluate_at(R, {u[0], u[1], u[2]}); };
  auto cross = [](const std::array<Z, 3>& p, const std::array<Z, 3>& q) {
    return std::array<Z, 3>{p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
  };
  for (int trial = 0; trial < 4; ++trial) {
    std::array<std::array<Z, 3>, 4> pts;
    for (auto& p : pts) p = {Z(uniform(rng, -6, 6)), Z(uniform(rng, -6, 6)), Z(uniform(rng, 1, 3))};
    // Two conics of the pencil through the four points (pairs of lines, then mixed).
    const P3Z C1 = line_through(pts[0], pts[1]) * line_through(pts[2], pts[3]);
    const P3Z C2 = line_through(pts[0], pts[2]) * line_through(pts[1], pts[3]);
    const P3Z A = C1 + 2 * C2, B = 3 * C1 - C2;
    const P3Z Ru = u_resultant(std::vector<P3Z>{A, B});
    const P3Z expected = u_dot(pts[0]) * u_dot(pts[1]) * u_dot(pts[2]) * u_dot(pts[3]);
    if (CGAL::is_zero(expected)) continue;
    // Degenerate configurations (three collinear points) make the conics share a line.
    bool general = true;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        for (int k = j + 1; k < 4; ++k) {
          const auto c = cross(pts[i], pts[j]);
          if (c[0] * pts[k][0] + c[1] * pts[k][1] + c[2] * pts[k][2] == 0) general = false;
        }
    if (!general) {
      REQUIRE(CGAL::is_zero(Ru));
      continue;
    }
    REQUIRE(proportional(Ru, expected));
    // Any line through a common point annihilates it; a line through no common point does not.
    const std::array<Z, 3> q = {Z(uniform(rng, -9, 9)), Z(uniform(rng, -9, 9)), Z(uniform(rng, 1, 9))};
    for (const auto& p : pts) REQUIRE(value(Ru, cross(p, q)) == 0);
    const std::array<Z, 3> u = {Z(1), Z(1000), Z(-7)};
    bool on_line = false;
    for (const auto& p : pts) on_line = on_line || (u[0] * p[0] + u[1] * p[1] + u[2] * p[2] == 0);
    if (!on_line) REQUIRE(value(Ru, u) != 0);
  }
  // Two lines: u . (their intersection point).
  const P3Z L1 = 2 * x - y + 3 * w, L2 = x + 4 * y - w;
  const std::array<Z, 3> p = cross({Z(2), Z(-1), Z(3)}, {Z(1), Z(4), Z(-1)});
  REQUIRE(proportional(u_resultant(std::vector<P3Z>{L1, L2}), u_dot(p)));
  // A conic and a line meeting in (1 : 2 : 1) and (3 : -1 : 1).
  const std::array<Z, 3> a = {Z(1), Z(2), Z(1)}, b = {Z(3), Z(-1), Z(1)}, c = {Z(0), Z(1), Z(1)}, e = {Z(2), Z(5), Z(1)};
  const P3Z conic = line_through(a, c) * line_through(b, e) + line_through(a, e) * line_through(b, c);
  const P3Z line = line_through(a, b);
  REQUIRE(proportional(u_resultant(std::vector<P3Z>{conic, line}), u_dot(a) * u_dot(b)));
  // No x^2, y^2 terms: the extraneous minor [[a_xx, a_yy], [b_xx, b_yy]] vanishes and the
  // generalized characteristic polynomial is used. Common zeros (1:0:0), (0:1:0), (1:1:1) twice.
  const P3Z Ru = u_resultant(std::vector<P3Z>{x * y - w * w, w * (x + y - 2 * w)});
  REQUIRE(proportional(Ru, x * y * (x + y + w) * (x + y + w)));
  REQUIRE(U_resultant()(std::vector<P3Z>{x * y - w * w, w * (x + y - 2 * w)}) == Ru);
  // One binary form: its roots (2 : 1) and (1 : -3).
  const P2Z s1 = variable<P2Z>(0), s2 = variable<P2Z>(1);
  REQUIRE(proportional(u_resultant(std::vector<P2Z>{(s1 - 2 * s2) * (3 * s1 + s2)}), (2 * s1 + s2) * (s1 - 3 * s2)));
}

// ---------------------------------------------------------------- Goldman ----

TEST_CASE("Goldman special resolvent of du-1989 Example 3.3.1", "[classical][goldman]") {
  const P3Z x = variable<P3Z>(0), y = variable<P3Z>(1), z = variable<P3Z>(2);
  using PP = Polynomial_1<P3Z>;
  const PP P1(-(P3Z(4) + x), P3Z(3), P3Z(-1), P3Z(2));
  const PP P2(-(P3Z(1) + y), P3Z(2), P3Z(-2), P3Z(1));
  const PP P3(-(P3Z(1) + z), P3Z(3), P3Z(-3), P3Z(1));
  const auto r = Goldman_special_resolvent()(P1, P2, P3);
  REQUIRE(r.d320 == x - 5 * y + 3 * z + 2);
  REQUIRE(r.d321 == P3Z(-2));
  REQUIRE(r.d310 == -x + 3 * y - z - 2);
  REQUIRE(r.d210 == 6 * y - 4 * z + 2);
  REQUIRE(r.R1 == -x * x + 10 * x * y - 6 * x * z - 25 * y * y + 30 * y * z - 9 * z * z - 2 * x + 14 * y - 10 * z);
  REQUIRE(r.R2 == x * x - 8 * x * y + 4 * x * z + 15 * y * y - 14 * y * z + 3 * z * z + 4 * x - 28 * y + 16 * z);
  REQUIRE(r.R3 == -x * x + 12 * x * y - 6 * x * z - 39 * y * y + 44 * y * z - 13 * z * z - 2 * x + 14 * y - 6 * z);
  // At x = y = z = 0 the common root is t0 = 1.
  const PQ Q1(Q(-4), Q(3), Q(-1), Q(2)), Q2(Q(-1), Q(2), Q(-2), Q(1)), Q3(Q(-1), Q(3), Q(-3), Q(1));
  const auto root = goldman_common_root(Q1, Q2, Q3);
  REQUIRE(root.has_value());
  REQUIRE(*root == Q(1));
}

TEST_CASE("Goldman resolvent and inversion on random cubics, compared with CGAL", "[classical][goldman]") {
  std::mt19937 rng(17);
  const PQ t = CGAL::shift(PQ(1), 1);
  int with_root = 0, without_root = 0;
  for (int trial = 0; trial < 60; ++trial) {
    auto random_q = [&](int d) {
      std::vector<Q> c(std::size_t(d) + 1);
      for (auto& v : c) v = Q(uniform(rng, -9, 9));
      if (c[d] == 0) c[d] = Q(1);
      return PQ(c.begin(), c.end());
    };
    PQ P[3];
    const Q r0(uniform(rng, -20, 20), uniform(rng, 1, 6));
    const bool construct = (trial % 2 == 0);
    for (auto& p : P) p = construct ? (t - PQ(r0)) * random_q(2) : random_q(3);
    const auto r = goldman_resolvent(P[0], P[1], P[2]);
    REQUIRE(r.linearly_independent());
    // The resolvents are the resultants of the linear pairs (eq. 3.59); CGAL
    // uses actual degrees, so compare when both members have degree 1.
    INFO("brackets " << r.d321 << " " << r.d320 << " " << r.d310 << " " << r.d210);
    if (r.F1.degree() == 1 && r.F2.degree() == 1) REQUIRE(r.R1 == cgal_resultant(r.F1, r.F2));
    if (r.F1.degree() == 1 && r.F3.degree() == 1) REQUIRE(r.R2 == cgal_resultant(r.F1, r.F3));
    if (r.F2.degree() == 1 && r.F3.degree() == 1) REQUIRE(r.R3 == cgal_resultant(r.F2, r.F3));
    const PQ g = CGAL::gcd(CGAL::gcd(P[0], P[1]), P[2]);
    const bool cgal_common = g.degree() > 0;
    const auto root = goldman_common_root(P[0], P[1], P[2]);
    REQUIRE(root.has_value() == cgal_common);
    REQUIRE(r.has_common_root() == cgal_common);
    if (cgal_common) {
      ++with_root;
      REQUIRE(g.degree() == 1);
      REQUIRE(r.R1 == 0);
      REQUIRE(r.R2 == 0);
      REQUIRE(r.R3 == 0);
      REQUIRE(g.evaluate(*root) == 0);
      if (construct) REQUIRE(*root == r0);
      REQUIRE(cgal_resultant(P[0], P[1]) == 0);
    } else {
      ++without_root;
    }
  }
  REQUIRE(with_root >= 30);
  REQUIRE(without_root >= 25);
  // Linearly dependent input: the resolvents say nothing.
  const PQ a = t * t * t - 2, b = t + 1;
  REQUIRE_THROWS_AS(goldman_common_root(a, b, a + PQ(Q(3)) * b), Invalid_input);
  REQUIRE_THROWS_AS(goldman_resolvent(t * t, t, PQ(Q(1))), Invalid_input);
}

TEST_CASE("Goldman resolvent of rational space cubics (du-1989 eq. 4.2/4.3)", "[classical][goldman]") {
  std::mt19937 rng(18);
  auto eval3 = [](const P3Q& F, const Q& x, const Q& y, const Q& z) { return F.evaluate(z).evaluate(y).evaluate(x); };
  for (int trial = 0; trial < 6; ++trial) {
    PQ C[4];  // X, Y, Z, W
    for (auto& c : C) {
      std::vector<Q> v(4);
      for (auto& a : v) a = Q(uniform(rng, -9, 9));
      if (v[3] == 0) v[3] = Q(2);
      c = PQ(v.begin(), v.end());
    }
    const auto r = goldman_rational_cubic_resolvent(C[0], C[1], C[2], C[3]);
    for (int k = 0; k < 5; ++k) {
      const Q t0(uniform(rng, -30, 30), uniform(rng, 1, 5));
      const Q w = C[3].evaluate(t0);
      if (w == 0) continue;
      const Q x = C[0].evaluate(t0) / w, y = C[1].evaluate(t0) / w, z = C[2].evaluate(t0) / w;
      REQUIRE(eval3(r.R1, x, y, z) == 0);
      REQUIRE(eval3(r.R2, x, y, z) == 0);
      REQUIRE(eval3(r.R3, x, y, z) == 0);
      // The seed's 4x4 brackets |u_i, u_j, u_k, q| (u_k = coefficients of t^k in X, Y, Z, W, q = (x, y, z, 1)).
      auto u = [&](int kk) {
        std::array<Q, 4> v;
        for (int i = 0; i < 4; ++i) v[i] = (kk <= C[i].degree()) ? C[i][kk] : Q(0);
        return v;
      };
      auto det4 = [&](const std::array<Q, 4>& c0, const std::array<Q, 4>& c1, const std::array<Q, 4>& c2) {
        const std::array<Q, 4> q = {x, y, z, Q(1)};
        std::vector<std::vector<Q>> M(4, std::vector<Q>(4));
        for (int i = 0; i < 4; ++i) {
          M[i][0] = c0[i];
          M[i][1] = c1[i];
          M[i][2] = c2[i];
          M[i][3] = q[i];
        }
        return internal::bareiss_determinant(M);
      };
      const Q b321 = det4(u(3), u(2), u(1)), b320 = det4(u(3), u(2), u(0));
      REQUIRE(eval3(r.d321, x, y, z) == b321);
      REQUIRE(eval3(r.d320, x, y, z) == b320);
      REQUIRE(eval3(r.d310, x, y, z) == det4(u(3), u(1), u(0)));
      REQUIRE(eval3(r.d210, x, y, z) == det4(u(2), u(1), u(0)));
      // Inversion: t0 = -|u3,u2,u0,q| / |u3,u2,u1,q| (eq. 3.60; the seed's 4.3 omits the minus sign).
      REQUIRE(b321 != 0);
      REQUIRE(-b320 / b321 == t0);
    }
  }
}

// -------------------------------------------------------- implicitization ----

TEST_CASE("Implicitization of rational plane curves by the Bezout matrix (du-1989 eq. 4.1)", "[classical][implicit]") {
  std::mt19937 rng(19);
  using P3 = Polynomial_1<P2Z>;  // polynomials in t over Z[x, y]
  const P2Z x = variable<P2Z>(0), y = variable<P2Z>(1);
  for (int n = 2; n <= 5; ++n)
    for (int trial = 0; trial < 3; ++trial) {
      INFO("degree " << n);
      PZ X, Y, W;
      do {
        X = random_polynomial(rng, n, 6);
        Y = random_polynomial(rng, n, 6);
        W = random_polynomial(rng, n, 6);
      } while (CGAL::gcd(CGAL::gcd(X, Y), W).degree() > 0);
      const P2Z F = Bezout_implicit_equation()(X, Y, W);

      // Same as the generic Bezout matrix (eq. 3.4) of X - x W and Y - y W over Z[x, y].
      auto lift = [&](const PZ& A, const PZ& B, const P2Z& v) {
        std::vector<P2Z> c;
        for (int i = 0; i <= n; ++i) c.push_back(P2Z(A[i]) - v * P2Z(B[i]));
        return P3(c.begin(), c.end());
      };
      const P3 Px = lift(X, W, x), Py = lift(Y, W, y);
      REQUIRE(rational_curve_bezout_matrix(X, Y, W) == bezout_matrix(Px, Py));
      // CGAL's resultant with respect to t, with the sign (-1)^{n(n+1)/2}.
      const P2Z res = cgal_resultant(Px, Py);
      REQUIRE(F == ((n * (n + 1) / 2) % 2 == 0 ? res : P2Z(-res)));
      REQUIRE(bezout_resultant(Px, Py) == res);

      // F(X/W, Y/W) = 0: sum F_ij X^i Y^j W^{n-i-j} vanishes identically.
      REQUIRE(typename CGAL::Polynomial_traits_d<P2Z>::Total_degree()(F) == n);
      PZ s(0);
      for (int j = 0; j <= F.degree(); ++j)
        for (int i = 0; !CGAL::is_zero(F[j]) && i <= F[j].degree(); ++i)
          s += PZ(F[j][i]) * CGAL::ipower(X, i) * CGAL::ipower(Y, j) * CGAL::ipower(W, n - i - j);
      REQUIRE(CGAL::is_zero(s));

      // Irreducible: F = c G^k with G the curve's minimal equation and k the
      // degree of the parametrization, so square-free of degree n means k = 1.
      typename CGAL::Polynomial_traits_d<P2Z>::Differentiate diff;
      typename CGAL::Polynomial_traits_d<P2Z>::Total_degree total_degree;
      REQUIRE(total_degree(CGAL::gcd(F, diff(F, 0))) == 0);
      REQUIRE(total_degree(CGAL::gcd(F, diff(F, 1))) == 0);
    }
  REQUIRE_THROWS_AS(bezout_implicit_equation(PZ(1), PZ(2), PZ(3)), Invalid_input);
  REQUIRE_THROWS_AS(bezout_implicit_equation(variable_t(), PZ(2), PZ(0)), Invalid_input);
}

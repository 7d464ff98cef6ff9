// Benchmark of the exact determinant of polynomial matrices and of the
// square-free part (not part of the test build). Random n x n matrices whose
// entries are dense bivariate integer polynomials of bi-degree (d,d), like the
// Bezoutian matrices of buse-elkadi-galligo-2008 (3x3 .. 9x9, bi-degree up to
// about (6,6)).
//
// Determinant, compared implementations (all answers are checked to agree):
//   engine     bezoutian::polynomial_matrix_determinant (multi-modular, proven bound)
//   flint-kr   FLINT 2.9 fmpz_poly_mat_det after the Kronecker substitution
//              u -> x, v -> x^(n d + 1) (injective on the monomials of det)
//   flint-mp   fraction-free Gaussian elimination (Bareiss, with pivoting) over
//              FLINT's sparse multivariate fmpz_mpoly
//   berkowitz  bezoutian::berkowitz_determinant over CGAL::Polynomial (skipped
//              when too slow)
// Square-free part: bezoutian::normalized_square_free_part on D (square-free:
// fast path) and on D^2 (certified modular path) vs FLINT's
// fmpz_mpoly_factor_squarefree.
//
// Build by hand from the project root (see doc/determinant.md):
//   g++ -std=c++17 -O2 -DNDEBUG -DCGAL_USE_GMP -DCGAL_USE_MPFI -Iinclude \
//       benchmark/determinant_benchmark.cpp -o determinant_benchmark -lflint -lmpfi -lmpfr -lgmp
// Run: ./determinant_benchmark [max_berkowitz_seconds=5]
// Times are the minimum over several runs (the machine may be shared).
#include <bezoutian/elimination/Polynomial_matrix_determinant.h>
#include <bezoutian/algebraic/Polynomial_normalization.h>

#include <flint/fmpz.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_mpoly_factor.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_mat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using bezoutian::Integer;
using P1 = bezoutian::Polynomial_1<Integer>;
using P2 = bezoutian::Polynomial_2<Integer>;
using Matrix = std::vector<std::vector<P2>>;

static Matrix random_matrix(int n, int d, int bits, std::mt19937_64& gen) {
  std::uniform_int_distribution<long> coef(-(1L << bits) + 1, (1L << bits) - 1);
  Matrix M(n, std::vector<P2>(n));
  for (auto& row : M)
    for (auto& e : row) {
      std::vector<P1> rows;
      for (int l = 0; l <= d; ++l) {
        std::vector<Integer> c;
        for (int k = 0; k <= d; ++k) c.push_back(Integer(coef(gen)));
        rows.emplace_back(c.begin(), c.end());
      }
      e = P2(rows.begin(), rows.end());
    }
  return M;
}

// Minimum wall time of f over `repeat` runs, in seconds.
template <class F> static double seconds(F&& f, int repeat) {
  double best = 1e30;
  for (int r = 0; r < repeat; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    f();
    auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
  }
  return best;
}

// ---- FLINT, Kronecker substitution v -> x^S, S = Du + 1 -------------------
static P2 flint_kronecker_determinant(const Matrix& M, long Du) {
  const long n = long(M.size()), S = Du + 1;
  fmpz_poly_mat_t A;
  fmpz_poly_mat_init(A, n, n);
  fmpz_t c;
  fmpz_init(c);
  for (long i = 0; i < n; ++i)
    for (long j = 0; j < n; ++j) {
      fmpz_poly_struct* e = fmpz_poly_mat_entry(A, i, j);
      const P2& f = M[i][j];
      for (int l = 0; l <= f.degree(); ++l)
        for (int k = 0; k <= f[l].degree(); ++k) {
          fmpz_set_mpz(c, f[l][k].mpz());
          fmpz_poly_set_coeff_fmpz(e, l * S + k, c);
        }
    }
  fmpz_poly_t d;
  fmpz_poly_init(d);
  fmpz_poly_mat_det(d, A);
  const long len = fmpz_poly_length(d);
  std::vector<P1> rows;
  mpz_t z;
  mpz_init(z);
  for (long base = 0; base < len; base += S) {
    std::vector<Integer> cs;
    for (long k = 0; k < S && base + k < len; ++k) {
      fmpz_poly_get_coeff_fmpz(c, d, base + k);
      fmpz_get_mpz(z, c);
      cs.push_back(Integer(z));
    }
    rows.emplace_back(cs.begin(), cs.end());
  }
  mpz_clear(z);
  fmpz_poly_clear(d);
  fmpz_clear(c);
  fmpz_poly_mat_clear(A);
  if (rows.empty()) return P2(0);
  return P2(rows.begin(), rows.end());
}

// ---- FLINT fmpz_mpoly (variables x0 = u, x1 = v) -------------------------
static void to_mpoly(fmpz_mpoly_t out, const P2& f, const fmpz_mpoly_ctx_t ctx) {
  fmpz_mpoly_zero(out, ctx);
  fmpz_t c;
  fmpz_init(c);
  ulong exp[2];
  for (int l = 0; l <= f.degree(); ++l)
    for (int k = 0; k <= f[l].degree(); ++k) {
      if (CGAL::is_zero(f[l][k])) continue;
      fmpz_set_mpz(c, f[l][k].mpz());
      exp[0] = ulong(k), exp[1] = ulong(l);
      fmpz_mpoly_set_coeff_fmpz_ui(out, c, exp, ctx);
    }
  fmpz_clear(c);
}

static P2 from_mpoly(const fmpz_mpoly_t f, const fmpz_mpoly_ctx_t ctx) {
  const slong len = fmpz_mpoly_length(f, ctx);
  if (len == 0) return P2(0);
  ulong exp[2];
  int du = 0, dv = 0;
  for (slong t = 0; t < len; ++t) {
    fmpz_mpoly_get_term_exp_ui(exp, f, t, ctx);
    du = std::max(du, int(exp[0])), dv = std::max(dv, int(exp[1]));
  }
  std::vector<std::vector<Integer>> c(dv + 1, std::vector<Integer>(du + 1, Integer(0)));
  fmpz_t a;
  fmpz_init(a);
  mpz_t z;
  mpz_init(z);
  for (slong t = 0; t < len; ++t) {
    fmpz_mpoly_get_term_exp_ui(exp, f, t, ctx);
    fmpz_mpoly_get_term_coeff_fmpz(a, f, t, ctx);
    fmpz_get_mpz(z, a);
    c[exp[1]][exp[0]] = Integer(z);
  }
  mpz_clear(z);
  fmpz_clear(a);
  std::vector<P1> rows;
  for (auto& r : c) rows.emplace_back(r.begin(), r.end());
  return P2(rows.begin(), rows.end());
}

// Bareiss: a_ij <- (a_kk a_ij - a_ik a_kj) / a_{k-1,k-1}, exact; row swaps on zero pivots.
static P2 flint_bareiss_determinant(const Matrix& M) {
  const slong n = slong(M.size());
  fmpz_mpoly_ctx_t ctx;
  fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
  std::vector<fmpz_mpoly_struct> a(n * n);
  for (slong i = 0; i < n; ++i)
    for (slong j = 0; j < n; ++j) {
      fmpz_mpoly_init(&a[i * n + j], ctx);
      to_mpoly(&a[i * n + j], M[i][j], ctx);
    }
  fmpz_mpoly_t prev, t1, t2;
  fmpz_mpoly_init(prev, ctx), fmpz_mpoly_init(t1, ctx), fmpz_mpoly_init(t2, ctx);
  fmpz_mpoly_one(prev, ctx);
  bool negate = false, zero = false;
  for (slong k = 0; k < n && !zero; ++k) {
    slong r = k;
    while (r < n && fmpz_mpoly_is_zero(&a[r * n + k], ctx)) ++r;
    if (r == n) {
      zero = true;
      break;
    }
    if (r != k) {
      for (slong j = 0; j < n; ++j) fmpz_mpoly_swap(&a[r * n + j], &a[k * n + j], ctx);
      negate = !negate;
    }
    for (slong i = k + 1; i < n; ++i)
      for (slong j = k + 1; j < n; ++j) {
        fmpz_mpoly_mul(t1, &a[k * n + k], &a[i * n + j], ctx);
        fmpz_mpoly_mul(t2, &a[i * n + k], &a[k * n + j], ctx);
        fmpz_mpoly_sub(t1, t1, t2, ctx);
        fmpz_mpoly_divides(&a[i * n + j], t1, prev, ctx);
      }
    fmpz_mpoly_set(prev, &a[k * n + k], ctx);
  }
  P2 result = zero ? P2(0) : from_mpoly(&a[(n - 1) * n + (n - 1)], ctx);
  if (negate) result = -result;
  fmpz_mpoly_clear(prev, ctx), fmpz_mpoly_clear(t1, ctx), fmpz_mpoly_clear(t2, ctx);
  for (auto& e : a) fmpz_mpoly_clear(&e, ctx);
  fmpz_mpoly_ctx_clear(ctx);
  return result;
}

static P2 flint_square_free_part(const P2& D) {
  fmpz_mpoly_ctx_t ctx;
  fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
  fmpz_mpoly_t A, S;
  fmpz_mpoly_init(A, ctx), fmpz_mpoly_init(S, ctx);
  to_mpoly(A, D, ctx);
  fmpz_mpoly_factor_t f;
  fmpz_mpoly_factor_init(f, ctx);
  fmpz_mpoly_factor_squarefree(f, A, ctx);
  fmpz_mpoly_one(S, ctx);
  for (slong i = 0; i < f->num; ++i) fmpz_mpoly_mul(S, S, f->poly + i, ctx);
  P2 result = from_mpoly(S, ctx);
  fmpz_mpoly_factor_clear(f, ctx);
  fmpz_mpoly_clear(A, ctx), fmpz_mpoly_clear(S, ctx);
  fmpz_mpoly_ctx_clear(ctx);
  return bezoutian::normalized_primitive_part(result);
}

static std::size_t max_bits(const P2& D) {
  std::size_t b = 0;
  for (const P1& r : D)
    for (const Integer& x : r) b = std::max(b, x.bit_size());
  return b;
}

int main(int argc, char** argv) {
  const double max_berkowitz = argc > 1 ? std::atof(argv[1]) : 5.0;
  std::mt19937_64 gen(20261122);
  const int bits = 12; // coefficients in (-2^12, 2^12)
  std::printf("Determinant of random n x n matrices, entries dense of bi-degree (d,d), %d-bit coefficients\n", bits);
  std::printf("times in ms (minimum of several runs); ratios = other / engine\n");
  std::printf("%2s %2s %9s %5s %10s %10s %10s %10s %9s %9s %9s\n", "n", "d", "det bideg", "bits", "engine",
              "flint-kr", "flint-mp", "berkowitz", "kr/eng", "mp/eng", "berk/eng");
  double berk[16][16] = {{0}}; // Berkowitz seconds per (n,d); 1e9 = skipped
  std::vector<P2> keep;        // a few determinants for the square-free benchmark
  for (int d = 3; d <= 6; ++d)
    for (int n = 3; n <= 9; ++n) {
      const Matrix M = random_matrix(n, d, bits, gen);
      const int rep = n <= 6 ? 7 : 4;
      P2 D, F, B;
      const double te = seconds([&] { D = bezoutian::polynomial_matrix_determinant(M); }, rep);
      const double tk = seconds([&] { F = flint_kronecker_determinant(M, long(n) * d); }, rep);
      if (F != D) std::printf("MISMATCH engine/flint-kr n=%d d=%d\n", n, d);
      const double tm = seconds([&] { F = flint_bareiss_determinant(M); }, n <= 6 ? 3 : 1);
      if (F != D) std::printf("MISMATCH engine/flint-mp n=%d d=%d\n", n, d);
      // Berkowitz only while its predicted cost (from the neighbours (n-1,d) and (n,d-1)) stays small.
      double tb = -1;
      if (berk[n - 1][d] * 6 < max_berkowitz && berk[n][d - 1] * 6 < max_berkowitz) {
        tb = seconds([&] { B = bezoutian::berkowitz_determinant(M); }, 1);
        if (B != D) std::printf("MISMATCH engine/berkowitz n=%d d=%d\n", n, d);
      }
      berk[n][d] = tb < 0 ? 1e9 : tb;
      int du = 0;
      for (const P1& r : D) du = std::max(du, r.degree());
      char bideg[32], tbs[32], rbs[32];
      std::snprintf(bideg, sizeof bideg, "(%d,%d)", du, D.degree());
      std::snprintf(tbs, sizeof tbs, tb < 0 ? "-" : "%.1f", tb * 1e3);
      std::snprintf(rbs, sizeof rbs, tb < 0 ? "-" : "%.0f", tb / te);
      std::printf("%2d %2d %9s %5zu %10.2f %10.2f %10.1f %10s %9.1f %9.1f %9s\n", n, d, bideg, max_bits(D), te * 1e3,
                  tk * 1e3, tm * 1e3, tbs, tk / te, tm / te, rbs);
      std::fflush(stdout);
      if (n == d + 3 || (n == 9 && d == 6)) keep.push_back(D);
    }

  std::printf("\nSquare-free part (normalized): D square-free (fast path) and D^2 (certified modular path)\n");
  std::printf("%9s %10s %10s %12s %12s\n", "bideg D", "D: ours", "D: flint", "D^2: ours", "D^2: flint");
  for (const P2& D : keep) {
    const P2 D2 = D * D, pD = bezoutian::normalized_primitive_part(D);
    P2 S;
    const double a = seconds([&] { S = bezoutian::normalized_square_free_part(D); }, 3);
    if (S != pD) std::printf("MISMATCH square-free part of D\n");
    const double b = seconds([&] { S = flint_square_free_part(D); }, 3);
    if (S != pD) std::printf("MISMATCH flint square-free part of D\n");
    const double c = seconds([&] { S = bezoutian::normalized_square_free_part(D2); }, 2);
    if (S != pD) std::printf("MISMATCH square-free part of D^2\n");
    const double e = seconds([&] { S = flint_square_free_part(D2); }, 2);
    if (S != pD) std::printf("MISMATCH flint square-free part of D^2\n");
    int du = 0;
    for (const P1& r : D) du = std::max(du, r.degree());
    char bideg[32];
    std::snprintf(bideg, sizeof bideg, "(%d,%d)", du, D.degree());
    std::printf("%9s %10.2f %10.2f %12.1f %12.1f\n", bideg, a * 1e3, b * 1e3, c * 1e3, e * 1e3);
    std::fflush(stdout);
  }
  return 0;
}

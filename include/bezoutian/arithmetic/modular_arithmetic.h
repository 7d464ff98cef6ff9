// Word-size modular arithmetic for the multi-modular exact algorithms
// (determinants of polynomial matrices): Montgomery multiplication modulo
// primes p < 2^62, a deterministic 64-bit primality test, a table of word
// primes, and Chinese remaindering (Garner) back to CGAL::Gmpz.
//
// Internal header: not part of the public API.
#ifndef BEZOUTIAN_ARITHMETIC_MODULAR_ARITHMETIC_H
#define BEZOUTIAN_ARITHMETIC_MODULAR_ARITHMETIC_H

#include <CGAL/Gmpz.h>
#include <gmp.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <mutex>
#include <vector>

#if !defined(__SIZEOF_INT128__)
#error "bezoutian/internal/modular_arithmetic.h needs unsigned __int128 (GCC or Clang on a 64-bit target)"
#endif

namespace bezoutian {
namespace internal {

using u64 = std::uint64_t;
using u128 = unsigned __int128;

/// Arithmetic modulo an odd prime p < 2^62 in Montgomery form (R = 2^64):
/// a residue x is stored as x*R mod p, so that a product needs two word
/// multiplications and no division. Because p < 2^62, a sum of two products
/// (as in a step of Gaussian elimination) is < 2p^2 < p 2^64 and needs a
/// single reduction.
class Montgomery_modulus {
public:
  explicit Montgomery_modulus(u64 p) : p_(p) {
    if (p < 3 || p % 2 == 0 || (p >> 62) != 0)
      throw std::invalid_argument("Montgomery_modulus: need an odd modulus 3 <= p < 2^62");
    // Newton iteration for p^{-1} mod 2^64 (each step doubles the correct bits).
    u64 inv = p; // correct to 3 bits since p*p = 1 mod 8
    for (int i = 0; i < 5; ++i) inv *= 2 - p * inv;
    neg_inv_ = ~inv + 1; // -p^{-1} mod 2^64
    r_mod_ = static_cast<u64>((static_cast<u128>(1) << 64) % p);
    r2_mod_ = static_cast<u64>((static_cast<u128>(r_mod_) * r_mod_) % p);
  }

  u64 modulus() const { return p_; }

  /// Montgomery reduction: T*R^{-1} mod p, for T < p*2^64; result in [0,p).
  u64 reduce(u128 T) const {
    u64 m = static_cast<u64>(T) * neg_inv_;
    u64 t = static_cast<u64>((T + static_cast<u128>(m) * p_) >> 64);
    return t >= p_ ? t - p_ : t;
  }
  /// Product of two Montgomery residues.
  u64 mul(u64 a, u64 b) const { return reduce(static_cast<u128>(a) * b); }
  u64 add(u64 a, u64 b) const { u64 s = a + b; return s >= p_ ? s - p_ : s; }
  u64 sub(u64 a, u64 b) const { return a >= b ? a - b : a + p_ - b; }
  u64 neg(u64 a) const { return a == 0 ? 0 : p_ - a; }

  /// Plain residue x in [0,p) to Montgomery form.
  u64 to_montgomery(u64 x) const { return mul(x % p_, r2_mod_); }
  /// Montgomery form back to the plain residue in [0,p).
  u64 from_montgomery(u64 x) const { return reduce(x); }
  /// Montgomery form of 1.
  u64 one() const { return r_mod_; }

  /// Montgomery form of z mod p (any sign).
  u64 to_montgomery(const CGAL::Gmpz& z) const {
    // mpz_fdiv_ui gives the non-negative remainder; unsigned long is 64-bit on LP64.
    if (sizeof(unsigned long) >= sizeof(u64))
      return to_montgomery(static_cast<u64>(mpz_fdiv_ui(z.mpz(), static_cast<unsigned long>(p_))));
    CGAL::Gmpz pz = gmpz_from_u64(p_), r;
    mpz_fdiv_r(r.mpz(), z.mpz(), pz.mpz());
    return to_montgomery(u64_from_gmpz(r));
  }

  u64 pow(u64 a, u64 e) const {
    u64 r = one();
    while (e) {
      if (e & 1) r = mul(r, a);
      a = mul(a, a);
      e >>= 1;
    }
    return r;
  }
  /// Inverse of a nonzero Montgomery residue (Fermat: a^(p-2), p prime).
  u64 inverse(u64 a) const { return pow(a, p_ - 2); }

  static CGAL::Gmpz gmpz_from_u64(u64 x) {
    CGAL::Gmpz z;
    mpz_import(z.mpz(), 1, -1, sizeof(u64), 0, 0, &x);
    return z;
  }
  static u64 u64_from_gmpz(const CGAL::Gmpz& z) { // 0 <= z < 2^64
    u64 x = 0;
    mpz_export(&x, nullptr, -1, sizeof(u64), 0, 0, z.mpz());
    return x;
  }

private:
  u64 p_, neg_inv_, r_mod_, r2_mod_;
};

/// (a*b) mod m by 128-bit division; used only by the primality test.
inline u64 mulmod_u64(u64 a, u64 b, u64 m) {
  return static_cast<u64>((static_cast<u128>(a) * b) % m);
}

/// Deterministic Miller-Rabin for 64-bit integers: the first twelve primes as
/// bases are known to be a complete witness set below 3.3*10^24 > 2^64
/// (Sorenson and Webster 2015).
inline bool is_prime_u64(u64 n) {
  static const u64 small[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37};
  if (n < 2) return false;
  for (u64 q : small) {
    if (n == q) return true;
    if (n % q == 0) return false;
  }
  u64 d = n - 1;
  int s = 0;
  while ((d & 1) == 0) { d >>= 1; ++s; }
  for (u64 a : small) {
    u64 x = 1, b = a % n, e = d;
    while (e) {
      if (e & 1) x = mulmod_u64(x, b, n);
      b = mulmod_u64(b, b, n);
      e >>= 1;
    }
    if (x == 1 || x == n - 1) continue;
    bool composite = true;
    for (int r = 1; r < s; ++r) {
      x = mulmod_u64(x, x, n);
      if (x == n - 1) { composite = false; break; }
    }
    if (composite) return false;
  }
  return true;
}

/// The i-th prime below 2^62 in decreasing order (i = 0 is the largest). Each is found once and kept (thread-safe).
inline u64 word_prime(std::size_t i) {
  // computed once, in order, and kept: callers ask for primes 0, 1, 2, ... in loops (the determinant engine, the
  // square-free part), so a search from the start on each call would cost quadratically in the number of primes;
  // the mutex makes concurrent callers safe (each prime below 2^62 costs one deterministic Miller-Rabin test per
  // odd candidate, about 1 in 43 candidates being prime)
  static std::mutex mutex;
  static std::vector<u64> primes;
  std::lock_guard<std::mutex> lock(mutex);
  if (primes.empty()) primes.reserve(1024);
  for (u64 c = primes.empty() ? (static_cast<u64>(1) << 62) - 1 : primes.back() - 2; primes.size() <= i; c -= 2)
    if (is_prime_u64(c)) primes.push_back(c);
  return primes[i];
}

/// Chinese remaindering for many values modulo the same primes p_0..p_{k-1}
/// (Garner's mixed-radix method): the result is the symmetric representative
/// in (-P/2, P/2], P = p_0 ... p_{k-1}.
class Chinese_remainder {
public:
  explicit Chinese_remainder(const std::vector<u64>& primes) : primes_(primes) {
    const std::size_t k = primes_.size();
    mods_.reserve(k);
    for (u64 p : primes_) mods_.emplace_back(p);
    // c_i = (p_0 ... p_{i-1})^{-1} mod p_i, in Montgomery form modulo p_i.
    inv_prefix_.assign(k, 0);
    for (std::size_t i = 0; i < k; ++i) {
      const Montgomery_modulus& M = mods_[i];
      u64 prod = M.one();
      for (std::size_t j = 0; j < i; ++j) prod = M.mul(prod, M.to_montgomery(primes_[j]));
      inv_prefix_[i] = M.inverse(prod);
    }
    P_ = CGAL::Gmpz(1);
    for (u64 p : primes_) P_ *= Montgomery_modulus::gmpz_from_u64(p);
    // CGAL::Gmpz shares its representation between copies and mpz() gives
    // write access without copy-on-write: write only into fresh objects.
    half_P_ = CGAL::Gmpz();
    mpz_fdiv_q_2exp(half_P_.mpz(), P_.mpz(), 1);
  }

  const CGAL::Gmpz& product() const { return P_; }

  /// residues[i] is the plain residue modulo primes[i]; writes the symmetric
  /// representative into out.
  void combine(const u64* residues, CGAL::Gmpz& out) const {
    const std::size_t k = primes_.size();
    digits_.resize(k);
    for (std::size_t i = 0; i < k; ++i) {
      const Montgomery_modulus& M = mods_[i];
      // Evaluate y_0 + y_1 p_0 + ... + y_{i-1} p_0...p_{i-2} modulo p_i (Horner).
      u64 acc = 0;
      for (std::size_t j = i; j-- > 0;)
        acc = M.add(M.mul(acc, M.to_montgomery(primes_[j])), M.to_montgomery(digits_[j]));
      u64 y = M.mul(M.sub(M.to_montgomery(residues[i]), acc), inv_prefix_[i]);
      digits_[i] = M.from_montgomery(y);
    }
    // X = y_0 + p_0 (y_1 + p_1 (y_2 + ...)).
    out = CGAL::Gmpz(0); // fresh representation (out may share one with other copies)
    for (std::size_t i = k; i-- > 0;) {
      if (i + 1 < k) mul_u64(out, primes_[i]);
      add_u64(out, digits_[i]);
    }
    if (out > half_P_) out -= P_;
  }

private:
  static void mul_u64(CGAL::Gmpz& z, u64 x) {
    if (sizeof(unsigned long) >= sizeof(u64)) mpz_mul_ui(z.mpz(), z.mpz(), static_cast<unsigned long>(x));
    else z *= Montgomery_modulus::gmpz_from_u64(x);
  }
  static void add_u64(CGAL::Gmpz& z, u64 x) {
    if (sizeof(unsigned long) >= sizeof(u64)) mpz_add_ui(z.mpz(), z.mpz(), static_cast<unsigned long>(x));
    else z += Montgomery_modulus::gmpz_from_u64(x);
  }

  std::vector<u64> primes_;
  std::vector<Montgomery_modulus> mods_;
  std::vector<u64> inv_prefix_;
  CGAL::Gmpz P_, half_P_;
  mutable std::vector<u64> digits_;
};

/// Chinese remaindering one prime at a time, for algorithms that stop when
/// the result is certified a posteriori. The values are kept as symmetric
/// representatives x_i, |x_i| <= P/2: with a new prime p,
/// x <- x + P d, d = (r - x) P^{-1} mod p taken in (-p/2, p/2), so that the
/// result is again symmetric modulo P p, and unchanged iff r = x mod p.
class Incremental_chinese_remainder {
public:
  explicit Incremental_chinese_remainder(std::size_t count = 0) : values_(count), P_(1) {}

  std::size_t size() const { return values_.size(); }
  std::size_t number_of_primes() const { return primes_; }
  const CGAL::Gmpz& product() const { return P_; }

  /// Adds the plain residues r[0..size) modulo the prime p (not yet used).
  /// Returns true if no value changed (the reconstruction is stable).
  bool add(u64 p, const std::vector<u64>& r) {
    const Montgomery_modulus M(p);
    const u64 inv_P = M.inverse(M.to_montgomery(P_));
    bool stable = true;
    for (std::size_t i = 0; i < values_.size(); ++i) {
      const u64 x = M.to_montgomery(values_[i]);
      const u64 d = M.from_montgomery(M.mul(M.sub(M.to_montgomery(r[i]), x), inv_P));
      if (d == 0) continue;
      stable = false;
      CGAL::Gmpz t; // fresh object: CGAL::Gmpz copies share their mpz_t
      if (d > p / 2) {
        t = Montgomery_modulus::gmpz_from_u64(p - d);
        mpz_neg(t.mpz(), t.mpz());
      } else {
        t = Montgomery_modulus::gmpz_from_u64(d);
      }
      mpz_mul(t.mpz(), t.mpz(), P_.mpz());
      values_[i] += t;
    }
    P_ *= Montgomery_modulus::gmpz_from_u64(p);
    ++primes_;
    return stable;
  }

  /// The representative of value i, of absolute value at most P/2.
  const CGAL::Gmpz& symmetric(std::size_t i) const { return values_[i]; }

private:
  std::vector<CGAL::Gmpz> values_;
  CGAL::Gmpz P_;
  std::size_t primes_ = 0;
};

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_ARITHMETIC_MODULAR_ARITHMETIC_H

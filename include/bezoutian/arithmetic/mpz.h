// An owning handle of one GMP integer, for the algorithms written directly on mpz_t (root isolation, continued
// fractions): unlike CGAL::Gmpz it never shares its value, so writing through get() is always safe.
#ifndef BEZOUTIAN_ARITHMETIC_MPZ_H
#define BEZOUTIAN_ARITHMETIC_MPZ_H

#include <gmp.h>

namespace bezoutian {
namespace internal {

/// RAII owner of one mpz_t that can live in a std::vector (moves swap).
class Mpz {
 public:
  Mpz() { mpz_init(v_); }
  explicit Mpz(long x) { mpz_init_set_si(v_, x); }
  explicit Mpz(mpz_srcptr x) { mpz_init_set(v_, x); }
  Mpz(const Mpz& o) { mpz_init_set(v_, o.v_); }
  Mpz(Mpz&& o) noexcept { mpz_init(v_); mpz_swap(v_, o.v_); }
  Mpz& operator=(const Mpz& o) { mpz_set(v_, o.v_); return *this; }
  Mpz& operator=(Mpz&& o) noexcept { mpz_swap(v_, o.v_); return *this; }
  ~Mpz() { mpz_clear(v_); }
  mpz_ptr get() { return v_; }
  mpz_srcptr get() const { return v_; }
  int sign() const { return mpz_sgn(v_); }

 private:
  mpz_t v_;
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ARITHMETIC_MPZ_H

// Exact real algebraic numbers: a rational, or the unique root of a
// square-free primitive integer polynomial in an open isolating interval with
// rational ends. All predicates are decided exactly (signs of integer
// polynomials at rationals, gcds of polynomials); floating point is used only
// as a filter (CGAL::Interval_nt) or to propose refinements (Newton in MPFR)
// that are then checked exactly. See doc/algebraic_numbers.md.
#ifndef BEZOUTIAN_ALGEBRAIC_ALGEBRAIC_REAL_H
#define BEZOUTIAN_ALGEBRAIC_ALGEBRAIC_REAL_H

#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arithmetic/number_types.h>
#include <bezoutian/algebraic/bernstein_descartes.h>
#include <bezoutian/algebraic/internal/bernstein_descartes_support.h>

#include <CGAL/Interval_nt.h>

#include <mpfi.h>

#include <algorithm>
#include <memory>
#include <mutex>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace bezoutian {

namespace internal {
struct Algebraic_real_access;

/// The square-free factors (canonical, pairwise coprime) of a nonzero integer polynomial, with shared coefficient
/// vectors: the exact data that lazily known numbers materialize from (one per eliminant, shared by its roots).
struct Lazy_eliminant {
  struct Factor {
    Polynomial_1<Integer> poly;
    std::shared_ptr<const Mpz_vector> c;   // its coefficients (shared by the numbers it defines)
    std::vector<Rational> rational_roots;  // rational roots found so far
    bool others_irrational = false;        // proved: no rational root besides rational_roots
  };
  std::vector<Factor> factors;
  explicit Lazy_eliminant(const Polynomial_1<Integer>& f) {
    for (const auto& fm : square_free_factors(canonical_integer(f)))
      factors.push_back(Factor{fm.first, std::make_shared<const Mpz_vector>(coefficients_of(fm.first)), {}, false});
    add_rational_candidates({});
  }
  /// Keeps the candidates that are roots (exact signs), divides them out and tries to prove by the modular test
  /// (has_no_rational_root_modular) that no other rational root is left, so that materialized roots need not be
  /// refined to width 1/lc^2 to be shown irrational (the rational root test of resolve_rationality).
  void add_rational_candidates(const std::vector<Rational>& candidates) {
    for (Factor& f : factors) {
      if (f.poly.degree() < 2) {
        f.others_irrational = true;
        continue;
      }
      for (const Rational& q : candidates)
        if (std::find(f.rational_roots.begin(), f.rational_roots.end(), q) == f.rational_roots.end() &&
            sign_at(*f.c, q) == 0)
          f.rational_roots.push_back(q);
      Mpz_vector h = *f.c;
      for (const Rational& q : f.rational_roots) {  // h <- h / (den x - num), exact
        mpz_srcptr p = mpq_numref(q.mpq()), d = mpq_denref(q.mpq());
        const int n = static_cast<int>(h.size()) - 1;
        Mpz_vector r(n);
        Mpz t;
        mpz_divexact(r[n - 1].get(), h[n].get(), d);
        for (int i = n - 1; i >= 1; --i) {
          mpz_mul(t.get(), p, r[i].get());
          mpz_add(t.get(), t.get(), h[i].get());
          mpz_divexact(r[i - 1].get(), t.get(), d);
        }
        h.swap(r);
      }
      f.others_irrational = h.size() < 3 || has_no_rational_root_modular(h);
    }
  }
};

/// Sign of the derivative of the polynomial c on the closed interval [lo, hi] (MPFI Horner, outward rounding,
/// precision above the coefficient sizes); 0 if the enclosure contains 0.
inline int derivative_sign_on(const Mpz_vector& c, const Rational& lo, const Rational& hi) {
  const int n = static_cast<int>(c.size()) - 1;
  if (n < 1) return 0;
  std::size_t bits = 0;
  for (const Mpz& x : c) bits = std::max<std::size_t>(bits, mpz_sizeinbase(x.get(), 2));
  const mpfr_prec_t prec = static_cast<mpfr_prec_t>(bits + 2 * mpz_sizeinbase(mpq_denref(lo.mpq()), 2) + 128);
  mpfi_t x, r;
  mpfi_init2(x, prec);
  mpfi_init2(r, prec);
  mpfi_interv_q(x, lo.mpq(), hi.mpq());
  Mpz t;
  mpz_mul_ui(t.get(), c[n].get(), static_cast<unsigned long>(n));
  mpfi_set_z(r, t.get());
  for (int i = n - 1; i >= 1; --i) {
    mpfi_mul(r, r, x);
    mpz_mul_ui(t.get(), c[i].get(), static_cast<unsigned long>(i));
    mpfi_add_z(r, r, t.get());
  }
  const int s = mpfi_is_strictly_pos(r) > 0 ? 1 : (mpfi_is_strictly_neg(r) > 0 ? -1 : 0);
  mpfi_clear(x);
  mpfi_clear(r);
  return s;
}

/// Origin of numbers that are first known by a closed rational enclosure proved to contain them (e.g. a Krawczyk
/// box of a curve intersection) and made exact on demand (Algebraic_real's lazy representation). A source serves
/// several numbers, told apart by `index`.
class Lazy_real_source {
 public:
  virtual ~Lazy_real_source() {}
  /// Held by Algebraic_real around every call of eliminant() and contract(): the numbers of one source may be used
  /// from several threads, and these calls update the source's shared state. Taken after the numbers' own mutexes,
  /// never before them, so an implementation must not call members of the numbers it serves.
  std::mutex mutex;
  /// A nonzero polynomial (square-free factors) of which number `index` is a root; computed once and shared.
  virtual const Lazy_eliminant& eliminant(int index) = 0;
  /// Shrinks the closed enclosure [lo, hi] of number `index` (it keeps containing the number) towards width <= w;
  /// false if no certified progress was possible (the number is then materialized instead).
  virtual bool contract(int index, Rational& lo, Rational& hi, const Rational& w) = 0;
};
}  // namespace internal

/// A real algebraic number, represented exactly.
///
/// Either an exact rational, or the unique real root of a square-free,
/// primitive integer polynomial `polynomial()` (positive leading coefficient,
/// degree >= 2, not necessarily irreducible) inside the open interval
/// (`lower()`, `upper()`), whose ends are rationals that are not roots.
///
/// Rational numbers are always recognised: the constructors and
/// isolate_real_roots() turn every rational root into an exact rational, so
/// `is_rational()` is the mathematical predicate.
///
/// Copies share their representation (like CGAL handles): refining one copy
/// refines all. Refinement happens inside const member functions (the
/// number does not change, only its representation), under a mutex of the
/// representation: every const member may be called from several threads at
/// once, on one object or on copies (doc/algebraic_numbers.md, "Threads").
///
/// Exact on demand: a number may also be *lazy*, known first only by a closed
/// rational enclosure [lo, hi] proved to contain it and a shared source
/// (internal::Lazy_real_source) able to contract the enclosure and to give a
/// polynomial vanishing at it (e.g. intersect_curves' planar default path).
/// to_interval(), to_double(), to_decimal_string(), compare() and sign() use
/// (and contract) the enclosure while it decides; every member that needs the
/// exact representation (is_rational(), rational_value(), polynomial(),
/// lower(), upper(), sign_at_lower(), refine(), refine_to_width(), sign_of(),
/// rational_between(), negated(), operator<<, and compare() when the
/// enclosures cannot separate the numbers) materializes it first: the root of
/// the source's polynomial in [lo, hi], the enclosure contracted until it
/// holds only one root, rational roots recognised as above.
class Algebraic_real {
 public:
  /// Zero.
  Algebraic_real() : Algebraic_real(Rational(0)) {}
  Algebraic_real(int i) : Algebraic_real(Rational(i)) {}
  Algebraic_real(const Integer& z) : Algebraic_real(Rational(z)) {}
  /// The exact rational q.
  Algebraic_real(const Rational& q) : rep_(std::make_shared<Rep>()) { rep_->set_exact(q); }

  /// The unique real root of `poly` in the CLOSED interval [lo, hi] (lo <= hi).
  /// `poly` need not be square-free or primitive: it is factored
  /// (square-free) and the factor holding the root becomes the defining
  /// polynomial. Throws Invalid_input if poly is zero, lo > hi, or
  /// [lo, hi] holds no root or more than one distinct root.
  Algebraic_real(const Polynomial_1<Integer>& poly, const Rational& lo, const Rational& hi)
      : rep_(std::make_shared<Rep>()) {
    construct(poly, lo, hi);
  }
  /// Same, for rational coefficients.
  Algebraic_real(const Polynomial_1<Rational>& poly, const Rational& lo, const Rational& hi)
      : rep_(std::make_shared<Rep>()) {
    construct(internal::integer_multiple(poly), lo, hi);
  }

  /// True iff the number is rational (exact predicate, see the class comment).
  bool is_rational() const {
    Lock lock(rep_->mutex);
    rep_->materialize_if_lazy();
    return rep_->exact;
  }
  /// True while the number is known only by its enclosure (see the class comment).
  bool is_lazy() const {
    Lock lock(rep_->mutex);
    return bool(rep_->src);
  }
  /// A closed interval [first, second] containing the number, without materializing: the enclosure of a lazy
  /// number, otherwise the isolating interval (open, irrational numbers) or the value twice (rationals).
  std::pair<Rational, Rational> enclosure() const {
    Lock lock(rep_->mutex);
    return {rep_->lo, rep_->hi};
  }
  /// Makes a lazy number exact (no effect otherwise).
  void materialize() const {
    Lock lock(rep_->mutex);
    rep_->materialize_if_lazy();
  }
  /// The value, if is_rational(); throws Invalid_input otherwise.
  Rational rational_value() const {
    Lock lock(rep_->mutex);
    rep_->materialize_if_lazy();
    if (!rep_->exact) throw Invalid_input("Algebraic_real::rational_value(): the number is irrational");
    return rep_->lo;
  }

  /// Defining polynomial: square-free, primitive, positive leading
  /// coefficient; q x - p for the rational p/q. It may be replaced by a
  /// divisor when comparisons discover a common factor. Returned as a copy
  /// of its own (CGAL::Polynomial's reference count is not atomic).
  Polynomial_1<Integer> polynomial() const {
    Lock lock(rep_->mutex);
    rep_->materialize_if_lazy();
    return internal::unshared_copy(rep_->poly);
  }
  /// Ends of the isolating interval (both equal to the value for rationals). Materializes a lazy number
  /// (enclosure() gives the enclosure without doing so).
  Rational lower() const {
    Lock lock(rep_->mutex);
    rep_->materialize_if_lazy();
    return rep_->lo;
  }
  Rational upper() const {
    Lock lock(rep_->mutex);
    rep_->materialize_if_lazy();
    return rep_->hi;
  }
  /// Sign of polynomial() at lower() (0 for rationals).
  int sign_at_lower() const {
    Lock lock(rep_->mutex);
    rep_->materialize_if_lazy();
    return rep_->exact ? 0 : rep_->sign_lo;
  }

  /// Halves the isolating interval (one bisection, exact sign at the midpoint).
  void refine() const {
    Lock lock(rep_->mutex);
    rep_->materialize_if_lazy();
    if (!rep_->exact) rep_->bisect();
  }

  /// Refines until upper() - lower() <= w (w > 0). Uses Newton steps in MPFR
  /// to propose a small interval, accepted only after exact sign checks at
  /// its ends (quadratic convergence), with bisection as the fallback.
  void refine_to_width(const Rational& w) const {
    if (!(w > Rational(0))) throw Invalid_input("Algebraic_real::refine_to_width: width must be positive");
    Lock lock(rep_->mutex);
    rep_->materialize_if_lazy();
    rep_->refine_to_width(w);
  }

  /// Double interval containing the number, at most a few ulps wide (refines).
  std::pair<double, double> to_interval() const {
    Lock lock(rep_->mutex);
    return rep_->to_interval();
  }
  /// The double nearest to the number (up to one ulp in the rare case it is
  /// extremely close to the midpoint between two doubles).
  double to_double() const {
    Lock lock(rep_->mutex);
    rep_->to_interval();  // refines to relative width 2^-55
    internal::Mpfr x(53);
    const Rational mid = rep_->exact ? rep_->lo : (rep_->lo + rep_->hi) / 2;  // (lazy: the enclosure's)
    mpfr_set_q(x.get(), mid.mpq(), MPFR_RNDN);
    return mpfr_get_d(x.get(), MPFR_RNDN);
  }

  /// Decimal string with `significant_digits` significant digits, correctly
  /// rounded to nearest (ties, possible only for rationals, away from zero):
  /// the interval is refined until both its ends round to the same string.
  /// Plain notation ("1.41421") when the decimal exponent E satisfies
  /// -5 <= E < significant_digits, otherwise "d.ddde<E>"; trailing zeros are kept.
  std::string to_decimal_string(int significant_digits) const {
    if (significant_digits < 1) throw Invalid_input("to_decimal_string: need at least one digit");
    Lock lock(rep_->mutex);
    Rep& r = *rep_;
    for (int extra = 4; r.src && extra <= 68; extra += 16) {  // lazy: contracted enclosure, both ends rounded
      if (!r.lazy_narrow_relative(static_cast<unsigned long>(extra + 4 * significant_digits))) break;
      const bool neg = r.hi <= Rational(0);
      auto a = internal::round_to_significant(r.lo, significant_digits);
      auto b = internal::round_to_significant(r.hi, significant_digits);
      if (a == b) return internal::format_significant(neg, a.first, a.second);
    }
    r.materialize_if_lazy();
    r.separate_from_zero();
    for (int extra = 4;; extra += 16) {
      if (r.exact) return internal::rational_to_decimal_string(r.lo, significant_digits);
      // width <= min(|lo|,|hi|) 10^-digits 2^-extra
      const Rational m = CGAL::abs(r.lo) < CGAL::abs(r.hi) ? CGAL::abs(r.lo) : CGAL::abs(r.hi);
      Rational w;  // fresh object: CGAL::Gmpq copies share their mpq_t
      internal::Mpz p10;
      mpz_ui_pow_ui(p10.get(), 10, static_cast<unsigned long>(significant_digits));
      mpz_mul_2exp(p10.get(), p10.get(), static_cast<mp_bitcnt_t>(extra));
      mpq_set_z(w.mpq(), p10.get());
      mpq_div(w.mpq(), m.mpq(), w.mpq());
      r.refine_to_width(w);
      if (r.exact) continue;
      const bool neg = r.hi <= Rational(0);
      auto a = internal::round_to_significant(r.lo, significant_digits);
      auto b = internal::round_to_significant(r.hi, significant_digits);
      if (a == b) return internal::format_significant(neg, a.first, a.second);
    }
  }

  /// Exact comparison: -1, 0 or +1 as *this <, ==, > other.
  /// Refines both intervals against each other's ends and by bisection;
  /// equality is decided by a gcd of the defining polynomials (certified
  /// multi-modular gcd, algebraic/internal/bernstein_descartes_gcd.h),
  /// after which both numbers share the smaller defining polynomial.
  int compare(const Algebraic_real& other) const {
    if (rep_ == other.rep_) return 0;
    std::scoped_lock lock(rep_->mutex, other.rep_->mutex);  // std::lock's order: no deadlock with b.compare(a)
    return compare(*rep_, *other.rep_);
  }

  /// Exact comparison with a rational (refines the interval against q).
  int compare(const Rational& q) const {
    Lock lock(rep_->mutex);
    return compare(*rep_, q);
  }

  /// Sign of the number.
  int sign() const { return compare(Rational(0)); }

  /// Exact sign of f at this number (f with Integer or Rational coefficients).
  /// Filter: interval Horner evaluation on the isolating interval; exact:
  /// a common root is detected through gcd(f, polynomial()), otherwise the
  /// interval is refined until Descartes' rule shows f has no root in it.
  template <class NT>
  int sign_of(const Polynomial_1<NT>& f) const {
    const Polynomial_1<Integer> F = internal::integer_multiple(f);  // positive multiple
    if (CGAL::is_zero(F)) return 0;
    const internal::Mpz_vector fc = internal::coefficients_of(F);
    Lock lock(rep_->mutex);
    Rep& r = *rep_;
    r.materialize_if_lazy();
    if (F.degree() == 0 || r.exact) return internal::sign_at(fc, r.lo);
    bool gcd_done = false;
    unsigned long extra_bits = 8;
    for (int round = 0;; ++round) {
      if (r.exact) return internal::sign_at(fc, r.lo);
      const int s = interval_sign(F, r.lo, r.hi);
      if (s != 0) return s;
      if (round >= 2 && !gcd_done) {
        gcd_done = true;
        const internal::Mpz_vector hc = internal::gcd_of(fc, *r.c);
        if (hc.size() >= 2) {
          const int sl = internal::sign_at(hc, r.lo), sh = internal::sign_at(hc, r.hi);
          if (sl != 0 && sh != 0 && sl != sh) return 0;
        }
      }
      if (gcd_done) {
        // Exact: if the Bernstein coefficients of F on [lo,hi] show no sign
        // change, F has no root in (lo,hi) and its sign there is theirs.
        internal::Mpz_vector G = internal::map_to_unit_interval(fc, r.lo, r.hi);
        internal::Mpz_vector bern;
        internal::Bernstein_converter(F.degree())(G, bern);
        if (internal::sign_variations(bern) == 0)
          for (const internal::Mpz& x : bern)
            if (x.sign() != 0) return x.sign();
      }
      if (!gcd_done) {
        r.bisect();
        r.bisect();
      } else {
        r.refine_to_width(shrunk_width(r.hi - r.lo, extra_bits));
        extra_bits = std::min<unsigned long>(2 * extra_bits, 1UL << 20);
      }
    }
  }

  /// A rational strictly between *this and other (which must differ;
  /// throws Invalid_input if they are equal); the simplest one
  /// available from the refined intervals.
  Rational rational_between(const Algebraic_real& other) const {
    const int c = compare(other);
    if (c == 0) throw Invalid_input("Algebraic_real::rational_between: equal numbers");
    const Algebraic_real& a = c < 0 ? *this : other;
    const Algebraic_real& b = c < 0 ? other : *this;
    for (;;) {
      const Rational lo = a.upper(), hi = b.lower();  // a <= lo, hi <= b
      if (lo < hi) return internal::simplest_rational_between(lo, hi);
      if (lo == hi && !a.is_rational() && !b.is_rational()) return lo;
      a.refine();
      b.refine();
    }
  }

  friend bool operator==(const Algebraic_real& a, const Algebraic_real& b) { return a.compare(b) == 0; }
  friend bool operator!=(const Algebraic_real& a, const Algebraic_real& b) { return a.compare(b) != 0; }
  friend bool operator<(const Algebraic_real& a, const Algebraic_real& b) { return a.compare(b) < 0; }
  friend bool operator>(const Algebraic_real& a, const Algebraic_real& b) { return a.compare(b) > 0; }
  friend bool operator<=(const Algebraic_real& a, const Algebraic_real& b) { return a.compare(b) <= 0; }
  friend bool operator>=(const Algebraic_real& a, const Algebraic_real& b) { return a.compare(b) >= 0; }
  friend Algebraic_real operator-(const Algebraic_real& a) { return a.negated(); }

  /// Prints a rational exactly ("p/q"), otherwise "~d.ddd...(root of P in (lo,hi))".
  friend std::ostream& operator<<(std::ostream& os, const Algebraic_real& a) {
    if (a.is_rational()) return os << a.rational_value();
    return os << "~" << a.to_decimal_string(17) << "(root of " << a.polynomial() << " in (" << a.lower() << ","
              << a.upper() << "))";
  }

  /// -x: the root of P(-x) in (-hi, -lo).
  Algebraic_real negated() const {
    Lock lock(rep_->mutex);
    rep_->materialize_if_lazy();
    const Rep& r = *rep_;
    if (r.exact) return Algebraic_real(Rational(-r.lo));
    auto c = std::make_shared<internal::Mpz_vector>(*r.c);
    for (std::size_t i = 1; i < c->size(); i += 2) mpz_neg((*c)[i].get(), (*c)[i].get());
    if (c->back().sign() < 0)
      for (internal::Mpz& x : *c) mpz_neg(x.get(), x.get());
    const Rational lo = -r.hi;
    Algebraic_real res;
    res.rep_->set_interval(internal::polynomial_of(*c), c, lo, -r.lo, internal::sign_at(*c, lo));
    return res;
  }

 private:
  friend struct internal::Algebraic_real_access;
  using Lock = std::lock_guard<std::mutex>;

  // The representation shared by copies. Every member function of Algebraic_real holds `mutex` while it reads or
  // refines it; Rep's own functions expect the caller to hold it. `poly` never shares its CGAL handle with another
  // object (internal::unshared_copy): CGAL::Polynomial's reference count is a plain integer.
  struct Rep {
    std::mutex mutex;
    Polynomial_1<Integer> poly{Integer(0)};  // canonical square-free defining polynomial (not CGAL's per-thread 0)
    std::shared_ptr<const internal::Mpz_vector> c;  // its coefficients (shared by roots of one polynomial)
    Rational lo, hi;             // lo == hi == value when exact
    int sign_lo = 0;             // sign of poly at lo (nonzero unless exact)
    bool exact = true;
    // Lazy state (src non-null): [lo, hi] is a CLOSED enclosure, poly/c/sign_lo are unset, exact is false.
    std::shared_ptr<internal::Lazy_real_source> src;
    int src_index = 0;

    void materialize_if_lazy() {
      if (src) materialize();
    }

    // Contracts a lazy enclosure to width <= w through the source; false if it could not.
    bool lazy_contract(const Rational& w) {
      if (hi - lo <= w) return true;
      Rational l = lo, h = hi;
      bool done;
      {
        std::lock_guard<std::mutex> lock(src->mutex);
        done = src->contract(src_index, l, h, w);
      }
      if (!done) return false;
      if (l > lo) lo = l;  // (the source keeps the number inside)
      if (h < hi) hi = h;
      return hi - lo <= w;
    }
    // Lazy: contracts the enclosure until 0 is outside it and its width is <= min(|lo|,|hi|) 2^-bits.
    bool lazy_narrow_relative(unsigned long bits) {
      for (int round = 0; round < 3; ++round) {
        if (CGAL::sign(lo) * CGAL::sign(hi) > 0) {
          const Rational m = CGAL::abs(lo) < CGAL::abs(hi) ? CGAL::abs(lo) : CGAL::abs(hi);
          Rational w;
          mpq_div_2exp(w.mpq(), m.mpq(), static_cast<mp_bitcnt_t>(bits));
          return lazy_contract(w);
        }
        Rational w;  // straddles or touches 0: shrink towards a width that may exclude it
        mpq_div_2exp(w.mpq(), Rational(hi - lo).mpq(), 32);
        if (!lazy_contract(w)) return false;
      }
      return false;
    }

    // The exact representation of a lazy number: the root in [lo, hi] of the source's polynomial. While the
    // enclosure holds several roots, it is contracted (distinct roots are separated; the contraction keeps the
    // number), then the isolating interval comes from Descartes' rule on the factor holding it.
    void materialize() {
      std::shared_ptr<internal::Lazy_real_source> s = src;
      const internal::Lazy_eliminant& E = [&]() -> const internal::Lazy_eliminant& {
        std::lock_guard<std::mutex> lock(s->mutex);
        return s->eliminant(src_index);
      }();
      unsigned long bits = 16;
      for (int round = 0;; ++round) {
        if (lo == hi) {  // a point enclosure is the number itself
          set_exact(lo);
          break;
        }
        std::size_t count = 0;
        const internal::Lazy_eliminant::Factor* holder = nullptr;
        internal::Rational_isolating_interval iv;
        // Cheap certificate first: every factor strictly monotone on [lo, hi] (derivative enclosure without 0)
        // has at most one root there, exactly one iff its signs at the ends differ.
        // (Horner's interval enclosure of the derivative is only sharp on narrow enclosures: the power-basis
        // coefficients cancel, so the enclosure is first contracted, cheaply, through the source.)
        bool monotone = true;
        for (unsigned long extra = 0;; extra = extra == 0 ? 64 : 2 * extra) {
          if (extra > 0) {
            Rational w;  // fresh object
            mpq_div_2exp(w.mpq(), Rational(hi - lo).mpq(), static_cast<mp_bitcnt_t>(extra));
            if (extra > 2048 || !lazy_contract(w)) break;
          }
          bool all = true;
          for (const auto& f : E.factors)
            if (internal::derivative_sign_on(*f.c, lo, hi) == 0) all = false;
          if (all) break;
        }
        if (lo == hi) {
          set_exact(lo);
          break;
        }
        for (const auto& f : E.factors) {
          const int sl = internal::sign_at(*f.c, lo), sh = internal::sign_at(*f.c, hi);
          if (sl == 0 || sh == 0 || internal::derivative_sign_on(*f.c, lo, hi) == 0) {
            monotone = false;
            break;
          }
          if (sl != sh) {
            ++count;
            holder = &f;
            iv.lo = lo;
            iv.hi = hi;
            iv.sign_lo = sl;
          }
        }
        if (!monotone) count = 0;
        for (const auto& f : E.factors) {
          if (monotone) break;
          for (auto& r : internal::isolate_square_free(*f.c, lo, hi)) {
            ++count;
            holder = &f;
            iv = r;
          }
        }
        if (count == 0) throw Error("Algebraic_real: a lazy enclosure holds no root of its polynomial");
        if (count == 1) {
          if (iv.exact) set_exact(iv.lo);
          else if (holder->poly.degree() == 1) set_exact(Rational(-holder->poly[0], holder->poly[1]));
          else set_interval(holder->poly, holder->c, iv.lo, iv.hi, iv.sign_lo);
          for (const Rational& q : holder->rational_roots)
            if (!exact && lo < q && q < hi) set_exact(q);  // the only root of the factor in (lo, hi)
          if (!exact && !holder->others_irrational) {
            try_small_rational(32);
            resolve_rationality();
          }
          src.reset();
          return;
        }
        Rational w;
        mpq_div_2exp(w.mpq(), Rational(hi - lo).mpq(), static_cast<mp_bitcnt_t>(bits));
        bits = std::min<unsigned long>(2 * bits, 1UL << 16);
        if (round > 64 || !lazy_contract(w))
          throw Error("Algebraic_real: cannot separate the roots of a lazy number's polynomial");
      }
      src.reset();
    }

    void set_exact(const Rational& q) {
      src.reset();
      std::vector<Integer> v{Integer(mpq_numref(q.mpq())) * Integer(-1), Integer(mpq_denref(q.mpq()))};
      poly = Polynomial_1<Integer>(v.begin(), v.end());
      c = std::make_shared<const internal::Mpz_vector>(internal::coefficients_of(poly));
      lo = hi = q;
      sign_lo = 0;
      exact = true;
    }
    void set_interval(const Polynomial_1<Integer>& p, std::shared_ptr<const internal::Mpz_vector> pc, const Rational& l,
                      const Rational& h, int s_lo) {
      poly = internal::unshared_copy(p);
      c = std::move(pc);
      lo = l;
      hi = h;
      sign_lo = s_lo;
      exact = false;
      src.reset();
    }
    // For lo < m < hi: +1 if the root is > m, -1 if < m, 0 if it is m
    // (then the number becomes exact); the interval shrinks accordingly.
    int locate(const Rational& m) {
      const int s = internal::sign_at(*c, m);
      if (s == 0) { set_exact(m); return 0; }
      if (s == sign_lo) { lo = m; return 1; }
      hi = m;
      return -1;
    }
    void bisect() { locate((lo + hi) / 2); }
    // Algebraic_real::to_interval().
    std::pair<double, double> to_interval() {
      if (src) {  // lazy: contract the enclosure to relative width 2^-55 (0 outside it), else materialize
        if (lazy_narrow_relative(55)) return {CGAL::to_interval(lo).first, CGAL::to_interval(hi).second};
        materialize();
      }
      separate_from_zero();
      if (!exact) {
        Rational m = CGAL::abs(lo) < CGAL::abs(hi) ? CGAL::abs(lo) : CGAL::abs(hi);
        Rational w;  // fresh object: CGAL::Gmpq copies share their mpq_t
        mpq_div_2exp(w.mpq(), m.mpq(), 55);
        refine_to_width(w);
      }
      if (exact) return CGAL::to_interval(lo);
      return {CGAL::to_interval(lo).first, CGAL::to_interval(hi).second};
    }
    // Makes 0 lie outside [lo, hi] (the number is nonzero unless exact).
    void separate_from_zero() {
      if (!exact && lo < Rational(0) && hi > Rational(0)) locate(Rational(0));
      while (!exact && (CGAL::is_zero(lo) || CGAL::is_zero(hi))) bisect();
    }

    // One Newton proposal: an interval of width <= w around the MPFR
    // approximation, accepted iff the exact signs at its ends differ.
    bool newton_step(const Rational& w) {
      const long k = static_cast<long>(mpz_sizeinbase(mpq_denref(w.mpq()), 2)) -
                     static_cast<long>(mpz_sizeinbase(mpq_numref(w.mpq()), 2)) + 2;  // 2^(1-k) <= w
      if (k < 1) return false;
      const Rational x = internal::newton_approximation(*c, lo, hi, sign_lo, static_cast<unsigned long>(k + 2));
      Rational delta(1);
      mpz_mul_2exp(mpq_denref(delta.mpq()), mpq_denref(delta.mpq()), static_cast<mp_bitcnt_t>(k));
      Rational l = x - delta, h = x + delta;
      int sl, sh;
      if (l <= lo) { l = lo; sl = sign_lo; } else sl = internal::sign_at(*c, l);
      if (sl == 0) { set_exact(l); return true; }
      if (h >= hi) { h = hi; sh = -sign_lo; } else sh = internal::sign_at(*c, h);
      if (sh == 0) { set_exact(h); return true; }
      if (sl == sign_lo && sh != sign_lo) { lo = l; hi = h; return true; }
      if (sl != sign_lo) hi = l;  // root in (lo, l)
      else lo = h;                // root in (h, hi)
      return false;
    }

    void refine_to_width(const Rational& w) {
      int failures = 0;
      while (!exact && hi - lo > w) {
        if (failures < 6 && hi - lo > w * 16) {
          if (!newton_step(w)) {
            ++failures;
            for (int i = 0; i < 4 && !exact && hi - lo > w; ++i) bisect();
          }
        } else {
          bisect();
        }
      }
    }

    // Makes the representation exact if the root is rational. A rational
    // root p/q (lowest terms) has q | lc. Once the width is <= 1/D^2, at most
    // one fraction with denominator <= D fits, and it is then the simplest
    // one in the interval; D grows 2^8, 2^16, ... up to |lc|, so small
    // denominators are found after little refinement.
    // Cheap half of resolve_rationality: is the root a fraction whose denominator has at most `bits` bits?
    // (width <= 2^-2bits leaves at most one such fraction in the interval: the simplest one.)
    void try_small_rational(std::size_t bits) {
      if (exact) return;
      Rational target;
      mpq_set_ui(target.mpq(), 1, 1);
      mpq_div_2exp(target.mpq(), target.mpq(), static_cast<mp_bitcnt_t>(2 * bits + 2));
      refine_to_width(target);
      if (exact) return;
      const Rational s = internal::simplest_rational_between(lo, hi);
      if (mpz_divisible_p(mpz_abs_lc().mpz(), mpq_denref(s.mpq()))) locate(s);
    }
    Integer mpz_abs_lc() const { return CGAL::abs(poly.lcoeff()); }
    void resolve_rationality(bool modular_test_done = false) {
      if (exact) return;
      if (!modular_test_done && internal::has_no_rational_root_modular(*c)) return;
      const Integer Q = CGAL::abs(poly.lcoeff());
      const std::size_t qbits = mpz_sizeinbase(Q.mpz(), 2);
      for (std::size_t bits = 8;; bits *= 2) {
        const bool last = bits >= qbits;
        Rational target;  // 1/D^2, fresh object
        if (last) {
          mpq_set_z(target.mpq(), Q.mpz());
          mpq_mul(target.mpq(), target.mpq(), target.mpq());
          mpq_inv(target.mpq(), target.mpq());
        } else {
          mpq_set_ui(target.mpq(), 1, 1);
          mpq_div_2exp(target.mpq(), target.mpq(), static_cast<mp_bitcnt_t>(2 * bits));
        }
        refine_to_width(target);
        if (exact) return;
        const Rational s = internal::simplest_rational_between(lo, hi);
        if (mpz_cmp(mpq_denref(s.mpq()), Q.mpz()) > 0) return;  // no candidate fraction left
        if (mpz_divisible_p(Q.mpz(), mpq_denref(s.mpq())) && locate(s) == 0) return;  // rational root
        if (last) return;
      }
    }
  };

  void construct(const Polynomial_1<Integer>& poly, const Rational& lo, const Rational& hi) {
    if (CGAL::is_zero(poly)) throw Invalid_input("Algebraic_real: zero polynomial");
    if (lo > hi) throw Invalid_input("Algebraic_real: lower end above upper end");
    const Polynomial_1<Integer> P = internal::canonical_integer(poly);
    if (lo == hi) {
      if (internal::sign_at(internal::coefficients_of(P), lo) != 0)
        throw Invalid_input("Algebraic_real: the point interval is not a root");
      rep_->set_exact(lo);
      return;
    }
    bool found = false;
    for (const auto& fm : internal::square_free_factors(P)) {
      const internal::Mpz_vector g = internal::coefficients_of(fm.first);
      for (const auto& iv : internal::isolate_square_free(g, lo, hi)) {
        if (found) throw Invalid_input("Algebraic_real: more than one root in the interval");
        found = true;
        if (iv.exact) rep_->set_exact(iv.lo);
        else if (fm.first.degree() == 1) rep_->set_exact(Rational(-fm.first[0], fm.first[1]));
        else rep_->set_interval(fm.first, std::make_shared<const internal::Mpz_vector>(g), iv.lo, iv.hi, iv.sign_lo);
      }
    }
    if (!found) throw Invalid_input("Algebraic_real: no root in the interval");
    rep_->resolve_rationality();
  }

  // compare(other) and compare(q) with the mutexes of the representations held by the caller.
  static int compare(Rep& a, Rep& b) {
    if (a.src || b.src) {
      const int c = compare_enclosures(a, b);
      if (c != 2) return c;
      a.materialize_if_lazy();
      b.materialize_if_lazy();
    }
    bool gcd_done = false;
    unsigned long extra_bits = 16;
    for (int round = 0;; ++round) {
      if (a.exact) return -compare(b, a.lo);
      if (b.exact) return compare(a, b.lo);
      if (a.hi <= b.lo) return -1;
      if (b.hi <= a.lo) return 1;
      // Shrink both to the common part of the intervals.
      if (b.lo > a.lo) {
        const int s = a.locate(b.lo);  // sign of alpha - b.lo
        if (s < 0) return -1;
        if (s == 0) continue;
      }
      if (b.hi < a.hi) {
        const int s = a.locate(b.hi);
        if (s > 0) return 1;
        if (s == 0) continue;
      }
      if (a.lo > b.lo) {
        const int s = b.locate(a.lo);
        if (s < 0) return 1;
        if (s == 0) continue;
      }
      if (a.hi < b.hi) {
        const int s = b.locate(a.hi);
        if (s > 0) return -1;
        if (s == 0) continue;
      }
      // Now both isolating intervals are the same I = (lo, hi).
      if (a.c == b.c || a.poly == b.poly) return 0;  // I holds only one root of that polynomial
      if (!gcd_done && round >= 6) {
        gcd_done = true;
        auto hc = std::make_shared<const internal::Mpz_vector>(internal::gcd_of(*a.c, *b.c));
        if (hc->size() >= 2) {
          // h divides both defining polynomials, so it has at most one root in
          // I, which is then both numbers; equality iff h changes sign on I.
          const Polynomial_1<Integer> h = internal::polynomial_of(*hc);
          const int sl = internal::sign_at(*hc, a.lo), sh = internal::sign_at(*hc, a.hi);
          if (sl != 0 && sh != 0 && sl != sh) {
            a.set_interval(h, hc, a.lo, a.hi, sl);
            b.set_interval(h, hc, a.lo, a.hi, sl);
            return 0;
          }
        }
      }
      if (!gcd_done) {  // bisect the common interval
        const Rational m = (a.lo + a.hi) / 2;
        a.locate(m);
        if (!a.exact) b.locate(m);
      } else {  // known to differ: quadratic refinement, doubling the bits gained
        const Rational w = shrunk_width(a.hi - a.lo, extra_bits);
        extra_bits = std::min<unsigned long>(2 * extra_bits, 1UL << 20);
        a.refine_to_width(w);
        b.refine_to_width(w);
      }
    }
  }

  static int compare(Rep& r, const Rational& q) {
    if (r.src) {
      Rep p;
      p.set_exact(q);
      const int c = compare_enclosures(r, p);
      if (c != 2) return c;
      r.materialize_if_lazy();
    }
    if (r.exact) return CGAL::compare(r.lo, q);
    if (q <= r.lo) return 1;
    if (q >= r.hi) return -1;
    return r.locate(q);
  }

  // Compares with the enclosures only (at least one lazy): closed lazy enclosures, open isolating intervals,
  // points for rationals; lazy enclosures are contracted (and exact intervals refined) a few times. Returns 2 when
  // undecided (then both are materialized and compared exactly: equal numbers are never separated this way).
  static int compare_enclosures(Rep& a, Rep& b) {
    for (int round = 0;; ++round) {
      // a < b if every point of a's enclosure is below every point of b's (strictly where both ends are closed)
      const bool a_open = !a.src && !a.exact, b_open = !b.src && !b.exact;
      if (a.hi < b.lo || (a.hi == b.lo && (a_open || b_open))) return -1;
      if (b.hi < a.lo || (b.hi == a.lo && (a_open || b_open))) return 1;
      if (round >= 3) return 2;
      const Rational m = std::max(a.hi - a.lo, b.hi - b.lo);
      Rational w;  // fresh object: CGAL::Gmpq copies share their mpq_t
      mpq_div_2exp(w.mpq(), m.mpq(), round == 0 ? 24 : 64);
      for (Rep* r : {&a, &b}) {
        if (r->src) {
          if (!r->lazy_contract(w)) return 2;
        } else if (!r->exact) {
          r->refine_to_width(w);
        }
      }
    }
  }

  // w / 2^bits as a fresh object.
  static Rational shrunk_width(const Rational& w, unsigned long bits) {
    Rational r;
    mpq_div_2exp(r.mpq(), w.mpq(), static_cast<mp_bitcnt_t>(bits));
    return r;
  }

  // Sign of F on [lo,hi] by interval Horner evaluation (0: undecided).
  static int interval_sign(const Polynomial_1<Integer>& F, const Rational& lo, const Rational& hi) {
    typedef CGAL::Interval_nt<true> I;
    const I x(CGAL::to_interval(lo).first, CGAL::to_interval(hi).second);
    I v(CGAL::to_interval(F[F.degree()]));
    for (int i = F.degree() - 1; i >= 0; --i) v = v * x + I(CGAL::to_interval(F[i]));
    if (v.inf() > 0) return 1;
    if (v.sup() < 0) return -1;
    return 0;
  }

  std::shared_ptr<Rep> rep_;
};

namespace internal {
/// Construction without checks, for the root isolation functions.
struct Algebraic_real_access {
  static Algebraic_real from_interval(const Polynomial_1<Integer>& canonical_square_free,
                                      std::shared_ptr<const Mpz_vector> c,
                                      const Rational& lo, const Rational& hi, int sign_lo) {
    Algebraic_real a;
    a.rep_->set_interval(canonical_square_free, c, lo, hi, sign_lo);
    return a;
  }
  static void resolve_rationality(const Algebraic_real& a, bool modular_test_done) {
    Algebraic_real::Lock lock(a.rep_->mutex);
    a.rep_->materialize_if_lazy();
    a.rep_->resolve_rationality(modular_test_done);
  }
  static void try_small_rational(const Algebraic_real& a, std::size_t bits) {
    Algebraic_real::Lock lock(a.rep_->mutex);
    a.rep_->materialize_if_lazy();
    a.rep_->try_small_rational(bits);
  }
  /// A lazy number: the one of `source` numbered `index`, known to lie in the closed interval [lo, hi] (lo <= hi).
  static Algebraic_real lazy(std::shared_ptr<Lazy_real_source> source, int index, const Rational& lo,
                             const Rational& hi) {
    Algebraic_real a;
    Algebraic_real::Rep& r = *a.rep_;
    r.lo = lo;
    r.hi = hi;
    r.exact = false;
    r.sign_lo = 0;
    r.poly = Polynomial_1<Integer>(Integer(0));
    r.c.reset();
    r.src = std::move(source);
    r.src_index = index;
    return a;
  }
  static bool same_representation(const Algebraic_real& a, const Algebraic_real& b) { return a.rep_ == b.rep_; }
};
}  // namespace internal

/// Free-function forms, CGAL style.
inline int compare(const Algebraic_real& a, const Algebraic_real& b) { return a.compare(b); }
inline double to_double(const Algebraic_real& a) { return a.to_double(); }
inline std::pair<double, double> to_interval(const Algebraic_real& a) { return a.to_interval(); }

}  // namespace bezoutian

#endif  // BEZOUTIAN_ALGEBRAIC_ALGEBRAIC_REAL_H

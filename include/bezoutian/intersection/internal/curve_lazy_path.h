// The lazy planar path of intersect_curves (default method, plane curves with positive weights): the certified
// interval solver (planar_interval_solver.h) proves each transversal crossing in a Krawczyk box, and the
// parameters are returned as lazy algebraic numbers, made exact on demand from the eliminants R(s), T(t) of the
// exact default path (determinants of the implicit Bezout matrices, du-1989 eq. 4.1), computed at most once per
// curve pair (Planar_lazy_intersections). See doc/curve_intersection.md.
//
// Internal header: Planar_lazy_intersections and Curve_intersection_engine::lazy_path (Curve_intersection.h), not
// part of the public API.
#ifndef BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_LAZY_PATH_H
#define BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_LAZY_PATH_H

#include <bezoutian/intersection/Curve_intersection.h>

#include <bezoutian/arithmetic/interval_krawczyk.h>
#include <bezoutian/intersection/planar_interval_solver.h>

#include <algorithm>
#include <map>
#include <memory>
#include <vector>

namespace bezoutian {
namespace internal {

/// The lazy parameters of the planar default path (intersect_curves, D == 2): the intersections proved by the
/// interval solver (planar_interval_solver.h), each a box [s_lo, s_hi] x [t_lo, t_hi] holding exactly one,
/// transversal, intersection; number 2k is s of box k, 2k + 1 its t. Exact on demand: the eliminants R(s), T(t)
/// (determinants of the implicit Bezout matrices, du-1989 eq. 4.1, as in the exact default path) are computed at
/// most once per curve pair and shared by all its points; boxes are contracted by Krawczyk's operator in MPFI.
template <int D>
class Planar_lazy_intersections : public Lazy_real_source {
 public:
  using P1 = Ci_poly1;
  Planar_lazy_intersections(const Rational_bezier_curve<Rational, D>& c1, const Rational_bezier_curve<Rational, D>& c2,
                            const std::array<P1, 3>& H1, const std::array<P1, 3>& H2)
      : H_{H1, H2} {
    a.curve = c1;
    b.curve = c2;
    set_planar_interval_data(a, H1);
    set_planar_interval_data(b, H2);
    for (const auto* H : {&H1, &H2})
      for (const P1& f : *H)
        for (int i = 0; i <= f.degree(); ++i) bits_ = std::max(bits_, long(f[i].bit_size()));
  }
  Planar_interval_curve a, b;              // the two curves with the interval solver's data
  std::vector<std::array<Rational, 4>> boxes;  // s_lo, s_hi, t_lo, t_hi (closed)

  const Lazy_eliminant& eliminant(int index) override {
    const int side = index % 2;
    if (!fallback_ && !E_[side]) {
      P1 R;
      try {
        R = Curve_intersection_engine<D>::planar_eliminant(H_[side], H_[1 - side]);
      } catch (const Error&) {
        R = P1(0);
      }
      if (CGAL::is_zero(R) || R.degree() < 1) {
        fallback_ = true;  // a common component: exact points instead
      } else {
        E_[side].reset(new Lazy_eliminant(R));
        // Rational roots are recognised cheaply through the simplest fractions in the contracted enclosures
        // (a root p/q with q <= 2^32 is the simplest fraction of an interval of width < 2^-64 holding it).
        std::vector<Rational> candidates;
        Rational w(1);
        mpz_mul_2exp(mpq_denref(w.mpq()), mpq_denref(w.mpq()), 72);
        for (std::size_t k = 0; k < boxes.size(); ++k) {
          Rational lo = boxes[k][2 * side], hi = boxes[k][2 * side + 1];
          if (!contract(int(2 * k) + side, lo, hi, w) || !(lo < hi)) continue;
          const Rational q = simplest_rational_between(lo, hi);
          if (mpz_sizeinbase(mpq_denref(q.mpq()), 2) <= 40) candidates.push_back(q);
        }
        E_[side]->add_rational_candidates(candidates);
      }
    }
    if (!fallback_) return *E_[side];
    // The curves lie on one algebraic curve (R = 0): the exact intersection in the box (subresultant path).
    auto it = per_index_.find(index);
    if (it != per_index_.end()) return *it->second;
    if (!exact_) {
      exact_.reset(new Curve_intersection_result(
          Curve_intersection_engine<D>(a.curve, b.curve, Curve_intersection_method::subresultant).run()));
    }
    const auto& box = boxes[index / 2];
    for (const auto& p : exact_->points)
      if (p.s.compare(box[0]) >= 0 && p.s.compare(box[1]) <= 0 && p.t.compare(box[2]) >= 0 && p.t.compare(box[3]) <= 0) {
        const Algebraic_real& x = side == 0 ? p.s : p.t;
        const P1 q = x.is_rational() ? P1(-Integer(mpq_numref(x.rational_value().mpq())),
                                          Integer(mpq_denref(x.rational_value().mpq())))
                                     : x.polynomial();
        return *(per_index_[index] = std::make_shared<Lazy_eliminant>(q));
      }
    throw Error("intersect_curves: no exact intersection in a Krawczyk box");
  }

  bool contract(int index, Rational& lo, Rational& hi, const Rational& w) override {
    std::array<Rational, 4>& box = boxes[index / 2];
    const int side = index % 2;
    box[2 * side] = std::max(box[2 * side], lo);
    box[2 * side + 1] = std::min(box[2 * side + 1], hi);
    // Krawczyk in MPFI: quadratic contraction down to the precision's resolution, then more precision
    const long wbits = long(mpz_sizeinbase(mpq_denref(w.mpq()), 2)) - long(mpz_sizeinbase(mpq_numref(w.mpq()), 2));
    mpfr_prec_t prec = mpfr_prec_t(std::max(128L, wbits + bits_ + 64));
    for (int round = 0; round < 12 && box[2 * side + 1] - box[2 * side] > w; ++round, prec *= 2) {
      if (prec > (mpfr_prec_t(1) << 20)) break;
      if (!planar_krawczyk_contract(H_[0], H_[1], box, prec, 64, CGAL::to_double(w) * 0.5)) break;
    }
    lo = box[2 * side];
    hi = box[2 * side + 1];
    return hi - lo <= w;
  }

 private:
  std::array<std::array<P1, 3>, 2> H_;
  long bits_ = 0;
  std::unique_ptr<Lazy_eliminant> E_[2];
  bool fallback_ = false;
  std::unique_ptr<Curve_intersection_result> exact_;
  std::map<int, std::shared_ptr<Lazy_eliminant>> per_index_;
};

// Plane curves with positive weights: the certified interval solver (planar_interval_solver.h) first. If it
// settles everything (every crossing a Krawczyk box strictly inside (0,1)^2, every other cell excluded, no common
// end point, no tangency / overlap / undecided cell), the points are returned with lazy parameters s, t
// (Algebraic_real, exact on demand through Planar_lazy_intersections); Krawczyk's proof includes a regular
// Jacobian, i.e. a transversal crossing of multiplicity 1. Otherwise false: the exact paths below decide.
template <int D>
bool Curve_intersection_engine<D>::lazy_path(Curve_intersection_result& res) const {
  if constexpr (D != 2) {
    (void)res;
    return false;
  } else {
    if (!positive_weights(c1_) || !positive_weights(c2_)) return false;
    BEZOUTIAN_PROFILE_START;
    auto data = std::make_shared<Planar_lazy_intersections<D>>(c1_, c2_, H1_, H2_);
    Planar_interval_solver solver{data->a, data->b, {}};
    solver.budget = 20000;  // cells; more than the arrangement's (a failure costs the exact path anyway)
    solver.max_depth = 34;  // power-basis enclosures of large coefficients can need cells below 2^-24
    solver.mpfi_depth = 28;    // cells the doubles leave undecided that deep get the MPFI test
    solver.mpfi_merge = true;  // boxes of one zero a few ulps wide: merged in MPFI
    solver.mpfi_precision = mpfr_prec_t(192 + 2 * coefficient_bits_);
    solver.run(data->a.inet, 0, 1, data->b.inet, 0, 1, 0);
    BEZOUTIAN_PROFILE_STEP("lazy interval solver");
    if (solver.failed || !solver.contacts.empty()) return false;
    for (const auto& f : solver.found) {
      const int k = int(data->boxes.size());
      data->boxes.push_back({Rational(f[0]), Rational(f[1]), Rational(f[2]), Rational(f[3])});
      const auto& box = data->boxes.back();
      Curve_intersection_point p;
      p.s = Algebraic_real_access::lazy(data, 2 * k, box[0], box[1]);
      p.t = Algebraic_real_access::lazy(data, 2 * k + 1, box[2], box[3]);
      res.points.push_back(p);
    }
    return true;
  }
}

} // namespace internal
} // namespace bezoutian

#endif // BEZOUTIAN_INTERSECTION_INTERNAL_CURVE_LAZY_PATH_H

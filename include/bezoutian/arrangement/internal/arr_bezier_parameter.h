// Curve parameters of the arrangement traits that are exact on demand: an intersection of two supporting curves
// found by interval subdivision and certified by Krawczyk's test is first known only by a small parameter box
// holding exactly one transversal intersection; the exact algebraic parameters (intersect_curves, du-1989 ch. 4)
// are computed only when an interval comparison cannot decide.
#ifndef BEZOUTIAN_ARRANGEMENT_INTERNAL_ARR_BEZIER_PARAMETER_H
#define BEZOUTIAN_ARRANGEMENT_INTERNAL_ARR_BEZIER_PARAMETER_H

#include <bezoutian/arithmetic/profiling.h>
#include <bezoutian/algebraic/Algebraic_real.h>
#include <bezoutian/intersection/Curve_intersection.h>
#include <bezoutian/arithmetic/Error.h>
#include <bezoutian/arrangement/internal/arr_bezier_exact.h>
#include <bezoutian/intersection/planar_interval_solver.h>

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <memory>
#include <utility>
#include <vector>

namespace bezoutian {
namespace internal {

/// The exact intersections of one pair of supporting curves, computed at most once for all its lazy points.
struct Arr_exact_pair {
  std::shared_ptr<const Arr_bezier_supporting_curve> a, b;
  bool done = false;
  std::vector<std::pair<Algebraic_real, Algebraic_real>> points;  // (s on a, t on b)
  void compute() {
    if (done) return;
    BEZOUTIAN_PROFILE_SCOPE("exact pair (lazy)");
    const Curve_intersection_result r = a == b ? self_intersections(a->curve) : intersect_curves(a->curve, b->curve);
    for (const auto& p : r.points) points.push_back({p.s, p.t});
    done = true;
  }
};

/// One intersection known by a closed box [s_lo, s_hi] x [t_lo, t_hi] holding exactly one common point of the
/// two curves (Krawczyk), and its exact parameters once needed.
struct Arr_lazy_point {
  std::shared_ptr<Arr_exact_pair> pair;
  std::array<Rational, 4> box;  // s_lo, s_hi, t_lo, t_hi
  bool exact = false;
  Algebraic_real st[2];
  void materialize() {
    if (exact) return;
    BEZOUTIAN_PROFILE_SCOPE("materialize");
    pair->compute();
    int found = -1;
    for (std::size_t i = 0; i < pair->points.size(); ++i) {
      const auto& p = pair->points[i];
      if (p.first.compare(box[0]) >= 0 && p.first.compare(box[1]) <= 0 && p.second.compare(box[2]) >= 0 &&
          p.second.compare(box[3]) <= 0) {
        if (found >= 0) throw Error("Arr_rational_bezier_traits_2: two exact intersections in a Krawczyk box");
        found = int(i);
      }
    }
    if (found < 0) throw Error("Arr_rational_bezier_traits_2: no exact intersection in a Krawczyk box");
    st[0] = pair->points[found].first;
    st[1] = pair->points[found].second;
    exact = true;
  }
};

/// A parameter of a supporting curve: an exact Algebraic_real, or side 0/1 (s/t) of a lazy intersection.
/// Copies share their representation.
class Arr_parameter {
 public:
  Arr_parameter() : v_(constant(0)) {}
  Arr_parameter(int i) : v_(i == 0 || i == 1 ? constant(i) : Algebraic_real(Rational(i))) {}
  Arr_parameter(const Rational& q) : v_(q) {}
  Arr_parameter(const Algebraic_real& a) : v_(a) {}
  Arr_parameter(std::shared_ptr<Arr_lazy_point> l, int side) : v_(constant(0)), lazy_(std::move(l)), side_(side) {}

  bool is_lazy() const { return lazy_ && !lazy_->exact; }
  /// The exact number (computes it for a lazy intersection).
  const Algebraic_real& exact() const {
    if (!lazy_) return v_;
    lazy_->materialize();
    return lazy_->st[side_];
  }
  /// True if the number is known to be rational (never for an unresolved lazy parameter).
  bool is_rational() const { return !is_lazy() && exact().is_rational(); }
  Rational rational_value() const { return exact().rational_value(); }
  /// Ends of an enclosing interval (closed for lazy parameters, open for irrational exact ones).
  Rational lower() const { return is_lazy() ? lazy_->box[2 * side_] : exact().lower(); }
  Rational upper() const { return is_lazy() ? lazy_->box[2 * side_ + 1] : exact().upper(); }
  double to_double() const {
    if (is_lazy()) return 0.5 * (CGAL::to_double(lazy_->box[2 * side_]) + CGAL::to_double(lazy_->box[2 * side_ + 1]));
    return exact().to_double();
  }
  /// Shrinks the enclosing interval below width w (a lazy parameter becomes exact if its box is wider).
  void refine_to_width(const Rational& w) const {
    if (is_lazy() && upper() - lower() <= w) return;
    exact().refine_to_width(w);
  }
  bool same_representation(const Arr_parameter& o) const {
    if (lazy_ || o.lazy_) return lazy_ == o.lazy_ && side_ == o.side_;
    return Algebraic_real_access::same_representation(v_, o.v_);
  }

  /// Exact comparison: identical representations, then enclosures, then exact numbers.
  int compare(const Arr_parameter& o) const {
    if (same_representation(o)) return 0;
    // closed lazy boxes, open isolating intervals of irrational exact numbers, points for rationals: strict
    // separation of the closed intervals decides in every case; exact numbers are refined (cheap) down to the
    // width of the lazy box before the lazy one is made exact
    for (int round = 0; round < 4 && (is_lazy() || o.is_lazy()); ++round) {
      const Rational al = lower(), ah = upper(), bl = o.lower(), bh = o.upper();
      if (ah < bl) return -1;
      if (bh < al) return 1;
      const Rational w = is_lazy() ? ah - al : bh - bl;
      bool refined = false;
      for (const Arr_parameter* x : {this, &o})
        if (!x->is_lazy() && !x->exact().is_rational() && x->upper() - x->lower() > w) {
          x->exact().refine_to_width(std::max(w, (x->upper() - x->lower()) / Rational(1 << 20)));
          refined = true;
        }
      if (!refined) break;
    }
    return exact().compare(o.exact());
  }
  int compare(const Rational& q) const {
    if (is_lazy()) {
      if (upper() < q) return -1;
      if (lower() > q) return 1;
    }
    return exact().compare(q);
  }
  friend bool operator<(const Arr_parameter& a, const Arr_parameter& b) { return a.compare(b) < 0; }
  friend bool operator>(const Arr_parameter& a, const Arr_parameter& b) { return a.compare(b) > 0; }
  friend bool operator<=(const Arr_parameter& a, const Arr_parameter& b) { return a.compare(b) <= 0; }
  friend bool operator>=(const Arr_parameter& a, const Arr_parameter& b) { return a.compare(b) >= 0; }
  friend bool operator==(const Arr_parameter& a, const Arr_parameter& b) { return a.compare(b) == 0; }
  friend bool operator!=(const Arr_parameter& a, const Arr_parameter& b) { return a.compare(b) != 0; }

 private:
  // shared exact 0 and 1 (copies share the representation: no allocation per parameter)
  static const Algebraic_real& constant(int i) {
    static const Algebraic_real zero(0), one(1);
    return i == 0 ? zero : one;
  }
  Algebraic_real v_;
  std::shared_ptr<Arr_lazy_point> lazy_;
  int side_ = 0;
};

/// 2^-42: the parameter width to which enclosures are refined before double evaluation.
inline const Rational& arr_parameter_width() {
  static const Rational w(std::ldexp(1.0, -42));
  return w;
}

inline void arr_refine(const Arr_parameter& t) {
  if (t.is_rational()) return;
  t.refine_to_width((t.upper() - t.lower()) / Rational(64));
}

// ------------------------------------------------------------------------------------- interval solver
// The solver for two different curves lives in planar_interval_solver.h (shared with intersect_curves).
typedef Planar_interval Arr_interval;
using Arr_interval_net = Planar_interval_net;
using Arr_interval_solver = Planar_interval_solver;
inline void arr_eval_form(const Planar_interval_curve& c, const Arr_interval& u, Arr_interval f[3], Arr_interval df[3]) {
  planar_eval_form(c, u, f, df);
}
inline bool arr_krawczyk(const Planar_interval_curve& A, const Planar_interval_curve& B, Arr_interval& S, Arr_interval& T,
                         int iterations) {
  return planar_krawczyk(A, B, S, T, iterations);
}
inline bool arr_net_box(const Arr_interval_net& net, double b[4]) { return planar_net_box(net, b); }
inline void arr_net_halves(const Arr_interval_net& q, Arr_interval_net& left, Arr_interval_net& right,
                           Arr_interval_net& tri) {
  planar_net_halves(q, left, right, tri);
}

/// Enclosures of F(S, T), dF/ds, dF/dt for a bivariate coefficient matrix f[p][q] (s^p t^q).
inline void arr_eval_bivariate(const std::vector<std::vector<Arr_interval>>& f, const Arr_interval& S,
                               const Arr_interval& T, Arr_interval& v, Arr_interval& ds, Arr_interval& dt) {
  const int n = int(f.size()) - 1;
  v = ds = dt = Arr_interval(0);
  for (int p = n; p >= 0; --p) {
    Arr_interval r = f[p][n], dr(0);
    for (int q = n - 1; q >= 0; --q) {
      dr = dr * T + r;
      r = r * T + f[p][q];
    }
    ds = ds * S + v;
    v = v * S + r;
    dt = dt * S + dr;
  }
}

/// Krawczyk's test for the self-intersection system F_1 = F_2 = 0 (divided differences) on S x T; as
/// arr_krawczyk.
inline bool arr_krawczyk_self(const Arr_bezier_supporting_curve& A, Arr_interval& S, Arr_interval& T, int iterations) {
  typedef Arr_interval I;
  auto jet = [&](double cs, double ct, I J[2][2], I G[2]) {
    I d1, d2;
    for (int k = 0; k < 2; ++k) {
      arr_eval_bivariate(A.fd[k], S, T, d1, J[k][0], J[k][1]);
      arr_eval_bivariate(A.fd[k], I(cs), I(ct), G[k], d1, d2);
    }
  };
  return planar_krawczyk_iterate(jet, S, T, iterations, nullptr);
}

/// Certified self-intersections C(s) = C(t), s < t, of a supporting curve by interval subdivision of the
/// triangle s <= t: a cell is excluded by disjoint control boxes of its two pieces or by an enclosure of F_1 or
/// F_2 without 0 (the divided differences: off the diagonal their common zeros are the self-intersections, on it
/// the singular points), or it holds, enlarged, exactly one zero (Krawczyk), which must then lie strictly
/// inside (0,1)^2 and off the diagonal. `failed` as for Arr_interval_solver.
struct Arr_self_interval_solver {
  const Arr_bezier_supporting_curve& A;
  std::vector<std::array<double, 4>> found;
  int budget = 4000;
  bool failed = false;
  /// C(0) = C(1) (exact): the self-intersection (0, 1), a contact; the corner cell is settled as in
  /// Arr_interval_solver (a direction separating the first and the last piece except at the common point).
  bool closed = false;
  std::deque<std::array<Arr_interval_net, 5>> pool;  // (growing a deque keeps references)

  /// Call with the whole net twice on [0,1] x [0,1] and depth 0.
  void run(const Arr_interval_net& na, double s0, double s1, const Arr_interval_net& nb, double t0, double t1, int depth) {
    typedef Arr_interval I;
    typename I::Protector guard;
    if (depth == 0) closed = A.curve.control_point(0) == A.curve.control_point(A.curve.number_of_control_points() - 1);
    if (failed || t1 < s0) return;  // only s <= t
    const bool corner = closed && s0 == 0 && t1 == 1;
    if (corner && depth >= 1 && s1 <= t0 && Arr_interval_solver::separated(na, 0, nb, int(nb.size()) - 1)) return;
    if (--budget < 0 || A.fd[0].empty()) {
      failed = true;
      return;
    }
    if (s1 <= t0) {  // pieces meet at most at one end: control boxes
      double ba[4], bb[4];
      if (!arr_net_box(na, ba) || !arr_net_box(nb, bb)) {
        failed = true;
        return;
      }
      if (ba[1] < bb[0] || bb[1] < ba[0] || ba[3] < bb[2] || bb[3] < ba[2]) return;
    }
    const I S(s0, s1), T(t0, t1);
    for (int k = 0; k < 2; ++k) {
      I v, d1, d2;
      arr_eval_bivariate(A.fd[k], S, T, v, d1, d2);
      if (v.inf() > 0 || v.sup() < 0) return;
    }
    if (depth >= 2 && !corner) {
      const double es = 0.0625 * (s1 - s0), et = 0.0625 * (t1 - t0);
      I Sx(s0 - es, s1 + es), Tx(t0 - et, t1 + et);
      if (arr_krawczyk_self(A, Sx, Tx, 16)) {
        add(Sx, Tx);
        return;
      }
    }
    if (depth >= 24) {
      failed = true;
      return;
    }
    if (pool.size() <= std::size_t(depth)) pool.resize(depth + 1);  // one set of nets per depth: no allocation
    auto& nets = pool[depth];
    Arr_interval_net &al = nets[0], &ar = nets[1], &bl = nets[2], &br = nets[3];
    arr_net_halves(na, al, ar, nets[4]);
    arr_net_halves(nb, bl, br, nets[4]);
    const double sm = 0.5 * (s0 + s1), tm = 0.5 * (t0 + t1);
    run(al, s0, sm, bl, t0, tm, depth + 1);
    run(al, s0, sm, br, tm, t1, depth + 1);
    run(ar, sm, s1, bl, t0, tm, depth + 1);
    run(ar, sm, s1, br, tm, t1, depth + 1);
  }

  void add(const Arr_interval& S, const Arr_interval& T) {
    if (S.sup() < 0 || S.inf() > 1 || T.sup() < 0 || T.inf() > 1) return;
    if (T.sup() < S.inf()) return;  // the mirror image (t, s) of a zero
    if (!(S.inf() > 0 && S.sup() < 1 && T.inf() > 0 && T.sup() < 1 && S.sup() < T.inf())) {
      failed = true;
      return;
    }
    for (auto& f : found) {
      if (S.sup() < f[0] || f[1] < S.inf() || T.sup() < f[2] || f[3] < T.inf()) continue;
      Arr_interval HS(std::min(S.inf(), f[0]), std::max(S.sup(), f[1])), HT(std::min(T.inf(), f[2]), std::max(T.sup(), f[3]));
      const double es = HS.sup() - HS.inf(), et = HT.sup() - HT.inf();
      HS = Arr_interval(HS.inf() - es, HS.sup() + es);
      HT = Arr_interval(HT.inf() - et, HT.sup() + et);
      if (!arr_krawczyk_self(A, HS, HT, 0)) failed = true;
      return;
    }
    found.push_back({S.inf(), S.sup(), T.inf(), T.sup()});
  }
};

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_ARRANGEMENT_INTERNAL_ARR_BEZIER_PARAMETER_H

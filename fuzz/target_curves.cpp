// Fuzz target: planar curve/curve intersections and self-intersections (intersection/Curve_intersection.h).
//
// The bytes are decoded straight into a problem (no text): a header byte, then the curves. The answer is checked
// with exact rational interval arithmetic written here (de Casteljau on intervals), not with the library's own
// evaluation, so a wrong point cannot pass by sharing a mistake with the code under test.
#include "byte_reader.h"
#include "targets.h"

#include <bezoutian/intersection/Curve_intersection.h>

#include <algorithm>
#include <exception>
#include <initializer_list>
#include <optional>
#include <string>
#include <typeinfo>
#include <vector>

namespace bezoutian {
namespace fuzz {
namespace {

using Curve = Rational_bezier_curve<Rational, 2>;
using Hpoint = Curve::Homogeneous_point;

// Header byte: bit 0 self-intersection, bit 1 rational, bit 2 weights of any sign (0 included), bits 3-4 the
// coordinate alphabet, bits 5-7 the method (mostly the default one).
struct Header {
  bool self, rational, signed_weights;
  int alphabet;
  Curve_intersection_method method;
  explicit Header(std::uint8_t b)
      : self(b & 1), rational(b & 2), signed_weights(b & 4), alphabet((b >> 3) & 3),
        method(pick_method(b >> 5)) {}
  static Curve_intersection_method pick_method(int m) {
    // groebner is left out: its exact fallback takes seconds on small planar pairs (doc/curve_intersection.md)
    switch (m) {
      case 5: return Curve_intersection_method::subresultant;
      case 6: return Curve_intersection_method::projection;
      case 7: return Curve_intersection_method::resolvent;
      default: return Curve_intersection_method::default_method;
    }
  }
};

// A coordinate in the chosen alphabet: tiny integers give coincidences (common points, tangencies, overlaps),
// bytes give generic problems, small rationals unequal denominators.
Rational coordinate(Byte_reader& in, int alphabet) {
  const int b = in.next_signed();
  switch (alphabet) {
    case 0: return Rational(b % 3);
    case 1: return Rational(b % 9);
    case 2: return Rational(b);
    default: return Rational(b % 17, 1 + in.next() % 8);
  }
}

Rational weight(Byte_reader& in, const Header& h) {
  if (!h.rational) return Rational(1);
  if (h.signed_weights) return Rational(in.next_signed() % 5);  // -4 .. 4: poles and points at infinity
  return Rational(1 + in.next() % 8);
}

// Degree 1-4, 5 for one byte in 16 (the limits below allow 5).
int degree(Byte_reader& in) {
  const int b = in.next();
  return (b & 15) == 15 ? 5 : 1 + b % 4;
}

// A curve from homogeneous points (w, w x, w y); x byte -128 repeats the previous control point.
Curve read_curve(Byte_reader& in, const Header& h) {
  const int n = degree(in);
  std::vector<Hpoint> net;
  Rational x(0), y(0);
  for (int i = 0; i <= n; ++i) {
    const int peek = in.next_signed();
    if (!(peek == -128 && i > 0)) {
      x = coordinate(in, h.alphabet) + Rational(peek % 2);  // the peeked byte shifts by -1, 0, 1
      y = coordinate(in, h.alphabet);
    }
    const Rational w = weight(in, h);
    // w = 0: a control point at infinity in direction (x, y); (0, 0, 0) is refused with Invalid_input
    net.push_back(CGAL::is_zero(w) ? Hpoint{w, x, y} : Hpoint{w, w * x, w * y});
  }
  return Curve::from_homogeneous(net);
}

// ------------------------------------------------------------------ the oracle: exact interval evaluation
struct Interval {
  Rational lo, hi;
};
Interval operator+(const Interval& a, const Interval& b) { return {a.lo + b.lo, a.hi + b.hi}; }
Interval operator*(const Interval& a, const Interval& b) {
  const Rational p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}

// Homogeneous coordinate k of the curve over the parameter interval s (de Casteljau on intervals).
Interval coordinate_over(const Curve& c, int k, const Interval& s) {
  std::vector<Interval> b;
  for (const Hpoint& h : c.homogeneous_control_points()) b.push_back({h[k], h[k]});
  const Interval one_minus_s{Rational(1) - s.hi, Rational(1) - s.lo};
  for (std::size_t r = b.size(); r > 1; --r)
    for (std::size_t i = 0; i + 1 < r; ++i) b[i] = one_minus_s * b[i] + s * b[i + 1];
  return b[0];
}

// A box holding C(s) for every s in the interval, or nothing when W may vanish there.
std::optional<std::array<Interval, 2>> image_over(const Curve& c, const Interval& s) {
  const Interval w = coordinate_over(c, 0, s);
  if (w.lo <= Rational(0) && Rational(0) <= w.hi) return std::nullopt;
  const Interval inv{Rational(1) / w.hi, Rational(1) / w.lo};
  return std::array<Interval, 2>{coordinate_over(c, 1, s) * inv, coordinate_over(c, 2, s) * inv};
}

// A rational interval of a few ulps holding x (to_interval: proved, contracted without materializing).
Interval narrow(const Algebraic_real& x) {
  const std::pair<double, double> d = x.to_interval();
  return {Rational(d.first), Rational(d.second)};
}

std::string describe(const Algebraic_real& x) { return x.to_decimal_string(17); }
std::string describe(const Rational& x) { return std::to_string(x.numerator().to_double()) + "/" + std::to_string(x.denominator().to_double()); }

// Fails unless C1(s) = C2(t) is possible: the boxes of both images over the enclosures must meet.
void check_on_both(const Curve& c1, const Algebraic_real& s, const Curve& c2, const Algebraic_real& t,
                   const std::string& what) {
  for (const Algebraic_real* x : {&s, &t})
    if (x->compare(Rational(0)) < 0 || x->compare(Rational(1)) > 0)
      fuzz_failure(what + ": parameter " + describe(*x) + " outside [0, 1]");
  const auto a = image_over(c1, narrow(s)), b = image_over(c2, narrow(t));
  if (!a || !b) return;  // a weight near 0 at the point: the boxes decide nothing
  for (int k = 0; k < 2; ++k)
    if ((*a)[k].hi < (*b)[k].lo || (*b)[k].hi < (*a)[k].lo)
      fuzz_failure(what + " (s = " + describe(s) + ", t = " + describe(t) + "): the images differ in coordinate " +
                   std::to_string(k) + ", [" + std::to_string(CGAL::to_double((*a)[k].lo)) + ", " +
                   std::to_string(CGAL::to_double((*a)[k].hi)) + "] and [" +
                   std::to_string(CGAL::to_double((*b)[k].lo)) + ", " + std::to_string(CGAL::to_double((*b)[k].hi)) +
                   "]");
}

// Every point and overlap end on both curves; points sorted by s then t, no point twice.
void check_result(const Curve& c1, const Curve& c2, const Curve_intersection_result& r, const std::string& call) {
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const Curve_intersection_point& p = r.points[i];
    check_on_both(c1, p.s, c2, p.t, call + " point " + std::to_string(i));
    if (p.multiplicity < 1) fuzz_failure(call + ": multiplicity " + std::to_string(p.multiplicity) + " < 1");
    if (i > 0) {
      const Curve_intersection_point& q = r.points[i - 1];
      const int c = q.s.compare(p.s);
      if (c > 0 || (c == 0 && !(q.t < p.t)))
        fuzz_failure(call + ": points " + std::to_string(i - 1) + " and " + std::to_string(i) +
                     " not strictly sorted by (s, t)");
    }
  }
  for (std::size_t i = 0; i < r.overlaps.size(); ++i) {
    const Curve_overlap& o = r.overlaps[i];
    check_on_both(c1, o.s0, c2, o.t0, call + " overlap " + std::to_string(i) + " start");
    check_on_both(c1, o.s1, c2, o.t1, call + " overlap " + std::to_string(i) + " end");
    if (o.s1 < o.s0) fuzz_failure(call + ": overlap " + std::to_string(i) + " with s1 < s0");
  }
}

// The refusals the entry points document: Invalid_input (a pole in [0, 1], a zero control vector),
// Limit_exceeded / Budget_exceeded (the limits below), and the Error of a curve with a base point, of a
// self-intersection system that degenerates (a line traversed back and forth) and of the shear fallback.
bool documented_error(const Error& e) {
  if (dynamic_cast<const Invalid_input*>(&e) || dynamic_cast<const Limit_exceeded*>(&e)) return true;
  const std::string m = e.what();
  for (const char* prefix : {"intersect_curves: a curve has a base point",
                             "self_intersections: the curve is a straight line traversed non-monotonically",
                             "intersect_curves: no separating shear found"})
    if (m.rfind(prefix, 0) == 0) return true;
  return false;
}

enum class Refusal { none, limit, other };

bool improper(const Curve& c);

// Runs `f` on the curves `c` (none while they are built); a documented refusal is returned as such, anything else
// thrown fails. An Error on improper curves is their documented limitation (see improper()).
template <class F>
Refusal run(const std::string& call, F f, std::initializer_list<const Curve*> c = {}) {
  try {
    f();
    return Refusal::none;
  } catch (const Limit_exceeded&) {
    return Refusal::limit;
  } catch (const Error& e) {
    if (documented_error(e)) return Refusal::other;
    for (const Curve* x : c)
      if (improper(*x)) return Refusal::other;
    fuzz_failure(call + " threw an undocumented " + typeid(e).name() + ": " + e.what());
  } catch (const std::exception& e) {
    fuzz_failure(call + " threw " + typeid(e).name() + ": " + e.what());
  } catch (...) {
    fuzz_failure(call + " threw something that is not a std::exception");
  }
}

// How the second curve is made: independent, or from the first so that the answer is partly known.
enum class Second { independent, restriction, through_point, elevated_or_reversed, perturbed };

Second pick_second(std::uint8_t b) {
  switch (b % 8) {
    case 4: return Second::restriction;
    case 5: return Second::through_point;
    case 6: return Second::elevated_or_reversed;
    case 7: return Second::perturbed;
    default: return Second::independent;
  }
}

// The exact point C(sigma), if W(sigma) != 0 (de Casteljau on the homogeneous net, written here).
std::optional<Curve::Point> exact_point(const Curve& c, const Rational& sigma) {
  std::array<Rational, 3> v;
  for (int k = 0; k < 3; ++k) v[k] = coordinate_over(c, k, {sigma, sigma}).lo;
  if (CGAL::is_zero(v[0])) return std::nullopt;
  return Curve::Point{v[1] / v[0], v[2] / v[0]};
}

// True unless the parametrization is proper (one parameter per point of the image, but finitely many): the
// divided differences (X_k(s) W(t) - X_k(t) W(s)) / (s - t) then have no common factor. A curve of degree >= 2 on
// a line, one of the form C(phi(s)), or one with a base point is improper, and the overlaps of such a curve are
// outside what intersect_curves promises (doc/curve_intersection.md: parametrizations that cover each arc once).
bool improper(const Curve& c) {
  using P1 = Polynomial_1<Integer>;
  using P2 = Polynomial_2<Integer>;
  const Curve::Power_form f = c.power_form();
  Rational scale(1);  // clears every denominator of the power form
  for (const auto& q : f)
    for (int i = 0; i <= q.degree(); ++i) scale *= Rational(q[i].denominator());
  std::array<P1, 3> g;
  for (int k = 0; k < 3; ++k) {
    std::vector<Integer> co;
    for (int i = 0; i <= f[k].degree(); ++i) co.push_back((f[k][i] * scale).numerator());
    g[k] = P1(co.begin(), co.end());
  }
  auto cross = [&](int k) {  // X_k(s) W(t) - X_k(t) W(s), s the inner variable
    std::vector<P1> by_t;
    for (int j = 0; j <= std::max(g[0].degree(), g[k].degree()); ++j) {
      const Integer w = j <= g[0].degree() ? g[0][j] : Integer(0), x = j <= g[k].degree() ? g[k][j] : Integer(0);
      by_t.push_back(g[k] * P1(w) - g[0] * P1(x));
    }
    return P2(by_t.begin(), by_t.end());
  };
  const P2 h = CGAL::gcd(cross(1), cross(2));
  return CGAL::is_zero(h) || h.degree() != 1;  // zero: a constant curve (its answers are checked above)
}

} // namespace

void planar_curves(const std::uint8_t* data, std::size_t size) {
  Byte_reader in(data, size);
  const Header h(in.next());
  Curve_intersection_options options;
  options.method = h.method;
  // small sizes and a time budget, so that no input can run for long (one stage may overrun it: a self-intersecting
  // rational quintic, and a quintic against a rational cubic on a line, spent over 10 s under the sanitizers in the
  // shear stage, hence the degree product)
  options.limits.max_degree = 5;
  options.limits.max_degree_product = 12;
  options.limits.max_coefficient_bits = 128;
  options.limits.time_limit = 2;

  Curve c1;
  if (run("building curve 1", [&] { c1 = read_curve(in, h); }) != Refusal::none) return;
  if (h.self) {
    Curve_intersection_result r;
    if (run("self_intersections", [&] { r = self_intersections(c1, options); }, {&c1}) != Refusal::none) return;
    check_result(c1, c1, r, "self_intersections");
    for (std::size_t i = 0; i < r.points.size(); ++i)
      if (!(r.points[i].s < r.points[i].t))
        fuzz_failure("self_intersections: point " + std::to_string(i) + " without s < t (s = " +
                     describe(r.points[i].s) + ", t = " + describe(r.points[i].t) + ")");
    return;
  }

  // the second curve; `known` is a point (sigma, 0) that must be found unless the curves overlap
  const Second second = pick_second(in.next());
  Curve c2;
  std::optional<Rational> known;
  const Refusal built = run("building curve 2", [&] {
    switch (second) {
      case Second::independent: c2 = read_curve(in, h); break;
      case Second::restriction: {
        const Rational a(in.next() % 9, 8), b(in.next() % 9, 8);
        c2 = c1.restriction(a, b);
        break;
      }
      case Second::elevated_or_reversed: c2 = (in.next() & 1) ? c1.elevated() : c1.reversed(); break;
      case Second::through_point: {
        c2 = read_curve(in, h);
        const Rational sigma(in.next() % 9, 8);
        if (const auto p = exact_point(c1, sigma)) {
          std::vector<Hpoint> net = c2.homogeneous_control_points();
          if (!CGAL::is_zero(net[0][0])) {
            net[0] = Hpoint{net[0][0], net[0][0] * (*p)[0], net[0][0] * (*p)[1]};
            c2 = Curve::from_homogeneous(net);
            known = sigma;
          }
        }
        break;
      }
      case Second::perturbed: {
        std::vector<Hpoint> net = c1.homogeneous_control_points();
        Hpoint& q = net[in.next() % net.size()];
        q[1] += q[0] * Rational(in.next_signed() % 3, 4);
        q[2] += q[0] * Rational(in.next_signed() % 3, 4);
        c2 = Curve::from_homogeneous(net);
        break;
      }
    }
  });
  if (built != Refusal::none) return;

  Curve_intersection_result ab, ba;
  const Refusal rab = run("intersect_curves(c1, c2)", [&] { ab = intersect_curves(c1, c2, options); }, {&c1, &c2});
  if (rab == Refusal::none) check_result(c1, c2, ab, "intersect_curves(c1, c2)");
  const Refusal rba = run("intersect_curves(c2, c1)", [&] { ba = intersect_curves(c2, c1, options); }, {&c1, &c2});
  if (rba == Refusal::none) check_result(c2, c1, ba, "intersect_curves(c2, c1)");
  if (rab == Refusal::limit || rba == Refusal::limit) return;
  // improper curves: the answers are checked above; how they are split into overlaps and points is not promised
  if (improper(c1) || improper(c2)) return;
  if (rab != rba) fuzz_failure("intersect_curves refused one order of the curves and answered the other");
  if (rab != Refusal::none) return;

  // what the construction of the second curve guarantees
  if ((second == Second::restriction || second == Second::elevated_or_reversed) && ab.overlaps.empty())
    fuzz_failure("the second curve is a piece of the first, but no overlap was reported");
  if (known && ab.overlaps.empty()) {
    bool found = false;
    for (const auto& p : ab.points) found = found || (p.s == Algebraic_real(*known) && p.t == Algebraic_real(0));
    if (!found) fuzz_failure("curve 2 starts at C1(" + describe(*known) + "), but (s, t) = (" + describe(*known) +
                             ", 0) was not reported");
  }

  // every method gives the same answer (doc/curve_intersection.md: the same certified pairing after each eliminant)
  if (h.method != Curve_intersection_method::default_method) {
    Curve_intersection_options d = options;
    d.method = Curve_intersection_method::default_method;
    Curve_intersection_result r;
    if (run("intersect_curves(c1, c2) with the default method", [&] { r = intersect_curves(c1, c2, d); }, {&c1, &c2}) ==
        Refusal::none) {
      bool same = r.points.size() == ab.points.size() && r.overlaps.size() == ab.overlaps.size();
      for (std::size_t i = 0; same && i < r.points.size(); ++i)
        same = r.points[i].s == ab.points[i].s && r.points[i].t == ab.points[i].t &&
               r.points[i].kind == ab.points[i].kind && r.points[i].tangent == ab.points[i].tangent &&
               r.points[i].multiplicity == ab.points[i].multiplicity;
      if (!same) fuzz_failure("intersect_curves: the default method and the chosen one give different answers");
    }
  }

  // both orders: the same points with s and t exchanged (overlap ends may be split differently, so with an
  // overlap only its presence is compared)
  if (ab.overlaps.empty() != ba.overlaps.empty())
    fuzz_failure("intersect_curves reports an overlap in one order of the curves only");
  if (!ab.overlaps.empty()) return;
  if (ab.points.size() != ba.points.size())
    fuzz_failure("intersect_curves: " + std::to_string(ab.points.size()) + " points for (c1, c2), " +
                 std::to_string(ba.points.size()) + " for (c2, c1)");
  for (std::size_t i = 0; i < ab.points.size(); ++i) {
    const Curve_intersection_point& p = ab.points[i];
    bool matched = false;
    for (const auto& q : ba.points)
      if (q.s == p.t && q.t == p.s) {
        matched = true;
        if (q.kind != p.kind || q.tangent != p.tangent)
          fuzz_failure("intersect_curves: point " + std::to_string(i) + " is " + to_string(p.kind) +
                       (p.tangent ? " tangent" : "") + " for (c1, c2) and " + to_string(q.kind) +
                       (q.tangent ? " tangent" : "") + " for (c2, c1)");
      }
    if (!matched)
      fuzz_failure("intersect_curves: point " + std::to_string(i) + " (s = " + describe(p.s) + ", t = " +
                   describe(p.t) + ") of (c1, c2) is missing from (c2, c1)");
  }
}

} // namespace fuzz
} // namespace bezoutian

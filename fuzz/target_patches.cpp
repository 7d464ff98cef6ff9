// Fuzz target: surface/surface intersections and self-intersections of small patches
// (intersection/Surface_intersection.h).
//
// The bytes are decoded straight into a problem: a header byte, then the patches. The answer is checked with an
// evaluation of the patches written here (de Casteljau in double on the homogeneous net), not with the library's,
// so that a wrong point cannot pass by sharing a mistake with the code under test. What is checked is what the
// library proves: every traced point whose genuine status is proved has both parameter points in their domains,
// distinct for a self-intersection, and one 3D point; the partner enclosure holds the reported partner's domain
// side; nothing but a documented refusal is thrown; the time budget holds the call to a few seconds.
#include "byte_reader.h"
#include "targets.h"

#include <bezoutian/intersection/Surface_intersection.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <typeinfo>
#include <vector>

namespace bezoutian {
namespace fuzz {
namespace {

using Patch = Rational_bezier_patch<>;
using Hpoint = Patch::Homogeneous_point;

// Header byte: bit 0 self-intersection, bit 1 rational, bit 2 weights of any sign (0 included), bit 3 the
// coordinate alphabet (tiny integers: coincidences, planes, shared edges; or small rationals), bits 4-6 how the
// second patch is made.
struct Header {
  bool self, rational, signed_weights, tiny;
  int second;
  explicit Header(std::uint8_t b)
      : self(b & 1), rational(b & 2), signed_weights(b & 4), tiny(b & 8), second((b >> 4) & 7) {}
};

Rational coordinate(Byte_reader& in, bool tiny) {
  const int b = in.next_signed();
  return tiny ? Rational(b % 3) : Rational(b % 17, 1 + in.next() % 8);
}

Rational weight(Byte_reader& in, const Header& h) {
  if (!h.rational) return Rational(1);
  if (h.signed_weights) return Rational(in.next_signed() % 4);  // -3 .. 3: poles and points at infinity
  return Rational(1 + in.next() % 4);
}

// A patch of bi-degree (1 or 2, 1 or 2) from homogeneous points (w, w x, w y, w z).
Patch read_patch(Byte_reader& in, const Header& h) {
  const int b = in.next(), m = 1 + (b & 1), n = 1 + ((b >> 1) & 1);
  Patch::Net net(std::size_t(m + 1), std::vector<Hpoint>(std::size_t(n + 1)));
  for (auto& row : net)
    for (Hpoint& p : row) {
      const Rational x = coordinate(in, h.tiny), y = coordinate(in, h.tiny), z = coordinate(in, h.tiny);
      const Rational w = weight(in, h);
      p = CGAL::is_zero(w) ? Hpoint{w, x, y, z} : Hpoint{w, w * x, w * y, w * z};
    }
  return Patch::from_homogeneous(net);
}

// ------------------------------------------------------------------ the oracle: double de Casteljau
struct Evaluation {
  std::array<double, 3> point;
  double weight_ratio;  // |W(u, v)| / max |w_ij|: near 0 the point is not decided by this evaluation
};

Evaluation evaluate(const Patch& p, double u, double v) {
  const int m = p.degree_u(), n = p.degree_v();
  std::array<double, 4> acc{};
  std::vector<std::array<double, 4>> col(std::size_t(m + 1));
  double w_max = 0;
  for (int i = 0; i <= m; ++i) {
    std::vector<std::array<double, 4>> row(std::size_t(n + 1));
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k < 4; ++k) {
        row[std::size_t(j)][std::size_t(k)] = CGAL::to_double(p.homogeneous_control_point(std::size_t(i), std::size_t(j))[std::size_t(k)]);
        if (k == 0) w_max = std::max(w_max, std::fabs(row[std::size_t(j)][0]));
      }
    for (int r = n; r > 0; --r)
      for (int j = 0; j < r; ++j)
        for (int k = 0; k < 4; ++k)
          row[std::size_t(j)][std::size_t(k)] = (1 - v) * row[std::size_t(j)][std::size_t(k)] + v * row[std::size_t(j + 1)][std::size_t(k)];
    col[std::size_t(i)] = row[0];
  }
  for (int r = m; r > 0; --r)
    for (int i = 0; i < r; ++i)
      for (int k = 0; k < 4; ++k)
        col[std::size_t(i)][std::size_t(k)] = (1 - u) * col[std::size_t(i)][std::size_t(k)] + u * col[std::size_t(i + 1)][std::size_t(k)];
  acc = col[0];
  return {{acc[1] / acc[0], acc[2] / acc[0], acc[3] / acc[0]}, w_max > 0 ? std::fabs(acc[0]) / w_max : 0};
}

double scale_of(const Patch& p) {
  double s = 1;
  for (int i = 0; i <= p.degree_u(); ++i)
    for (int j = 0; j <= p.degree_v(); ++j) {
      const Hpoint& h = p.homogeneous_control_point(std::size_t(i), std::size_t(j));
      if (CGAL::is_zero(h[0])) continue;
      for (int k = 1; k < 4; ++k) s = std::max(s, std::fabs(CGAL::to_double(h[std::size_t(k)] / h[0])));
    }
  return s;
}

bool in_unit_square(const std::array<double, 2>& x, double slack) {
  return x[0] >= -slack && x[0] <= 1 + slack && x[1] >= -slack && x[1] <= 1 + slack;
}

// Every traced point proved genuine: both parameter points in [0, 1]^2, distinct for a self-intersection, mapped
// to one 3D point (up to the floating point of the traced point: 1e-5 of the patches' size where both weights are
// well away from 0).
void check_locus(const Patch& phi, const Patch& psi, bool self, const Surface_locus& L, const std::string& call) {
  const double size = std::max(scale_of(phi), scale_of(psi));
  for (std::size_t a = 0; a < L.arcs.size(); ++a)
    for (std::size_t i = 0; i < L.arcs[a].points.size(); ++i) {
      const Locus_point& q = L.arcs[a].points[i];
      if (!(q.status_proved && q.genuine)) continue;
      const std::string where = call + ": arc " + std::to_string(a) + " point " + std::to_string(i);
      if (!in_unit_square(q.first, 1e-9) || !in_unit_square(q.second, 1e-9))
        fuzz_failure(where + " proved genuine with a parameter point outside [0, 1]^2: (" +
                     std::to_string(q.first[0]) + ", " + std::to_string(q.first[1]) + "), (" +
                     std::to_string(q.second[0]) + ", " + std::to_string(q.second[1]) + ")");
      if (self && q.first == q.second) fuzz_failure(where + " proved genuine with its trivial partner");
      const Evaluation x = evaluate(phi, q.first[0], q.first[1]), y = evaluate(psi, q.second[0], q.second[1]);
      if (x.weight_ratio < 1e-3 || y.weight_ratio < 1e-3) continue;
      double d = 0;
      for (int k = 0; k < 3; ++k) d = std::max(d, std::fabs(x.point[std::size_t(k)] - y.point[std::size_t(k)]));
      if (!(d <= 1e-5 * size))
        fuzz_failure(where + " proved genuine, but its two parameter points are " + std::to_string(d) +
                     " apart in 3D (patch size " + std::to_string(size) + ")");
      for (int c = 0; c < 2; ++c)
        if (!(q.partner_enclosure[std::size_t(c)][0] <= q.partner_enclosure[std::size_t(c)][1]))
          fuzz_failure(where + " proved genuine without a partner enclosure");
    }
}

// Runs `f`; documented refusals (Invalid_input: degenerate patches, zero weights, det B vanishing without a
// projection operator; Limit_exceeded: the limits below; the Error of boundary contacts that the curve engine
// does not decide) return false, anything else thrown fails.
template <class F>
bool run(const std::string& call, F f) {
  try {
    f();
    return true;
  } catch (const Limit_exceeded&) {
    return false;
  } catch (const Invalid_input&) {
    return false;
  } catch (const Error& e) {
    // the boundary contacts rest on intersect_curves, whose shear fallback may not separate a tangency
    if (std::string(e.what()).rfind("intersection_locus: the contacts of side ", 0) == 0) return false;
    fuzz_failure(call + " threw an undocumented " + typeid(e).name() + ": " + e.what());
  } catch (const std::exception& e) {
    fuzz_failure(call + " threw " + typeid(e).name() + ": " + e.what());
  } catch (...) {
    fuzz_failure(call + " threw something that is not a std::exception");
  }
}

}  // namespace

void small_patches(const std::uint8_t* data, std::size_t size) {
  Byte_reader in(data, size);
  const Header h(in.next());
  Surface_intersection_options options;
  // small sizes and a time budget (checked between the stages and per arc of the proved lifting), and no
  // whole-plane analysis, whose time has no bound
  options.limits.max_degree = 2;
  options.limits.max_coefficient_bits = 64;
  options.limits.time_limit = 2;
  options.max_total_degree_for_topology = 0;
  std::optional<Patch> built_phi;
  if (!run("building patch 1", [&] { built_phi = read_patch(in, h); })) return;
  const Patch& phi = *built_phi;
  if (h.self) {
    Surface_locus L;
    if (run("self_intersection_locus", [&] { L = self_intersection_locus(phi, options); }))
      check_locus(phi, phi, true, L, "self_intersection_locus");
    return;
  }
  // the second patch: independent, or made from the first (its transposed net: the same surface; a sub-patch: an
  // overlap; a control point moved: a near copy)
  std::optional<Patch> psi;
  const bool built = run("building patch 2", [&] {
    switch (h.second) {
      case 1: psi = phi.transposed(); break;
      case 2: {
        const Rational a(in.next() % 4, 8), b(4 + in.next() % 5, 8);
        psi = phi.restriction(a, b, Rational(0), Rational(1));
        break;
      }
      case 3: {
        Patch::Net net(std::size_t(phi.degree_u() + 1), std::vector<Hpoint>(std::size_t(phi.degree_v() + 1)));
        for (int i = 0; i <= phi.degree_u(); ++i)
          for (int j = 0; j <= phi.degree_v(); ++j)
            net[std::size_t(i)][std::size_t(j)] = phi.homogeneous_control_point(std::size_t(i), std::size_t(j));
        Hpoint& q = net[in.next() % net.size()][in.next() % net[0].size()];
        q[3] += q[0] * Rational(in.next_signed() % 3, 4);
        psi = Patch::from_homogeneous(net);
        break;
      }
      default: psi = read_patch(in, h);
    }
  });
  if (!built) return;
  Surface_locus L;
  if (run("intersection_locus", [&] { L = intersection_locus(phi, *psi, options); }))
    check_locus(phi, *psi, false, L, "intersection_locus");
}

}  // namespace fuzz
}  // namespace bezoutian

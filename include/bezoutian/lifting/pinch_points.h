// Pinch points of a patch: parameter points where its Jacobian has rank 1 (Whitney umbrellas, cross-caps). There
// the double-point curve of a self-intersection ends inside the domain: along the locus D = 0 the partner tends to
// the point itself (buse-elkadi-galligo-2008 §4: the trivial partner (k, l) = (0, 0)), and beyond it the two
// preimages of the double curve are complex conjugate.
//
// With phi = (a1, a2, a3) / a0, rank d(phi) = 1 at x iff phi_u + m phi_v = 0 for some m (chart 0) or
// m phi_u + phi_v = 0 (chart 1). Clearing a0^2 gives three polynomial equations in (u, v, m):
//   G_c = H_c + m K_c (chart 0),  m H_c + K_c (chart 1),   H_c = a_c,u a0 - a_c a0,u,  K_c = a_c,v a0 - a_c a0,v,
// square in (u, v, m). Every solution with |m| <= 1 in one of the charts (so every kernel direction) and (u, v)
// in the box is found by subdivision of box x [-1, 1]: a sub-box is discarded when some G_c excludes 0 on it
// (interval evaluation), and a solution is isolated by Krawczyk's test (MPFI, arithmetic/interval_krawczyk.h) on a
// small box, which proves that it holds exactly one solution and that the solution is simple. The subdivision is
// complete when every sub-box is discarded or lies in a proved box. A solution that is not simple (structured
// patches: a fold v -> v^2 meeting the rank-one locus) or a point where d(phi) = 0 (rank 0) leaves a box that is
// neither; then the rank-one points are computed exactly as the common zeros of the normal's components
// (internal/exact_rank_one_points.h), which decides when one of their coordinates is rational. Otherwise the search
// says that it is incomplete, and where.
#ifndef BEZOUTIAN_LIFTING_PINCH_POINTS_H
#define BEZOUTIAN_LIFTING_PINCH_POINTS_H

#include <bezoutian/topology/Curve_topology.h>
#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/lifting/certified_lifting.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/lifting/internal/exact_rank_one_points.h>
#include <bezoutian/arithmetic/interval_krawczyk.h>

#include <array>
#include <string>
#include <vector>

namespace bezoutian {

/// A pinch point of a patch (rank-1 Jacobian) in the analysed box: `box` {u, v} holds exactly one, with the kernel
/// direction (1, m) (chart 0) or (m, 1) (chart 1), m in `m`. Bounds are exact rationals (refinable).
struct Pinch_point {
  std::array<std::array<Rational, 2>, 2> box;
  int chart = 0;
  std::array<Rational, 2> m;
  double u = 0, v = 0;  ///< midpoint of the box
  bool rank_zero = false;  ///< d(phi) = 0 at the point: no kernel direction (chart 0, m = [-1, 1] by convention)
};

/// All pinch points of a patch in a box, and whether the search is complete (every other point excluded).
struct Pinch_point_search {
  std::vector<Pinch_point> points;
  bool complete = false;
  std::string reason;  ///< why the search is not complete
};

namespace internal {

// A bivariate polynomial (CGAL's Polynomial_2, inner variable u) as its coefficient matrix c[j][i] of u^i v^j,
// for fast evaluation.
struct Bivariate {
  std::vector<std::vector<Rational>> c;
  explicit Bivariate(const Polynomial_2<Rational>& p) {
    int m = 0;
    for (int j = 0; j <= p.degree(); ++j) m = std::max(m, p[j].degree());
    c.assign(p.degree() + 1, std::vector<Rational>(m + 1, Rational(0)));
    for (int j = 0; j <= p.degree(); ++j)
      for (int i = 0; i <= p[j].degree(); ++i) c[j][i] = p[j][i];
  }
};

// Interval evaluation of a bivariate polynomial: Horner in double intervals (outward coefficient enclosures).
struct Bivariate_enclosure {
  std::vector<std::vector<Double_interval>> c;
  explicit Bivariate_enclosure(const Bivariate& b) {
    for (const auto& row : b.c) {
      c.emplace_back();
      for (const Rational& q : row) c.back().push_back(Double_interval::of(q));
    }
  }
  Double_interval operator()(const Double_interval& u, const Double_interval& v) const {
    return interval_horner(c, u, v);
  }
};

inline Mpfi_interval evaluate_mpfi(const Bivariate& b, const Mpfi_interval& u, const Mpfi_interval& v) {
  const mpfr_prec_t prec = u.prec();
  Mpfi_interval r = Mpfi_interval::point(0, prec);
  for (std::size_t j = b.c.size(); j-- > 0;) {
    Mpfi_interval s = Mpfi_interval::point(0, prec);
    for (std::size_t i = b.c[j].size(); i-- > 0;) s = s * u + Mpfi_interval::hull(b.c[j][i], b.c[j][i], prec);
    r = r * v + s;
  }
  return r;
}

/// The pinch-point system of a patch: H_c, K_c and their first derivatives (see the header comment).
class Pinch_system {
 public:
  explicit Pinch_system(const Rational_bezier_patch<Rational>& phi) {
    using P2 = Polynomial_2<Rational>;
    const auto diff = [](const P2& p, int variable) {  // variable 0: u (inner), 1: v
      return typename CGAL::Polynomial_traits_d<P2>::Differentiate()(p, variable);
    };
    const auto a = phi.power_form();
    for (int c = 0; c < 3; ++c) {
      const P2 H = diff(a[c + 1], 0) * a[0] - a[c + 1] * diff(a[0], 0);
      const P2 K = diff(a[c + 1], 1) * a[0] - a[c + 1] * diff(a[0], 1);
      H_.emplace_back(H);
      K_.emplace_back(K);
      for (int d = 0; d < 2; ++d) {
        Hd_[c].emplace_back(diff(H, d));
        Kd_[c].emplace_back(diff(K, d));
      }
      He_.emplace_back(H_[c]);
      Ke_.emplace_back(K_[c]);
      for (int d = 0; d < 2; ++d) {
        Hde_[c].emplace_back(Hd_[c][d]);
        Kde_[c].emplace_back(Kd_[c][d]);
      }
    }
  }
  /// G and its Jacobian (rows c, columns u, v, m) over the box x (outward-rounded double intervals).
  void evaluate(int chart, const std::array<Double_interval, 3>& x, std::array<Double_interval, 3>& G,
                std::array<std::array<Double_interval, 3>, 3>* J) const {
    for (int c = 0; c < 3; ++c) {
      const Double_interval h = He_[c](x[0], x[1]), k = Ke_[c](x[0], x[1]);
      G[c] = chart == 0 ? h + x[2] * k : x[2] * h + k;
      if (!J) continue;
      for (int d = 0; d < 2; ++d) {
        const Double_interval hd = Hde_[c][d](x[0], x[1]), kd = Kde_[c][d](x[0], x[1]);
        (*J)[c][d] = chart == 0 ? hd + x[2] * kd : x[2] * hd + kd;
      }
      (*J)[c][2] = chart == 0 ? k : h;
    }
  }
  /// Does some G_c exclude 0 on the box x (chart)? Naive Horner and the mean-value form about the centre.
  bool excluded(int chart, const std::array<Double_interval, 3>& x) const {
    std::array<Double_interval, 3> G, Gc, c;
    std::array<std::array<Double_interval, 3>, 3> J;
    evaluate(chart, x, G, nullptr);  // the cheap test first
    for (int r = 0; r < 3; ++r)
      if (!G[r].contains_zero()) return true;
    evaluate(chart, x, G, &J);
    for (int d = 0; d < 3; ++d) c[d] = Double_interval{x[d].mid(), x[d].mid()};
    evaluate(chart, c, Gc, nullptr);
    for (int r = 0; r < 3; ++r) {
      Double_interval g = Gc[r];
      for (int d = 0; d < 3; ++d) g = g + J[r][d] * (x[d] - c[d]);
      if (!g.contains_zero()) return true;
    }
    // preconditioned: any combination C G of the equations vanishes with them; with C ~ J(centre)^-1 the rows of
    // C G are nearly decoupled, so a box without a solution is excluded while still wide (interval Newton's idea)
    double A[3][3], C[3][3];
    for (int r = 0; r < 3; ++r)
      for (int d = 0; d < 3; ++d) A[r][d] = J[r][d].mid();
    if (!invert_3x3(A, C)) return false;
    for (int r = 0; r < 3; ++r) {
      Double_interval g{0, 0};
      for (int k = 0; k < 3; ++k) g = g + Double_interval{C[r][k], C[r][k]} * Gc[k];
      for (int d = 0; d < 3; ++d) {
        Double_interval slope{0, 0};
        for (int k = 0; k < 3; ++k) slope = slope + Double_interval{C[r][k], C[r][k]} * J[k][d];
        g = g + slope * (x[d] - c[d]);
      }
      if (!g.contains_zero()) return true;
    }
    return false;
  }
  /// Newton's method in doubles from z (a guess for the proofs, never a decision); false if it does not converge.
  bool newton(int chart, std::array<double, 3>& z, double radius) const {
    const std::array<double, 3> z0 = z;
    for (int it = 0; it < 20; ++it) {
      std::array<Double_interval, 3> x, G;
      for (int d = 0; d < 3; ++d) x[d] = Double_interval{z[d], z[d]};
      std::array<std::array<Double_interval, 3>, 3> J;
      evaluate(chart, x, G, &J);
      double A[3][3], C[3][3];
      for (int r = 0; r < 3; ++r)
        for (int d = 0; d < 3; ++d) A[r][d] = J[r][d].mid();
      if (!invert_3x3(A, C)) return false;
      double step = 0;
      for (int r = 0; r < 3; ++r) {
        const double dz = C[r][0] * G[0].mid() + C[r][1] * G[1].mid() + C[r][2] * G[2].mid();
        z[r] -= dz;
        step += std::fabs(dz);
      }
      if (!std::isfinite(step)) return false;
      for (int r = 0; r < 3; ++r)  // left the cell's neighbourhood: not this cell's solution
        if (std::fabs(z[r] - z0[r]) > radius) return false;
      if (step < 1e-14 * (1 + std::fabs(z[0]) + std::fabs(z[1]) + std::fabs(z[2]))) return true;
    }
    return false;
  }
  /// Krawczyk's proof on X = (u, v, m) (MPFI); on success X is a box holding exactly one simple solution.
  bool prove(int chart, std::array<Mpfi_interval, 3>& X, int contractions) const {
    using I = Mpfi_interval;
    auto value = [&](const std::array<I, 3>& x, std::array<I, 3>& F) {
      for (int c = 0; c < 3; ++c) {
        const I h = evaluate_mpfi(H_[c], x[0], x[1]), k = evaluate_mpfi(K_[c], x[0], x[1]);
        F[c] = chart == 0 ? h + x[2] * k : x[2] * h + k;
      }
    };
    auto jacobian = [&](const std::array<I, 3>& x, std::vector<std::vector<I>>& J) {
      for (int c = 0; c < 3; ++c) {
        for (int d = 0; d < 2; ++d) {
          const I hd = evaluate_mpfi(Hd_[c][d], x[0], x[1]), kd = evaluate_mpfi(Kd_[c][d], x[0], x[1]);
          J[c][d] = chart == 0 ? hd + x[2] * kd : x[2] * hd + kd;
        }
        J[c][2] = chart == 0 ? evaluate_mpfi(K_[c], x[0], x[1]) : evaluate_mpfi(H_[c], x[0], x[1]);
      }
    };
    return krawczyk_prove<3>(X, value, jacobian, contractions);
  }

 private:
  std::vector<Bivariate> H_, K_;
  std::array<std::vector<Bivariate>, 3> Hd_, Kd_;
  std::vector<Bivariate_enclosure> He_, Ke_;
  std::array<std::vector<Bivariate_enclosure>, 3> Hde_, Kde_;
};

/// The subdivision search for every pinch point of `phi` in `box` (see the header comment). `max_boxes` bounds it.
inline Pinch_point_search find_pinch_points_by_subdivision(const Rational_bezier_patch<Rational>& phi, const Parameter_box& box,
                                            std::size_t max_boxes = 600000) {
  using D = Double_interval;
  using I = Mpfi_interval;
  const Pinch_system S(phi);
  Pinch_point_search out;
  out.complete = true;
  const mpfr_prec_t prec = 128;
  struct Found {
    int chart;
    std::array<I, 3> unique;  // the box of the proof: it holds exactly this one solution
    std::array<I, 3> X;       // a contracted enclosure of the solution
  };
  std::vector<Found> found;
  // every box proved to hold exactly one solution (each a found one): a cell inside one holds no other. Kept as
  // double boxes rounded inwards (a cell inside the double box is inside the proved one): the test runs for
  // every cell against every region, and exact comparisons made it most of the search's time.
  struct Region {
    int chart;
    std::array<double, 3> lo, hi;
  };
  std::vector<Region> regions;
  auto add_region = [&](int chart, const std::array<I, 3>& U) {
    Region r{chart, {}, {}};
    for (int c = 0; c < 3; ++c) {
      r.lo[c] = CGAL::to_interval(U[c].lower()).second;  // >= the exact lower end
      r.hi[c] = CGAL::to_interval(U[c].upper()).first;   // <= the exact upper end
    }
    regions.push_back(r);
  };
  auto inside = [](const I& a, const I& b) { return b.lower() <= a.lower() && a.upper() <= b.upper(); };
  // is the solution of f the one of g? f's enclosure, mapped to g's chart, lies in g's box of uniqueness
  auto same = [&](const Found& f, const Found& g) {
    if (!inside(f.X[0], g.unique[0]) || !inside(f.X[1], g.unique[1])) return false;
    if (f.chart == g.chart) return inside(f.X[2], g.unique[2]);
    if (f.X[2].contains_zero()) return false;  // m = 0 in one chart is infinite in the other
    const I inv = I::point(1, prec) / f.X[2];
    return inside(inv, g.unique[2]);
  };
  struct Cell {
    std::array<D, 3> x;
    int depth;
  };
  std::size_t boxes = 0;
  for (int chart = 0; chart < 2 && out.complete; ++chart) {
    std::vector<Cell> todo{{{D::hull(box.u0, box.u1), D::hull(box.v0, box.v1), D{-1, 1}}, 0}};
    while (!todo.empty()) {
      const Cell cell = todo.back();
      todo.pop_back();
      if (++boxes > max_boxes) {
        out.complete = false;
        out.reason = "the subdivision budget of " + std::to_string(max_boxes) + " boxes is spent (last box near (u, v, m) = (" +
                     std::to_string(cell.x[0].mid()) + ", " + std::to_string(cell.x[1].mid()) + ", " +
                     std::to_string(cell.x[2].mid()) + "), chart " + std::to_string(chart) + ", depth " +
                     std::to_string(cell.depth) + ")";
        break;
      }
      const auto& x = cell.x;
      if (S.excluded(chart, x)) continue;
      // inside a box already proved to hold exactly one (found) solution of this chart?
      auto covered = [&]() {
        for (const Region& r : regions)
          if (r.chart == chart && r.lo[0] <= x[0].lo && x[0].hi <= r.hi[0] && r.lo[1] <= x[1].lo &&
              x[1].hi <= r.hi[1] && r.lo[2] <= x[2].lo && x[2].hi <= r.hi[2])
            return true;
        return false;
      };
      if (covered()) continue;
      const double w = std::max({x[0].hi - x[0].lo, x[1].hi - x[1].lo, x[2].hi - x[2].lo});
      std::array<double, 3> z{x[0].mid(), x[1].mid(), x[2].mid()};
      if (w < 1.0 / 16 && S.newton(chart, z, w)) {
        // a solution near the cell: Krawczyk's proof on boxes around it, the largest first (one that contains
        // the cell ends its subdivision)
        for (double r : {2 * w, w / 8, w / 128, 1e-9 * (1 + std::fabs(z[0]) + std::fabs(z[1]) + std::fabs(z[2]))}) {
          std::array<I, 3> X{I::point(0, prec), I::point(0, prec), I::point(0, prec)};
          for (int c = 0; c < 3; ++c) X[c] = I::hull(Rational(z[c] - r), Rational(z[c] + r), prec);
          const std::array<I, 3> U = X;
          if (!S.prove(chart, X, 3)) continue;
          Found f{chart, U, X};
          bool duplicate = false;
          for (const Found& g : found) duplicate = duplicate || same(f, g) || same(g, f);
          if (!duplicate) found.push_back(f);
          add_region(chart, U);
          break;
        }
        if (covered()) continue;
      }
      if (cell.depth >= 75) {
        out.complete = false;
        out.reason = "a box near (u, v, m) = (" + std::to_string(x[0].mid()) + ", " + std::to_string(x[1].mid()) + ", " +
                     std::to_string(x[2].mid()) + ") (chart " + std::to_string(chart) +
                     ") is neither excluded nor isolated (a degenerate rank-1 point or d(phi) = 0)";
        break;
      }
      int s = 0;
      for (int c = 1; c < 3; ++c)
        if (x[c].hi - x[c].lo > x[s].hi - x[s].lo) s = c;
      const double mid = x[s].mid();
      Cell a = cell, b = cell;
      a.x[s] = D{x[s].lo, mid};
      b.x[s] = D{mid, x[s].hi};
      a.depth = b.depth = cell.depth + 1;
      todo.push_back(a);
      todo.push_back(b);
    }
  }
  for (const Found& f : found) {
    // keep points of the box (the proved box may stick out of it: decide by the exact bounds where possible)
    if (f.X[0].upper() < box.u0 || f.X[0].lower() > box.u1 || f.X[1].upper() < box.v0 || f.X[1].lower() > box.v1)
      continue;
    Pinch_point p;
    p.box = {{{f.X[0].lower(), f.X[0].upper()}, {f.X[1].lower(), f.X[1].upper()}}};
    p.chart = f.chart;
    p.m = {f.X[2].lower(), f.X[2].upper()};
    p.u = f.X[0].mid_double();
    p.v = f.X[1].mid_double();
    out.points.push_back(p);
  }
  return out;
}

/// Every pinch point of `phi` in `box`: the subdivision, and where it does not finish, the exact rank-one points
/// (see the header comment). `max_boxes` bounds the subdivision.
inline Pinch_point_search find_pinch_points(const Rational_bezier_patch<Rational>& phi, const Parameter_box& box,
                                            std::size_t max_boxes = 600000) {
  Pinch_point_search out = find_pinch_points_by_subdivision(phi, box, max_boxes);
  if (out.complete) return out;
  const Exact_rank_one_points exact = exact_rank_one_points(phi, box);
  if (!exact.decided) {
    out.reason += "; the exact route: " + exact.reason;
    return out;
  }
  out = Pinch_point_search{};
  out.complete = true;
  for (const Exact_rank_one_point& e : exact.points) {
    Pinch_point p;
    p.box = {{{e.u.lower(), e.u.upper()}, {e.v.lower(), e.v.upper()}}};
    p.chart = e.chart;
    p.m = {e.m_lo, e.m_hi};
    p.u = e.u.to_double();
    p.v = e.v.to_double();
    p.rank_zero = e.rank_zero;
    out.points.push_back(p);
  }
  return out;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_PINCH_POINTS_H

// The partner equations re-expanded about a point, for the proofs next to a point where the two surfaces are
// tangent.
//
// E_c(z) = A_c(P) B_0(Q) - B_c(Q) A_0(P) (double_partner_witness.h) is a difference of two products of size about
// 1. At distance d from a tangential contact the partner system's Jacobian is nearly singular, and the products
// agree to about d^2 over the boxes the proofs need. Evaluated as written, each product carries a rounding error
// of about 2^-53 of its size, so no enclosure of E is narrower than about 1e-16. Krawczyk's test then fails once
// the equations' variation over its box falls to that level (about 1.5e-7 from Viviani's node), and so does the
// exclusion of the other partners.
//
// Expanded about a point z_c,
//   E_c(z_c + delta) = sum_alpha e_{c,alpha} delta^alpha   (alpha in N^4),
// with every coefficient computed exactly in rationals and rounded outward once. The cancellation then happens in
// exact arithmetic, and each term is rounded relative to its own size |e_alpha| |delta|^|alpha|. So the
// enclosure of E over a box at distance d from z_c shrinks with d. The map z -> (P, Q) is affine with 0/1
// coefficients (self-intersection: P = (x1, x2 + k), Q = (x1 + l, x2); two patches: P = (x1, v), Q = (s, x2)),
// so P - P_c and Q - Q_c are sums of the coordinates of delta: no cancellation is left in floating point.
//
// The unknowns are delta itself, not z: boxes relative to the centre keep their full relative precision however
// near the centre they are, where boxes of absolute coordinates near 1/2 could not be narrower than a few ulps of
// 1/2 (1e-16). With z_c at a singular point of D = 0, the same tests then work down to any distance from it.
//
// The class has the interface the span proofs take from Partner_equations (evaluate over real boxes, weights), so parametric_partner_krawczyk, predict_partner_box, prove_zero_curve and widened_unique_box run on
// it unchanged, in the relative coordinates.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_CENTRED_PARTNER_EQUATIONS_H
#define BEZOUTIAN_LIFTING_INTERNAL_CENTRED_PARTNER_EQUATIONS_H

#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/arithmetic/double_interval.h>
#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace bezoutian {
namespace internal {

class Centred_partner_equations {
 public:
  using D = Double_interval;
  /// E of `eq` about the point z_c = (x1, x2, y1, y2) (doubles, taken exactly); the arguments of every
  /// function below are delta = z - z_c.
  Centred_partner_equations(const Partner_equations& eq, const std::array<double, 4>& zc) : eq_(&eq), zc_(zc) {
    std::array<Rational, 4> c;
    for (int i = 0; i < 4; ++i) c[std::size_t(i)] = Rational(zc[std::size_t(i)]);
    std::array<Rational, 2> P0, Q0;
    eq.points(c, P0, Q0);
    // P - P_c and Q - Q_c as linear forms in delta (the rows of dP/dz, dQ/dz)
    std::array<std::array<int, 4>, 2> dP, dQ;
    for (int a = 0; a < 2; ++a)
      for (int i = 0; i < 4; ++i) {
        dP[std::size_t(a)][std::size_t(i)] = eq.dP(a, i);
        dQ[std::size_t(a)][std::size_t(i)] = eq.dQ(a, i);
      }
    std::array<Poly, 4> a, b;
    for (int k = 0; k < 4; ++k) {
      a[std::size_t(k)] = substitute(eq.form(0, k), P0, dP);
      b[std::size_t(k)] = substitute(eq.form(1, k), Q0, dQ);
    }
    for (int c1 = 1; c1 <= 3; ++c1) {
      Poly e = multiply(a[std::size_t(c1)], b[0]);
      for (const auto& t : multiply(b[std::size_t(c1)], a[0])) e[t.first] -= t.second;
      for (const auto& t : e) {
        if (CGAL::is_zero(t.second)) continue;
        const D coef = D::of(t.second);
        value_[std::size_t(c1 - 1)].push_back({t.first, coef});
        for (int i = 0; i < 4; ++i) {
          if (t.first[std::size_t(i)] == 0) continue;
          Exponent d = t.first;
          --d[std::size_t(i)];
          derivative_[std::size_t(c1 - 1)][std::size_t(i)].push_back({d, D::of(t.second * t.first[std::size_t(i)])});
        }
        for (int i = 0; i < 4; ++i) degree_ = std::max(degree_, t.first[std::size_t(i)]);
      }
    }
  }

  bool self_intersection() const { return eq_->self_intersection(); }
  const Partner_equations& equations() const { return *eq_; }
  const std::array<double, 4>& centre() const { return zc_; }
  /// The box z_c + delta in absolute coordinates (outward).
  std::array<D, 4> absolute(const std::array<D, 4>& delta) const {
    std::array<D, 4> z;
    for (int i = 0; i < 4; ++i) z[std::size_t(i)] = delta[std::size_t(i)] + D{zc_[std::size_t(i)], zc_[std::size_t(i)]};
    return z;
  }
  /// The weights A_0(P), B_0(Q) over the box z_c + delta (these do not cancel: evaluated as written).
  std::array<D, 2> weights(const std::array<D, 4>& delta) const { return eq_->weights(absolute(delta)); }

  /// E (and dE/dz if J is given) over the box z_c + delta: outward-rounded enclosures.
  void evaluate(const std::array<D, 4>& delta, std::array<D, 3>& E, std::array<std::array<D, 4>, 3>* J = nullptr) const {
    std::array<std::vector<D>, 4> power;  // powers of delta_i
    for (int i = 0; i < 4; ++i) {
      const D d = delta[std::size_t(i)];
      auto& p = power[std::size_t(i)];
      p.assign(std::size_t(degree_) + 1, D{1, 1});
      for (int k = 1; k <= degree_; ++k) p[std::size_t(k)] = k == 1 ? d : p[std::size_t(k - 1)] * d;
    }
    auto sum = [&](const std::vector<Term>& terms) {
      D s{0, 0};
      for (const Term& t : terms) {
        D m = t.c;
        for (int i = 0; i < 4; ++i)
          if (t.e[std::size_t(i)] > 0) m = m * power[std::size_t(i)][std::size_t(t.e[std::size_t(i)])];
        s = s + m;
      }
      return s;
    };
    for (int c = 0; c < 3; ++c) {
      E[std::size_t(c)] = sum(value_[std::size_t(c)]);
      if (J)
        for (int i = 0; i < 4; ++i) (*J)[std::size_t(c)][std::size_t(i)] = sum(derivative_[std::size_t(c)][std::size_t(i)]);
    }
  }

 private:
  using Exponent = std::array<int, 4>;
  using Poly = std::map<Exponent, Rational>;
  struct Term {
    Exponent e;
    D c;
  };
  static Poly multiply(const Poly& x, const Poly& y) {
    Poly r;
    for (const auto& s : x)
      for (const auto& t : y) {
        Exponent e;
        for (int i = 0; i < 4; ++i) e[std::size_t(i)] = s.first[std::size_t(i)] + t.first[std::size_t(i)];
        r[e] += s.second * t.second;
      }
    return r;
  }
  // f(X_c + L(delta)) for a form f (coefficient [j][i] of u^i v^j) and the linear forms L_a = sum_i rows[a][i] delta_i
  static Poly substitute(const std::vector<std::vector<Rational>>& f, const std::array<Rational, 2>& Xc,
                         const std::array<std::array<int, 4>, 2>& rows) {
    std::array<Poly, 2> shifted;  // X_c,a + L_a
    for (int a = 0; a < 2; ++a) {
      shifted[std::size_t(a)][Exponent{0, 0, 0, 0}] = Xc[std::size_t(a)];
      for (int i = 0; i < 4; ++i)
        if (rows[std::size_t(a)][std::size_t(i)]) {
          Exponent e{0, 0, 0, 0};
          e[std::size_t(i)] = 1;
          shifted[std::size_t(a)][e] += Rational(rows[std::size_t(a)][std::size_t(i)]);
        }
    }
    Poly r;  // Horner in v over rows of Horner in u
    for (std::size_t j = f.size(); j-- > 0;) {
      Poly row;
      for (std::size_t i = f[j].size(); i-- > 0;) {
        row = multiply(row, shifted[0]);
        if (!CGAL::is_zero(f[j][i])) row[Exponent{0, 0, 0, 0}] += f[j][i];
      }
      r = multiply(r, shifted[1]);
      for (const auto& t : row) r[t.first] += t.second;
    }
    return r;
  }

  const Partner_equations* eq_;
  std::array<double, 4> zc_;
  std::array<std::vector<Term>, 3> value_;
  std::array<std::array<std::vector<Term>, 4>, 3> derivative_;
  int degree_ = 0;
};

/// No partner y in any of the `pieces` for any point x of the box X1 x X2 (all relative to the centre, the
/// partner pieces as offsets from the centre's partner): the exclusion of no_genuine_partner
/// (double_partner_witness.h; the mean-value form about each piece's centre, one equation or a combination along
/// the singular directions of the Jacobian, then the rank test beside the trivial partner of a self-intersection),
/// on the centred equations. Used next to a tangential contact, where the other partners come within about d^2 of
/// solving the equations at distance d and the equations as written cannot show them nonzero. At most
/// `max_pieces` pieces are tested.
inline bool no_partner_near_centre(const Centred_partner_equations& eq, const Double_interval& X1,
                                   const Double_interval& X2, std::vector<std::array<Double_interval, 2>> stack,
                                   int max_pieces = 1024) {
  using D = Double_interval;
  int pieces = 0;
  while (!stack.empty()) {
    const std::array<D, 2> y = stack.back();
    stack.pop_back();
    if (++pieces > max_pieces) return false;
    const std::array<D, 4> z{X1, X2, y[0], y[1]};
    std::array<D, 3> E, Ec;
    std::array<std::array<D, 4>, 3> J;
    eq.evaluate(z, E);
    if (!E[0].contains_zero() || !E[1].contains_zero() || !E[2].contains_zero()) continue;
    eq.evaluate(z, E, &J);
    std::array<D, 4> c, dz;
    for (int i = 0; i < 4; ++i) {
      const double m = z[std::size_t(i)].mid();
      c[std::size_t(i)] = D{m, m};
      dz[std::size_t(i)] = z[std::size_t(i)] - c[std::size_t(i)];
    }
    eq.evaluate(c, Ec);
    bool excluded = false;
    for (int r = 0; r < 3 && !excluded; ++r) {
      D v = Ec[std::size_t(r)];
      for (int i = 0; i < 4; ++i) v = v + J[std::size_t(r)][std::size_t(i)] * dz[std::size_t(i)];
      excluded = !v.contains_zero();
    }
    if (excluded || combination_excludes_zero(Ec, J, dz)) continue;
    if (eq.self_intersection()) {  // beside the trivial partner y = 0 (offset -y_c): dE/dy of rank 2 on the hull
      const double o0 = -eq.centre()[2], o1 = -eq.centre()[3];
      const D h0{std::min(y[0].lo, o0), std::max(y[0].hi, o0)}, h1{std::min(y[1].lo, o1), std::max(y[1].hi, o1)};
      if ((h0.hi - h0.lo) + (h1.hi - h1.lo) <= 3 * ((y[0].hi - y[0].lo) + (y[1].hi - y[1].lo))) {
        eq.evaluate({X1, X2, h0, h1}, E, &J);
        bool full_rank = false;
        for (int r = 0; r < 3 && !full_rank; ++r)
          for (int q = r + 1; q < 3 && !full_rank; ++q)
            full_rank = !(J[std::size_t(r)][2] * J[std::size_t(q)][3] - J[std::size_t(r)][3] * J[std::size_t(q)][2]).contains_zero();
        if (full_rank) continue;
      }
    }
    const int i = (y[0].hi - y[0].lo) >= (y[1].hi - y[1].lo) ? 0 : 1;
    const double m = y[std::size_t(i)].mid();
    std::array<D, 2> lo = y, hi = y;
    lo[std::size_t(i)].hi = m;
    hi[std::size_t(i)].lo = m;
    if (!(lo[std::size_t(i)].lo < m && m < hi[std::size_t(i)].hi)) return false;
    stack.push_back(lo);
    stack.push_back(hi);
  }
  return true;
}

}  // namespace internal
}  // namespace bezoutian

#endif  // BEZOUTIAN_LIFTING_INTERNAL_CENTRED_PARTNER_EQUATIONS_H

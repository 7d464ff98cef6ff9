// The partner equations of a self-intersection divided by the trivial partner (a blow-up of y = 0), for the
// certified lifting near pinch points.
//
// For a self-intersection, E(x; y) = A_c(P) A_0(Q) - A_c(Q) A_0(P) (double_partner_witness.h, P = (x1, x2 + k),
// Q = (x1 + l, x2), y = (l, k)) vanishes for y = 0 and every x: the trivial partner. Near a pinch point the
// genuine partner tends to it, so a Krawczyk box around the partner must be smaller than |y| and the tests fail
// there. Write y = r d(m), d = (1, m) (chart 0, |l| >= |k|) or (m, 1) (chart 1). Then E(x; r d) has no term
// free of r (it vanishes at r = 0 for every x, m), and
//   F(x; r, m) = E(x; r d(m)) / r
// is a polynomial. F(x; 0, m) = dE/dy(x; 0) d(m) vanishes only where the Jacobian of the patch (in homogeneous
// form) has rank 1 in the direction d: at pinch points (pinch_points.h). A zero of F with r != 0 is a zero of E
// with the nontrivial partner y = r d(m), so Krawczyk's test on F with a box excluding r = 0 proves a genuine
// partner where the test on E cannot separate it from y = 0.
#ifndef BEZOUTIAN_LIFTING_INTERNAL_BLOWN_UP_PARTNER_EQUATIONS_H
#define BEZOUTIAN_LIFTING_INTERNAL_BLOWN_UP_PARTNER_EQUATIONS_H

#include <bezoutian/geometry/Rational_bezier_patch.h>
#include <bezoutian/lifting/double_partner_witness.h>
#include <bezoutian/arithmetic/number_types.h>

#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace bezoutian {
namespace internal {

class Blown_up_partner_equations {
 public:
  /// The blown-up equations of the self-intersection of `phi` in chart 0 (y = r (1, m)) or 1 (y = r (m, 1)).
  /// Evaluated in factored form, much tighter in interval arithmetic than the expanded polynomial: with
  /// A(P) = A(x) + r DP(A), A(Q) = A(x) + r DQ(A), where DP(A) = (A(P) - A(x)) / r and DQ(A) are polynomials
  /// (divided differences along the shift),
  ///   F_c = A_c (DQ(A_0) - DP(A_0)) + A_0 (DP(A_c) - DQ(A_c)) + r (DP(A_c) DQ(A_0) - DQ(A_c) DP(A_0)).
  Blown_up_partner_equations(const Rational_bezier_patch<Rational>& phi, int chart) : chart_(chart), weight_(phi) {
    const auto pf = phi.power_form();
    for (int c = 0; c < 4; ++c) {
      Sparse at_P = expand(pf[c], true), at_Q = expand(pf[c], false), value, dp, dq;
      for (const auto& t : at_P) (t.first[2] == 0 ? value : dp)[shift_r(t.first)] += t.second;
      for (const auto& t : at_Q)
        if (t.first[2] > 0) dq[shift_r(t.first)] += t.second;
      for (int k = 0; k < 3; ++k) {
        const Sparse& f = k == 0 ? value : (k == 1 ? dp : dq);
        parts_[c][k][0] = compile(f);
        for (int d = 0; d < 4; ++d) parts_[c][k][1 + d] = compile(derivative(f, d));
      }
    }
  }

  int chart() const { return chart_; }
  /// The partner y = r d(m) of z = (x1, x2, r, m).
  std::array<Double_interval, 2> partner(const std::array<Double_interval, 4>& z) const {
    const Double_interval rm = z[2] * z[3];
    return chart_ == 0 ? std::array<Double_interval, 2>{z[2], rm} : std::array<Double_interval, 2>{rm, z[2]};
  }
  /// The parameters P, Q of the two sheets at z = (x1, x2, r, m).
  void points(const std::array<Double_interval, 4>& z, std::array<Double_interval, 2>& P,
              std::array<Double_interval, 2>& Q) const {
    const auto y = partner(z);
    P = {z[0], z[1] + y[1]};
    Q = {z[0] + y[0], z[1]};
  }
  /// The weights A_0(P), A_0(Q) over the box z (E = 0 puts x on D = 0 only where they do not vanish).
  std::array<Double_interval, 2> weights(const std::array<Double_interval, 4>& z) const {
    const auto y = partner(z);
    return weight_.weights(std::array<Double_interval, 4>{z[0], z[1], y[0], y[1]});
  }
  /// F and dF/dz (3 x 4) over the box z = (x1, x2, r, m), outward-rounded enclosures.
  void evaluate(const std::array<Double_interval, 4>& z, std::array<Double_interval, 3>& F,
                std::array<std::array<Double_interval, 4>, 3>* J = nullptr) const {
    using D = Double_interval;
    std::array<std::vector<D>, 4> pw;
    for (int v = 0; v < 4; ++v) {
      pw[v].assign(std::size_t(max_degree_[v]) + 1, D{1, 1});
      for (int e = 1; e <= max_degree_[v]; ++e) pw[v][e] = power(z[v], e, pw[v][e - 1]);
    }
    // a[c][k][0]: value of A_c, DP(A_c), DQ(A_c) (k = 0, 1, 2); a[c][k][1 + d]: its derivative along z_d
    std::array<std::array<std::array<D, 5>, 3>, 4> a;
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < (J ? 5 : 1); ++d) a[c][k][d] = sum(parts_[c][k][d], pw);
    const D& r = z[2];
    for (int c = 1; c <= 3; ++c) {
      auto part = [&](int d) {  // d = 0: F_c; d = 1 + i: the terms of dF_c/dz_i other than d r / dz_i
        const auto &A = a[c], &B = a[0];
        return A[0][d] * (B[2][0] - B[1][0]) + A[0][0] * (B[2][d] - B[1][d]) + B[0][d] * (A[1][0] - A[2][0]) +
               B[0][0] * (A[1][d] - A[2][d]) +
               r * (A[1][d] * B[2][0] + A[1][0] * B[2][d] - A[2][d] * B[1][0] - A[2][0] * B[1][d]);
      };
      const auto& A = a[c];
      const auto& B = a[0];
      F[c - 1] = A[0][0] * (B[2][0] - B[1][0]) + B[0][0] * (A[1][0] - A[2][0]) + r * (A[1][0] * B[2][0] - A[2][0] * B[1][0]);
      if (!J) continue;
      for (int i = 0; i < 4; ++i) {
        D d = part(1 + i);
        if (i == 2) d = d + (A[1][0] * B[2][0] - A[2][0] * B[1][0]);  // d r / d r = 1
        (*J)[c - 1][i] = d;
      }
    }
  }

 private:
  using Exponent = std::array<int, 4>;  // x1, x2, r, m
  using Sparse = std::map<Exponent, Rational>;
  struct Term {
    Exponent e;
    Double_interval c;
  };

  // x^e from x^(e-1): even powers of an interval around 0 are nonnegative (the product would not know it)
  static Double_interval power(const Double_interval& x, int e, const Double_interval& previous) {
    Double_interval p = previous * x;
    if (e % 2 == 0 && p.lo < 0) p.lo = 0;
    return p;
  }
  static Double_interval sum(const std::vector<Term>& f, const std::array<std::vector<Double_interval>, 4>& pw) {
    Double_interval s{0, 0};
    for (const Term& t : f) {
      Double_interval m = t.c;
      for (int v = 0; v < 4; ++v)
        if (t.e[v] > 0) m = m * pw[v][t.e[v]];
      s = s + m;
    }
    return s;
  }
  std::vector<Term> compile(const Sparse& f) {
    std::vector<Term> out;
    for (const auto& t : f) {
      if (CGAL::is_zero(t.second)) continue;
      out.push_back({t.first, Double_interval::of(t.second)});
      for (int v = 0; v < 4; ++v) max_degree_[v] = std::max(max_degree_[v], t.first[v]);
    }
    return out;
  }
  static Sparse derivative(const Sparse& f, int d) {
    Sparse g;
    for (const auto& t : f)
      if (t.first[d] > 0) {
        Exponent k = t.first;
        --k[d];
        g[k] += t.second * t.first[d];
      }
    return g;
  }
  // A form sum a_ji u^i v^j at P = (x1, x2 + k) (at_P) or at Q = (x1 + l, x2), with (l, k) = r d(m), by the
  // binomial theorem: the shifted coordinate (x + r w)^n = sum_s C(n, s) x^(n-s) r^s w^s, w = 1 or m.
  template <class P2>
  Sparse expand(const P2& p, bool at_P) const {
    Sparse out;
    const bool shift_has_m = at_P ? chart_ == 0 : chart_ == 1;  // k = r m in chart 0, l = r m in chart 1
    for (int j = 0; j <= p.degree(); ++j)
      for (int i = 0; i <= p[j].degree(); ++i) {
        const Rational a = p[j][i];
        if (CGAL::is_zero(a)) continue;
        const int n = at_P ? j : i;  // the shifted coordinate's power
        Rational binomial(1);
        for (int s = 0; s <= n; ++s) {
          Exponent k{at_P ? i : i - s, at_P ? j - s : j, s, shift_has_m ? s : 0};
          out[k] += a * binomial;
          binomial = binomial * (n - s) / (s + 1);
        }
      }
    return out;
  }

  static Exponent shift_r(Exponent e) {  // divide a term by r (terms free of r stay: the value A(x))
    if (e[2] > 0) --e[2];
    return e;
  }

  int chart_;
  Partner_equations weight_;  // (for the weights)
  // parts_[c][k][d]: A_c, DP(A_c), DQ(A_c) (k = 0, 1, 2) and their derivatives along z_0..z_3 (d = 1..4)
  std::array<std::array<std::array<std::vector<Term>, 5>, 3>, 4> parts_;
  Exponent max_degree_{0, 0, 0, 0};
};

}  // namespace internal
}  // namespace bezoutian

#endif

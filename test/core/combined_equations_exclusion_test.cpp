// The exclusion by combinations of the partner equations (lifting/internal/combined_equations_exclusion.h) on
// linear systems whose common zeros are known in closed form.
#include <bezoutian/lifting/internal/combined_equations_exclusion.h>

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using bezoutian::internal::combination_excludes_zero;
using bezoutian::internal::symmetric_eigenvectors_3;
using D = bezoutian::internal::Double_interval;

namespace {

// E(z) = A z + b on the box Z: the values at Z's centre c, the (constant) Jacobian, and Z - c.
struct Linear_system {
  std::array<std::array<double, 4>, 3> A;
  std::array<double, 3> b;
  void at(const std::array<D, 4>& Z, std::array<D, 3>& Ec, std::array<std::array<D, 4>, 3>& J,
          std::array<D, 4>& dz) const {
    std::array<double, 4> c;
    for (int i = 0; i < 4; ++i) {
      c[i] = Z[i].mid();
      dz[i] = Z[i] - D{c[i], c[i]};
    }
    for (int r = 0; r < 3; ++r) {
      D e{b[r], b[r]};
      for (int i = 0; i < 4; ++i) {
        e = e + D{A[r][i], A[r][i]} * D{c[i], c[i]};
        J[r][i] = D{A[r][i], A[r][i]};
      }
      Ec[r] = e;
    }
  }
  // whether a single equation's mean value form excludes 0 on Z (the test the combinations add to)
  bool single_excludes(const std::array<D, 4>& Z) const {
    std::array<D, 3> Ec;
    std::array<std::array<D, 4>, 3> J;
    std::array<D, 4> dz;
    at(Z, Ec, J, dz);
    for (int r = 0; r < 3; ++r) {
      D v = Ec[r];
      for (int i = 0; i < 4; ++i) v = v + J[r][i] * dz[i];
      if (!v.contains_zero()) return true;
    }
    return false;
  }
  bool combination_excludes(const std::array<D, 4>& Z) const {
    std::array<D, 3> Ec;
    std::array<std::array<D, 4>, 3> J;
    std::array<D, 4> dz;
    at(Z, Ec, J, dz);
    return combination_excludes_zero(Ec, J, dz);
  }
};

}  // namespace

TEST_CASE("eigenvectors of a symmetric 3 x 3 matrix", "[lifting][exclusion]") {
  // diag(1, 2, 3) rotated by 30 degrees in the (0, 1) plane: eigenvectors (cos, sin, 0), (-sin, cos, 0), (0, 0, 1)
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const std::array<std::array<double, 3>, 3> a{{{c * c + 2 * s * s, c * s - 2 * s * c, 0},
                                                {c * s - 2 * s * c, s * s + 2 * c * c, 0},
                                                {0, 0, 3}}};
  const auto v = symmetric_eigenvectors_3(a);
  for (const auto& x : v) {
    // A x = lambda x for lambda in {1, 2, 3}
    std::array<double, 3> y{};
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) y[r] += a[r][k] * x[k];
    const double lambda = y[0] * x[0] + y[1] * x[1] + y[2] * x[2];
    CHECK(std::fabs(lambda - std::round(lambda)) < 1e-12);
    for (int r = 0; r < 3; ++r) CHECK(std::fabs(y[r] - lambda * x[r]) < 1e-12);
  }
}

TEST_CASE("combinations exclude where the equations are nearly dependent", "[lifting][exclusion]") {
  // E1 = y1 - x1, E2 = y2 - x2, E3 = y1 - x1 + eps (y2 - 1): the common zeros are y = x with x2 = 1 (E3 - E1 =
  // eps (y2 - 1) and E2). On Z = [0, 1] x [0, 1/2] x [0, 1] x [0, 1/2] there is none, but each E_c takes the value
  // 0 there; the combination E3 - E1 is eps (y2 - 1) <= -eps/2. Its gradient is eps: the direction of the
  // Jacobian's smallest singular value.
  for (const double eps : {1e-2, 1e-4, 1e-8}) {
    const Linear_system L{{{{-1, 0, 1, 0}, {0, -1, 0, 1}, {-1, 0, 1, eps}}}, {0, 0, -eps}};
    const std::array<D, 4> Z{D{0, 1}, D{0, 0.5}, D{0, 1}, D{0, 0.5}};
    CHECK_FALSE(L.single_excludes(Z));
    CHECK(L.combination_excludes(Z));
    // a box holding the common zero (1/2, 1, 1/2, 1) is never excluded
    const std::array<D, 4> W{D{0, 1}, D{0.5, 1.5}, D{0, 1}, D{0.5, 1.5}};
    CHECK_FALSE(L.combination_excludes(W));
    CHECK_FALSE(L.single_excludes(W));
  }
}

TEST_CASE("combinations: a box holding zeros is not excluded", "[lifting][exclusion]") {
  // a well-conditioned system with the zero z = (1, 2, 3, 4) + t (1, 1, 1, 1) (A (1, 1, 1, 1) = 0): the box
  // [0, 1] x [1, 2] x [2, 3] x [3, 4] holds the zeros with x1 in [0, 1]
  const Linear_system L{{{{1, -1, 0, 0}, {0, 1, -1, 0}, {0, 0, 1, -1}}}, {1, 1, 1}};
  const std::array<D, 4> Z{D{0, 1}, D{1, 2}, D{2, 3}, D{3, 4}};
  CHECK_FALSE(L.combination_excludes(Z));
  // a box whose part x1 <= 1/2 still holds zeros (x = (x1, x1 + 1, x1 + 2, x1 + 3), x1 in [0, 1/2])
  const std::array<D, 4> half{D{0, 0.5}, D{1, 2}, D{2, 3}, D{3, 4}};
  CHECK_FALSE(L.combination_excludes(half));
}

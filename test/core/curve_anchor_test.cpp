// The exact test of lifting/internal/curve_anchor.h: no zero of D on a line segment beyond a value c, on curves whose
// zeros on each line are known in closed form (a parabola tangent to the line v = 1, the two branches v = +-sqrt(u)).
#include <catch2/catch.hpp>

#include <bezoutian/lifting/internal/curve_anchor.h>

using bezoutian::Integer;
using bezoutian::Polynomial_1;
using bezoutian::Polynomial_2;
using bezoutian::Rational;
using bezoutian::internal::curve_has_no_zero_beyond;

namespace {
Rational power_of_two(int e) {  // 2^e, e < 0
  Rational r(1);
  for (int i = 0; i < -e; ++i) r = r / Rational(2);
  return r;
}
}  // namespace

TEST_CASE("curve anchor: a zero within 1e-18 of the side is told from none beyond it", "[lifting][anchor]") {
  // D = 4 x2 - 3 - 4 x1 + 4 x1^2: on the line x1 = t its zero is v = 1 - (t - 1/2)^2, tangent to v = 1 at t = 1/2
  const Polynomial_2<Integer> D(Polynomial_1<Integer>(Integer(-3), Integer(-4), Integer(4)), Polynomial_1<Integer>(Integer(4)));
  // the same curve with the roles of x1 and x2 exchanged: the graph coordinate is x2 (axis 1)
  const Polynomial_2<Integer> S(Polynomial_1<Integer>(Integer(-3), Integer(4)), Polynomial_1<Integer>(Integer(-4)),
                                Polynomial_1<Integer>(Integer(4)));
  const Rational t = Rational(1, 2) - power_of_two(-30);  // zero at v = 1 - 2^-60
  for (int axis : {0, 1}) {
    const Polynomial_2<Integer>& P = axis == 0 ? D : S;
    CHECK(curve_has_no_zero_beyond(P, axis, t, Rational(1), Rational(1) + power_of_two(-40)));
    CHECK_FALSE(curve_has_no_zero_beyond(P, axis, t, Rational(1), Rational(1) - power_of_two(-40)));
    CHECK_FALSE(curve_has_no_zero_beyond(P, axis, Rational(1, 2), Rational(1), Rational(2)));  // the zero is at c
    // the zero 1 - 2^-60 lies beyond c = 1 - 2^-50, towards 1
    CHECK_FALSE(curve_has_no_zero_beyond(P, axis, t, Rational(1) - power_of_two(-50), Rational(1)));
    CHECK(curve_has_no_zero_beyond(P, axis, t, Rational(1) - power_of_two(-70), Rational(1) - power_of_two(-62)));
  }
}

TEST_CASE("curve anchor: two branches v = +-1/2 on the line u = 1/4", "[lifting][anchor]") {
  const Polynomial_2<Integer> D(Polynomial_1<Integer>(Integer(0), Integer(-1)), Polynomial_1<Integer>(Integer(0)),
                                Polynomial_1<Integer>(Integer(1)));  // x2^2 - x1
  const Rational t(1, 4);
  CHECK(curve_has_no_zero_beyond(D, 0, t, Rational(1), Rational(11, 10)));
  CHECK(curve_has_no_zero_beyond(D, 0, t, Rational(-1), Rational(-3, 2)));
  CHECK(curve_has_no_zero_beyond(D, 0, t, Rational(3, 5), Rational(9, 10)));
  CHECK_FALSE(curve_has_no_zero_beyond(D, 0, t, Rational(1), Rational(0)));  // +1/2 between
  CHECK_FALSE(curve_has_no_zero_beyond(D, 0, t, Rational(0), Rational(-1)));  // -1/2 between
}

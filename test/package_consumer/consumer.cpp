// Uses the installed headers: the unit circle quarter as a rational quadratic.
#include <bezoutian/geometry/Rational_bezier_curve.h>
#include <iostream>
int main() {
  using Q = bezoutian::Rational;
  bezoutian::Rational_bezier_curve_2<> arc({{Q(1), Q(0)}, {Q(1), Q(1)}, {Q(0), Q(1)}}, {Q(1), Q(1), Q(2)});
  auto p = arc(Q(1, 3));
  const bool on_circle = p[0] * p[0] + p[1] * p[1] == Q(1);
  std::cout << "point " << p[0] << ", " << p[1] << (on_circle ? " on" : " NOT on") << " the unit circle\n";
  return on_circle ? 0 : 1;
}

// Catch2 checks shared by the curve intersection tests: two results are the same exact answer.
#ifndef BEZOUTIAN_TEST_INTERSECTION_CHECKS_H
#define BEZOUTIAN_TEST_INTERSECTION_CHECKS_H
#include <catch2/catch.hpp>

#include <bezoutian/intersection/Curve_intersection.h>

namespace bezoutian_test {

/// The same points (exact comparison of the algebraic parameters), kinds, multiplicities and tangency flags, and
/// the same number of overlaps. (D, the dimension, is only documentation at the call sites.)
template <int D = 0>
void require_same(const bezoutian::Curve_intersection_result& a, const bezoutian::Curve_intersection_result& b) {
  REQUIRE(a.points.size() == b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    CHECK(a.points[i].s == b.points[i].s);
    CHECK(a.points[i].t == b.points[i].t);
    CHECK(a.points[i].kind == b.points[i].kind);
    CHECK(a.points[i].tangent == b.points[i].tangent);
    CHECK(a.points[i].multiplicity == b.points[i].multiplicity);
  }
  REQUIRE(a.overlaps.size() == b.overlaps.size());
}

}  // namespace bezoutian_test

#endif  // BEZOUTIAN_TEST_INTERSECTION_CHECKS_H

// Known-answer problems of the du-1989 §4.2 generator and constructed tangencies, the default-run share of
// benchmark/generated_problems.cpp (10,000 problems there; the same problems, checks and counts here, 410 of them:
// every one of the 820 classes of plane and space, rational and polynomial curves of degrees 2-6 with 0-4
// constructed intersections or a tangency, every other class).
#include <catch2/catch.hpp>

#define BEZOUTIAN_GENERATED_PROBLEMS_NO_MAIN
#include "../../benchmark/generated_problems.cpp"

#include <cstdio>

TEST_CASE("generated problems: 0 missed and 0 spurious intersections, constructed tangencies found tangent",
          "[curve_intersection][generated_problems]") {
  // seeds 200001.. (the benchmark's default run starts at 1); every 4th problem also against the subresultant strategy
  std::vector<generated_problems::Counts> per_class;
  const generated_problems::Counts n = generated_problems::run(410, 200001, 4, stderr, &per_class);
  INFO("missed " << n.missed << ", spurious " << n.spurious << ", wrong kind " << n.wrong_kind << ", overlaps "
                 << n.overlaps << ", disagreements " << n.disagreements << ", errors " << n.errors);
  CHECK(n.problems == 410);
  CHECK(n.missed == 0);
  CHECK(n.spurious == 0);
  CHECK(n.wrong_kind == 0);
  CHECK(n.overlaps == 0);
  CHECK(n.disagreements == 0);
  CHECK(n.errors == 0);
  CHECK(n.compared == 103);
  // the mix: tangencies in plane and space, every dimension and weight kind present
  long tangencies = 0, space = 0, rational = 0;
  const auto classes = generated_problems::problem_classes();
  for (std::size_t c = 0; c < classes.size(); ++c) {
    tangencies += per_class[c].tangencies;
    if (classes[c].dimension == 3) space += per_class[c].problems;
    if (classes[c].rational) rational += per_class[c].problems;
  }
  CHECK(tangencies >= 80);
  CHECK(space >= 150);
  CHECK(rational >= 150);
  CHECK(n.constructed >= 700);
}

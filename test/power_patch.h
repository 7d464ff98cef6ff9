// Test helper: an exact patch from power-basis coordinate polynomials in u, v, through the JSON reader.
#ifndef BEZOUTIAN_TEST_POWER_PATCH_H
#define BEZOUTIAN_TEST_POWER_PATCH_H
#include <bezoutian/io/Geometry_document.h>

#include <array>
#include <string>

namespace bezoutian_test {
inline bezoutian::Rational_bezier_patch<> patch_from_power(const std::array<std::string, 3>& xyz, int m, int n) {
  const std::string json = "{\"patch\": {\"basis\": \"power\", \"parameters\": [\"u\", \"v\"], \"x\": \"" + xyz[0] +
                           "\", \"y\": \"" + xyz[1] + "\", \"z\": \"" + xyz[2] + "\", \"degree\": [" +
                           std::to_string(m) + ", " + std::to_string(n) + "]}}";
  return bezoutian::io::read_json(json, "test").patches.at(0);
}
/// The same with a weight polynomial w: the rational patch (x, y, z) / w.
inline bezoutian::Rational_bezier_patch<> rational_patch_from_power(const std::array<std::string, 4>& xyzw, int m,
                                                                 int n) {
  const std::string json = "{\"patch\": {\"basis\": \"power\", \"parameters\": [\"u\", \"v\"], \"x\": \"" + xyzw[0] +
                           "\", \"y\": \"" + xyzw[1] + "\", \"z\": \"" + xyzw[2] + "\", \"w\": \"" + xyzw[3] +
                           "\", \"degree\": [" + std::to_string(m) + ", " + std::to_string(n) + "]}}";
  return bezoutian::io::read_json(json, "test").patches.at(0);
}
}  // namespace bezoutian_test
#endif

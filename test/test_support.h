// Helpers shared by the tests: where the shipped samples and the external data live.
#ifndef BEZOUTIAN_TEST_SUPPORT_H
#define BEZOUTIAN_TEST_SUPPORT_H
#include <string>
namespace bezoutian_test {
inline std::string shared_data(const std::string& relative) {
  return std::string(BEZOUTIAN_SHARED_DATA) + "/" + relative;
}
inline std::string source_file(const std::string& relative) {
  return std::string(BEZOUTIAN_SOURCE_DIR) + "/" + relative;
}
} // namespace bezoutian_test
#endif

// Replays the stored inputs of every fuzz target through its entry function (targets.h), without libFuzzer:
//   bezoutian_fuzz_replay <fuzz folder>
// reads <fuzz folder>/corpus/<target>/* and <fuzz folder>/regressions/<target>/*. A failing input aborts the
// program with its name (fuzz_failure()); a target without a corpus is an error, so that a wrong path cannot pass.
#include "targets.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

struct Target {
  const char* name;
  void (*entry)(const std::uint8_t*, std::size_t);
};

std::size_t replay_folder(const std::filesystem::path& folder, const Target& t) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return 0;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(entry.path());
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bezoutian::fuzz::current_input_name() = file.string();
    t.entry(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  return files.size();
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <fuzz folder holding corpus/ and regressions/>\n", argv[0]);
    return 2;
  }
  const std::filesystem::path root(argv[1]);
  const Target targets[] = {{"json", bezoutian::fuzz::json_document},
                            {"expression", bezoutian::fuzz::polynomial_expression},
                            {"dat", bezoutian::fuzz::cgal_dat},
                            {"bpt", bezoutian::fuzz::bpt},
                            {"curves", bezoutian::fuzz::planar_curves},
                            {"patches", bezoutian::fuzz::small_patches}};
  int status = 0;
  for (const Target& t : targets) {
    const std::size_t corpus = replay_folder(root / "corpus" / t.name, t);
    const std::size_t regressions = replay_folder(root / "regressions" / t.name, t);
    std::printf("%-10s %6zu corpus inputs, %4zu regression inputs: passed\n", t.name, corpus, regressions);
    if (corpus == 0) {
      std::fprintf(stderr, "no corpus for the target %s in %s\n", t.name, (root / "corpus").string().c_str());
      status = 1;
    }
  }
  return status;
}

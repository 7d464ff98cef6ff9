// The include rule of the library's layout (doc/design.md, "Layout and the include rule"), read from the
// `#include` lines of the headers under include/bezoutian:
//  1. the stages are ordered arithmetic < algebraic < geometry < elimination < topology < lifting < intersection
//     < arrangement < io; a header includes headers of its own stage and of lower stages only;
//  2. a stage's internal/ folder is included only from that stage (tests and benchmarks may include it);
//  3. CGAL's algebraic kernels and Arrangement_2 are reached, directly or through other headers of the library,
//     only from the arrangement stage and from the CGAL fallback topology/Cgal_curve_analysis.h;
//  4. a header directly in include/bezoutian is a compatibility path: one include of a staged header, nothing else;
//  5. examples/ (the command-line tool) includes no internal/ folder.
#ifndef BEZOUTIAN_TEST_INCLUDE_RULE_H
#define BEZOUTIAN_TEST_INCLUDE_RULE_H

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace include_rule {

inline const std::vector<std::string>& stages() {
  static const std::vector<std::string> s = {"arithmetic", "algebraic",    "geometry",    "elimination", "topology",
                                             "lifting",    "intersection", "arrangement", "io"};
  return s;
}

inline int stage_index(const std::string& stage) {
  const auto& s = stages();
  const auto it = std::find(s.begin(), s.end(), stage);
  return it == s.end() ? -1 : int(it - s.begin());
}

// The headers allowed to reach CGAL's algebraic kernels and Arrangement_2 (paths relative to include/bezoutian).
inline bool may_reach_cgal_arrangement(const std::string& rel) {
  return rel.rfind("arrangement/", 0) == 0 || rel == "topology/Cgal_curve_analysis.h" ||
         rel == "Curve_topology_in_box.h" || rel == "Arr_rational_bezier_traits_2.h" ||
         rel == "Algebraic_kernel_interop.h";
}

inline bool is_cgal_arrangement_header(const std::string& inc) {
  static const std::regex r(R"(CGAL/(Arrangement_2|Arr_|Algebraic_kernel_d|Algebraic_curve_kernel|Algebraic_kernel_for)[^>]*)");
  return std::regex_search(inc, r);
}

struct Header {
  std::vector<std::string> bezoutian_includes;  // paths relative to include/bezoutian
  std::vector<std::string> other_includes;
  std::size_t code_lines = 0;                   // non-blank lines that are not comments or preprocessor lines
};

inline Header read_header(const std::filesystem::path& file) {
  static const std::regex inc(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  Header h;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, inc)) {
      const std::string path = m[1];
      if (path.rfind("bezoutian/", 0) == 0)
        h.bezoutian_includes.push_back(path.substr(10));
      else
        h.other_includes.push_back(path);
      continue;
    }
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line.compare(first, 2, "//") == 0 || line[first] == '#') continue;
    ++h.code_lines;
  }
  return h;
}

// Every violation of the rule in the tree rooted at `source_dir`, one line each.
inline std::vector<std::string> violations(const std::filesystem::path& source_dir) {
  namespace fs = std::filesystem;
  std::vector<std::string> out;
  const fs::path root = source_dir / "include" / "bezoutian";
  std::map<std::string, Header> headers;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file() && e.path().extension() == ".h")
      headers[fs::relative(e.path(), root).generic_string()] = read_header(e.path());

  auto stage_of = [](const std::string& rel) { return rel.substr(0, rel.find('/')); };
  auto is_internal = [](const std::string& rel) { return rel.find("/internal/") != std::string::npos; };

  for (const auto& [rel, h] : headers) {
    const bool top_level = rel.find('/') == std::string::npos;
    if (top_level) {
      if (h.bezoutian_includes.size() != 1 || !h.other_includes.empty() || h.code_lines != 0 ||
          h.bezoutian_includes[0].find('/') == std::string::npos)
        out.push_back(rel + ": a header directly in include/bezoutian must only forward to one staged header");
      continue;
    }
    const int mine = stage_index(stage_of(rel));
    if (mine < 0) {
      out.push_back(rel + ": folder '" + stage_of(rel) + "' is not a stage");
      continue;
    }
    for (const auto& inc : h.bezoutian_includes) {
      if (!headers.count(inc)) {
        out.push_back(rel + ": includes bezoutian/" + inc + ", which does not exist");
        continue;
      }
      if (inc.find('/') == std::string::npos) {
        out.push_back(rel + ": includes the compatibility path bezoutian/" + inc + "; include the staged header");
        continue;
      }
      const int theirs = stage_index(stage_of(inc));
      if (theirs > mine)
        out.push_back(rel + ": includes bezoutian/" + inc + " of the later stage " + stage_of(inc));
      if (is_internal(inc) && stage_of(inc) != stage_of(rel))
        out.push_back(rel + ": includes bezoutian/" + inc + ", internal to the stage " + stage_of(inc));
    }
  }

  // rule 3: reachability of CGAL's arrangement / algebraic kernel headers through the library's includes
  std::map<std::string, bool> reaches;
  std::set<std::string> visiting;
  std::function<bool(const std::string&)> reach = [&](const std::string& rel) -> bool {
    if (reaches.count(rel)) return reaches[rel];
    if (!visiting.insert(rel).second) return false;  // an include cycle is cut here; the guards make it harmless
    bool r = false;
    const auto it = headers.find(rel);
    if (it != headers.end()) {
      for (const auto& o : it->second.other_includes) r = r || is_cgal_arrangement_header(o);
      for (const auto& b : it->second.bezoutian_includes) r = r || reach(b);
    }
    visiting.erase(rel);
    return reaches[rel] = r;
  };
  for (const auto& entry : headers)
    if (!may_reach_cgal_arrangement(entry.first) && reach(entry.first))
      out.push_back(entry.first + ": reaches CGAL's algebraic kernel or Arrangement_2 (only the arrangement stage and "
                                  "topology/Cgal_curve_analysis.h may)");

  // rule 5: the command-line tool uses the stages' interfaces only
  const fs::path examples = source_dir / "examples";
  if (fs::exists(examples))
    for (const auto& e : fs::recursive_directory_iterator(examples))
      if (e.is_regular_file() && (e.path().extension() == ".h" || e.path().extension() == ".cpp"))
        for (const auto& inc : read_header(e.path()).bezoutian_includes)
          if (is_internal(inc))
            out.push_back(fs::relative(e.path(), source_dir).generic_string() + ": includes bezoutian/" + inc +
                          ", internal to the stage " + stage_of(inc));
  return out;
}

}  // namespace include_rule

#endif  // BEZOUTIAN_TEST_INCLUDE_RULE_H

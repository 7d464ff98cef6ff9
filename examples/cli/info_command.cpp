// bezoutian info FILE: what a file holds.
#include "commands.h"
#include "exact_json.h"
#include "load.h"

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace {

void run_info(const std::string& path, bool json) {
  bezoutian_cli::Loaded_file f = bezoutian_cli::load_and_validate(path);
  const auto& d = f.doc;
  nlohmann::json degrees = nlohmann::json::array();
  bool rational = false;
  std::string kind;
  std::size_t dims = 0;
  if (!d.patches.empty()) {
    kind = "patches";
    for (const auto& p : d.patches) {
      degrees.push_back({p.degree_u(), p.degree_v()});
      rational = rational || p.is_rational();
    }
  } else {
    kind = "curves";
    for (const auto& c : d.curves_2) {
      degrees.push_back(c.degree());
      rational = rational || c.is_rational();
    }
    for (const auto& c : d.curves_3) {
      degrees.push_back(c.degree());
      rational = rational || c.is_rational();
    }
    dims = d.curves_3.empty() ? 2 : (d.curves_2.empty() ? 3 : 0);
  }
  const std::size_t count = d.patches.empty() ? d.curves_2.size() + d.curves_3.size() : d.patches.size();
  if (!d.patches.empty() && (d.curves_2.size() + d.curves_3.size()) > 0)
    f.warnings.push_back("the file also holds " + std::to_string(d.curves_2.size() + d.curves_3.size()) +
                         " curves, not counted here");
  if (json) {
    nlohmann::json j = bezoutian_cli::envelope("info");
    j["kind"] = kind;
    j["count"] = count;
    j["degrees"] = degrees;
    j["rational"] = rational;
    j["warnings"] = f.warnings;
    if (kind == "curves") j["dimension"] = dims == 0 ? nlohmann::json("mixed") : nlohmann::json(dims);
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << path << ": " << count << " " << (count == 1 ? (kind == "patches" ? std::string("patch") : std::string("curve")) : kind);
  if (kind == "curves") std::cout << (dims == 2 ? " in the plane" : dims == 3 ? " in space" : " (planar and spatial)");
  std::cout << ", " << (rational ? "rational" : "polynomial") << "\n";
  std::cout << "degrees:";
  for (const auto& g : degrees) std::cout << " " << (g.is_array() ? "(" + g[0].dump() + "," + g[1].dump() + ")" : g.dump());
  std::cout << "\n";
  if (f.warnings.empty()) std::cout << "no warnings; every weight polynomial is proved free of poles in the domain\n";
  for (const auto& w : f.warnings) std::cout << "warning: " << w << "\n";
}

bezoutian_cli::Register info_registration([](CLI::App& app) {
  auto* sub = app.add_subcommand("info", "What a file holds: curves or patches, degrees, rational, warnings");
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  sub->add_option("FILE", *path, "input file (.json, .dat or .bpt)")->required();
  sub->add_flag("--json", *json, "machine-readable output");
  sub->callback([path, json] { run_info(*path, *json); });
});

} // namespace

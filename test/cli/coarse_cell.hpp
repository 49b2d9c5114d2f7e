#pragma once
// The default cell on a coarse grid (m_max 0.4 m, joint 4 swept, whole cells) as a cell file, so
// that the command tests that build look-up tables take a moment, not seconds.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "safecell/cell/default_cell.hpp"
#include "safecell/test/scratch_folder.hpp"

namespace safecell::test {

inline std::filesystem::path write_coarse_cell(const std::filesystem::path& folder) {
  std::string yaml(default_cell_yaml());
  const auto replace = [&yaml](const std::string& from, const std::string& to) {
    const auto at = yaml.find(from);
    if (at == std::string::npos) throw std::logic_error("default cell without '" + from + "'");
    yaml.replace(at, from.size(), to);
  };
  replace("m_max_m: 0.18", "m_max_m: 0.4");
  replace("range_deg: [-240, 240]\n    discretised: true",
          "range_deg: [-240, 240]\n    discretised: false");
  replace("envelope_max_move_m: 0.06", "envelope_max_move_m: 0.4");  // whole cells: fast tables
  const std::filesystem::path path = folder / "coarse.yaml";
  std::ofstream(path) << yaml;
  return path;
}

}  // namespace safecell::test

#pragma once
// The default cell on a coarse grid (m_max 0.4 m, joint 4 swept) as a cell file, so that the
// command tests that build look-up tables take a moment, not seconds.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "safecell/cell/default_cell.hpp"

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
  const std::filesystem::path path = folder / "coarse.yaml";
  std::ofstream(path) << yaml;
  return path;
}

// A fresh folder under the temporary directory, removed when the object goes.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              (name + "-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
               "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() { std::filesystem::remove_all(path_); }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace safecell::test

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "coarse_cell.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

TEST(DemoCommand, RunsThePipelineAndWritesTheReport) {
  const test::ScratchFolder scratch("safecell-demo");
  const fs::path cell = test::write_coarse_cell(scratch.path());
  const fs::path out = scratch.path() / "report";
  const auto run = test::safecell_cli({"demo", "--cell", cell.string(), "--seconds", "3", "--fps",
                                       "4", "--out", out.string(), "--lut-cache",
                                       (scratch.path() / "cache").string(), "--views-every", "4"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary["cycles"].get<int>(), 12);
  EXPECT_EQ(summary["missed"].get<int>(), 0);
  EXPECT_GT(summary["fusion_ms_p99"].get<double>(), 0.0);
  EXPECT_GT(summary["forbidden_cells_max"].get<double>(), 0.0);
  EXPECT_EQ(summary["timeline"].size(), 12U);
  // The person is in the cell for part of the run and is seen then.
  bool seen = false;
  for (const auto& cycle : summary["timeline"]) {
    for (const auto& pixels : cycle["obstacle_cells"]) seen = seen || pixels.get<int>() > 0;
  }
  EXPECT_TRUE(seen);
  for (const char* picture : {"views/cycle_0000.png", "views/cycle_0008.png",
                              "slices/cycle_0004_joints_1_2.png", "floor_coverage.png"}) {
    EXPECT_TRUE(fs::exists(out / picture)) << picture;
  }
  EXPECT_NE(run.out.find("missed 0"), std::string::npos) << run.out;
}

TEST(DemoCommand, AbsurdDurationsAreRefused) {
  EXPECT_EQ(test::safecell_cli({"demo", "--seconds", "-1"}).exit_code, 2);
  EXPECT_EQ(test::safecell_cli({"demo", "--fps", "0"}).exit_code, 2);
}

}  // namespace
}  // namespace safecell

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_run.hpp"
#include "coarse_cell.hpp"

namespace safecell {
namespace {

TEST(CellCoverageCommand, WritesTheFloorPlanAndTheBlindShare) {
  const test::ScratchFolder scratch("safecell-coverage");
  const auto cell = test::write_coarse_cell(scratch.path());
  const auto out = scratch.path() / "coverage";
  const auto run = test::safecell_cli({"cell", "coverage", "--cell", cell.string(), "--out",
                                       out.string(), "--step", "0.4", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_GT(report["reach_positions"].get<int>(), 10);
  EXPECT_EQ(report["reach_blind_positions"].get<int>(), 0) << "the default cell has none";
  EXPECT_EQ(report["reach_blind_share"].get<double>(), 0.0);
  const cv::Mat picture = cv::imread((out / "floor_coverage.png").string());
  EXPECT_GT(picture.cols, 500);
  EXPECT_TRUE(std::filesystem::exists(out / "coverage.json"));
}

TEST(CellCoverageCommand, RefusesAnAbsurdStep) {
  const auto run = test::safecell_cli({"cell", "coverage", "--step", "0"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--step"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace safecell

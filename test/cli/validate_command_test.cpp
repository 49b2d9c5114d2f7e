#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "cli_run.hpp"
#include "coarse_cell.hpp"

namespace safecell {
namespace {

std::vector<std::string> validate_args(const test::ScratchFolder& scratch,
                                       const std::filesystem::path& cell, const char* scenes,
                                       std::vector<std::string> more = {}) {
  std::vector<std::string> args{"validate", "--cell",      cell.string(),
                                "--scenes", scenes,        "--seed",
                                "5",        "--configs",   "60",
                                "--json",   "--lut-cache", (scratch.path() / "cache").string()};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(ValidateCommand, ReportsTheIssuesKeysAndMissesNothing) {
  const test::ScratchFolder scratch("safecell-validate");
  const auto cell = test::write_coarse_cell(scratch.path());
  const auto run = test::safecell_cli(validate_args(scratch, cell, "6"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const auto report = nlohmann::json::parse(run.out);
  for (const char* key : {"scenes", "configs_checked", "colliding", "missed", "unseen",
                          "unseen_reasons", "needless_stop_share", "strata", "fusion_ms_p99"}) {
    EXPECT_TRUE(report.contains(key)) << key;
  }
  EXPECT_EQ(report["scenes"].get<int>(), 6);
  EXPECT_EQ(report["configs_checked"].get<int>(), 360);
  EXPECT_EQ(report["missed"].get<int>(), 0);
  EXPECT_TRUE(report["strata"].contains("scene/against_arm"));
  EXPECT_TRUE(report["strata"].contains("configs/near_robot"));
  EXPECT_TRUE(report["unseen_reasons"].contains("hidden_by_robot"));
  EXPECT_FALSE(report["hidden_votes"].get<bool>()) << "the paper's vote is the default";
  // The default cell's vote, which the coarse cell keeps: 3 of 4 cameras, blobs grown 4 cells.
  EXPECT_EQ(report["camera_threshold"].get<int>(), 3);
  EXPECT_EQ(report["occlusion_reach"].get<int>(), 4);
  EXPECT_EQ(report["envelope_subdivision"].get<int>(), 1) << "the coarse cell draws whole cells";
  EXPECT_EQ(report["robot_parts"].get<std::string>(), "links-and-wrist");
  EXPECT_EQ(report["ball_radius_m"].get<double>(), 0.04);
}

// The cell file's robot parts and balls are the tables' and the report's; the options override.
TEST(ValidateCommand, TheCellsRobotPartsAndBallsAreTheRunsUnlessTheOptionsSay) {
  const test::ScratchFolder scratch("safecell-validate");
  const auto cell = test::write_coarse_cell(scratch.path());
  std::string yaml;
  {
    std::ifstream in(cell);
    yaml.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"robot_parts: links-and-wrist",
                                                                     "robot_parts: per-link"},
                                 {"ball_radius_m: 0.04", "ball_radius_m: 0.05"}}) {
    const auto at = yaml.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    yaml.replace(at, from.size(), to);
  }
  std::ofstream(cell) << yaml;
  const auto run = test::safecell_cli(validate_args(scratch, cell, "2"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_EQ(report["robot_parts"].get<std::string>(), "per-link");
  EXPECT_EQ(report["ball_radius_m"].get<double>(), 0.05);
  EXPECT_EQ(report["missed"].get<int>(), 0);
  const auto overridden = test::safecell_cli(
      validate_args(scratch, cell, "2", {"--robot-parts", "whole-robot", "--ball-radius", "0.07"}));
  ASSERT_EQ(overridden.exit_code, 0) << overridden.err << overridden.out;
  const auto other = nlohmann::json::parse(overridden.out);
  EXPECT_EQ(other["robot_parts"].get<std::string>(), "whole-robot");
  EXPECT_EQ(other["ball_radius_m"].get<double>(), 0.07);
}

TEST(ValidateCommand, SubCellsAreAnOptionAndInTheReport) {
  const test::ScratchFolder scratch("safecell-validate");
  const auto cell = test::write_coarse_cell(scratch.path());
  const auto run =
      test::safecell_cli(validate_args(scratch, cell, "6", {"--envelope-max-move", "0.2"}));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_EQ(report["envelope_subdivision"].get<int>(), 2);  // m_max 0.4 m cut in 2
  EXPECT_EQ(report["missed"].get<int>(), 0);
  const auto refused =
      test::safecell_cli(validate_args(scratch, cell, "6", {"--envelope-max-move", "0"}));
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
}

TEST(ValidateCommand, ANegativeControlFailsTheRun) {
  const test::ScratchFolder scratch("safecell-validate");
  const auto cell = test::write_coarse_cell(scratch.path());
  const auto run =
      test::safecell_cli(validate_args(scratch, cell, "6", {"--negative-control", "empty-masks"}));
  EXPECT_EQ(run.exit_code, 1) << run.err << run.out;
  EXPECT_GT(nlohmann::json::parse(run.out)["missed"].get<int>(), 0);
}

TEST(ValidateCommand, FourShardsMergedAreTheWholeRun) {
  const test::ScratchFolder scratch("safecell-validate");
  const auto cell = test::write_coarse_cell(scratch.path());
  const auto whole = test::safecell_cli(validate_args(scratch, cell, "8"));
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  std::vector<std::string> merge{"validate", "merge", "--json"};
  for (int k = 1; k <= 4; ++k) {
    const auto shard = test::safecell_cli(
        validate_args(scratch, cell, "8", {"--shard", std::to_string(k) + "/4"}));
    ASSERT_EQ(shard.exit_code, 0) << shard.err;
    const auto file = scratch.path() / ("shard" + std::to_string(k) + ".json");
    std::ofstream(file) << shard.out;
    merge.push_back(file.string());
  }
  const auto merged = test::safecell_cli(merge);
  ASSERT_EQ(merged.exit_code, 0) << merged.err << merged.out;
  auto a = nlohmann::json::parse(whole.out);
  auto b = nlohmann::json::parse(merged.out);
  EXPECT_EQ(b["shards"], nlohmann::json::array({1, 2, 3, 4}));
  for (auto* report : {&a, &b}) {  // timings and the shard list differ by nature
    for (const char* key : {"fusion_ms_p99", "features_ms_p99", "shards", "shard_count",
                            "forbidden_share", "forbidden_share_sum"}) {
      report->erase(key);
    }
  }
  EXPECT_EQ(a, b) << a.dump(1) << "\n" << b.dump(1);
  // The same shard twice, or a file that is no report, is refused by name.
  const auto twice = test::safecell_cli({"validate", "merge", merge[3], merge[3]});
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("shard 1 is in an earlier file"), std::string::npos) << twice.err;
  const auto not_json = scratch.path() / "bad.json";
  std::ofstream(not_json) << "{\"scenes\": 3}";
  const auto bad = test::safecell_cli({"validate", "merge", not_json.string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("key 'configs_checked' missing"), std::string::npos) << bad.err;
}

TEST(ValidateCommand, RefusesUnknownOptionValues) {
  const auto removal = test::safecell_cli({"validate", "--scenes", "1", "--removal", "magic"});
  EXPECT_EQ(removal.exit_code, 2);
  EXPECT_NE(removal.err.find("--removal 'magic'"), std::string::npos) << removal.err;
  const auto control =
      test::safecell_cli({"validate", "--scenes", "1", "--negative-control", "oops"});
  EXPECT_EQ(control.exit_code, 2);
  EXPECT_NE(control.err.find("--negative-control 'oops'"), std::string::npos) << control.err;
  const auto shard = test::safecell_cli({"validate", "--scenes", "4", "--shard", "5/4"});
  EXPECT_EQ(shard.exit_code, 2);
  EXPECT_NE(shard.err.find("--shard '5/4'"), std::string::npos) << shard.err;
  const auto reach = test::safecell_cli({"validate", "--scenes", "1", "--occlusion-reach", "-1"});
  EXPECT_EQ(reach.exit_code, 2);
  EXPECT_NE(reach.err.find("--occlusion-reach"), std::string::npos) << reach.err;
  const auto parts =
      test::safecell_cli({"validate", "--scenes", "1", "--robot-parts", "per-joint"});
  EXPECT_EQ(parts.exit_code, 2);
  EXPECT_NE(parts.err.find("--robot-parts 'per-joint'"), std::string::npos) << parts.err;
}

}  // namespace
}  // namespace safecell

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"
#include "coarse_cell.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

class LutsCommand : public ::testing::Test {
 protected:
  test::ScratchFolder scratch_{"safecell-luts-command"};
  fs::path folder_ = scratch_.path();
  fs::path cell_ = test::write_coarse_cell(folder_);
};

TEST_F(LutsCommand, BuildsOnceAndReportsSizes) {
  const fs::path out = folder_ / "luts";
  const auto first = test::safecell_cli(
      {"luts", "build", "--cell", cell_.string(), "--out", out.string(), "--json"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const auto report = nlohmann::json::parse(first.out);
  EXPECT_TRUE(report["built"].get<bool>());
  EXPECT_EQ(report["cameras"].size(), 4U);
  EXPECT_GT(report["bytes_per_camera"].get<double>(), 0.0);
  EXPECT_GT(report["compression_ratio"].get<double>(), 1.0);
  EXPECT_TRUE(fs::exists(report["file"].get<std::string>()));
  // The stages' times: every stage ran, and together they are the build's time (give or take the
  // fingerprint, computed before the build's clock starts).
  double stages_s = 0.0;
  for (const char* stage : {"lut1_silhouettes", "lut2_inversion", "static_obstacles"}) {
    ASSERT_TRUE(report["stage_s"].contains(stage)) << report.dump();
    EXPECT_GT(report["stage_s"][stage].get<double>(), 0.0) << stage;
    stages_s += report["stage_s"][stage].get<double>();
  }
  const double build_s = report["build_s"].get<double>();
  EXPECT_NEAR(stages_s, build_s, 0.25 + 0.1 * build_s) << report.dump();

  const auto second = test::safecell_cli(
      {"luts", "build", "--cell", cell_.string(), "--out", out.string(), "--json"});
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_FALSE(nlohmann::json::parse(second.out)["built"].get<bool>());
  EXPECT_FALSE(nlohmann::json::parse(second.out).contains("stage_s"));

  const auto info = test::safecell_cli({"luts", "info", out.string()});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("cam3"), std::string::npos);
  EXPECT_NE(info.out.find("model mode"), std::string::npos);

  // A folder that also keeps a file it cannot use (as the cache keeps those of older versions):
  // the usable one is reported, the other named, and the exit code says so.
  std::ofstream(out / "0000000000000000.sclut") << std::string(200, 'x');
  const auto mixed = test::safecell_cli({"luts", "info", out.string(), "--json"});
  EXPECT_EQ(mixed.exit_code, 2);
  EXPECT_EQ(nlohmann::json::parse(mixed.out)["cameras"].size(), 4U) << mixed.out;
  EXPECT_NE(mixed.err.find("skipped"), std::string::npos) << mixed.err;
  EXPECT_NE(mixed.err.find("0000000000000000.sclut"), std::string::npos) << mixed.err;
}

TEST_F(LutsCommand, BuildVerifiesTheTablesAgainstTheSilhouettes) {
  const fs::path out = folder_ / "luts";
  const auto built = test::safecell_cli({"luts", "build", "--cell", cell_.string(), "--out",
                                         out.string(), "--verify-cells", "50", "--json"});
  ASSERT_EQ(built.exit_code, 0) << built.err;
  const auto verified = nlohmann::json::parse(built.out)["verified"];
  EXPECT_EQ(verified["cells"].get<int>(), 50);
  EXPECT_GT(verified["pairs"].get<double>(), 50.0 * 4096 * 4);
  EXPECT_EQ(verified["mismatches"].get<int>(), 0) << verified.dump(2);

  // The same tables, now read from the folder, checked again with other cells; the text says how
  // many were compared and with which seed.
  const auto text = test::safecell_cli({"luts", "build", "--cell", cell_.string(), "--out",
                                        out.string(), "--verify-cells", "20", "--seed", "3"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("20 cells (seed 3)"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find(": 0 mismatches"), std::string::npos) << text.out;

  const auto absurd = test::safecell_cli(
      {"luts", "build", "--cell", cell_.string(), "--out", out.string(), "--verify-cells", "-4"});
  EXPECT_EQ(absurd.exit_code, 2) << absurd.err;
}

TEST_F(LutsCommand, CheckComparesTheRecordedRobotWithTheModel) {
  const auto check = test::safecell_cli({"luts", "check", "--cell", cell_.string(), "--key-stride",
                                         "6", "--wrist-samples", "1", "--json"});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  const auto report = nlohmann::json::parse(check.out);
  EXPECT_FALSE(report["flagged"].get<bool>());
  ASSERT_EQ(report["cameras"].size(), 4U);
  for (const auto& camera : report["cameras"]) {
    EXPECT_GE(camera["coverage"].get<double>(), 0.95) << camera.dump();
    EXPECT_GT(camera["keys"].get<int>(), 0) << camera.dump();
  }
  const auto table = test::safecell_cli(
      {"luts", "check", "--cell", cell_.string(), "--key-stride", "6", "--wrist-samples", "1"});
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("coverage"), std::string::npos) << table.out;
}

TEST_F(LutsCommand, RecordRefusesCamerasTooCloseForItsBoundBeforeRecording) {
  const fs::path out = folder_ / "recorded";
  const auto record = test::safecell_cli(
      {"luts", "record", "--cell", cell_.string(), "--out", out.string(), "--key-stride", "6"});
  EXPECT_EQ(record.exit_code, 2);
  EXPECT_NE(record.err.find("cam0"), std::string::npos) << record.err;
  EXPECT_EQ(record.err.find("recording "), std::string::npos) << "recorded before refusing";
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(LutsCommand, RefusesWhatIsNotALutFile) {
  const fs::path bogus = folder_ / "bogus.sclut";
  std::ofstream(bogus) << std::string(200, 'x');
  const auto garbage = test::safecell_cli({"luts", "info", bogus.string()});
  EXPECT_EQ(garbage.exit_code, 2);
  EXPECT_NE(garbage.err.find("not a safecell LUT file"), std::string::npos) << garbage.err;

  fs::create_directories(folder_ / "empty");
  const auto empty = test::safecell_cli({"luts", "info", (folder_ / "empty").string()});
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("holds no LUT file"), std::string::npos) << empty.err;

  const auto absurd = test::safecell_cli(
      {"luts", "build", "--cell", cell_.string(), "--out", folder_.string(), "--ball-radius", "3"});
  EXPECT_NE(absurd.exit_code, 0);
}

}  // namespace
}  // namespace safecell

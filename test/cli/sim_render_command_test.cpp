#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "safecell/cli/cli_app.hpp"

namespace safecell {
namespace {

using test::CliRun;
using test::safecell_cli;

std::filesystem::path fresh_directory(const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(path);
  return path;
}

TEST(SimRenderCommand, WritesOneImagePerCameraAndASheet) {
  const auto out = fresh_directory("safecell-sim-render");
  const CliRun run = safecell_cli({"sim", "render", "--q", "20,40,50,0,60,0", "--human",
                                   "1.2,-0.8,120", "--out", out.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* name : {"cam0.png", "cam1.png", "cam2.png", "cam3.png"}) {
    const cv::Mat image = cv::imread((out / name).string(), cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(image.empty()) << name;
    EXPECT_EQ(image.type(), CV_8UC1) << name;
    EXPECT_EQ(image.cols, 704);
    EXPECT_EQ(image.rows, 576);
  }
  EXPECT_FALSE(cv::imread((out / "cameras.png").string()).empty());
  EXPECT_NE(run.out.find("ground truth: robot clear of the obstacles"), std::string::npos)
      << run.out;
  std::filesystem::remove_all(out);
}

TEST(SimRenderCommand, RendersTheRx160WithItsVisualMeshes) {
  const auto urdf =
      std::filesystem::path(SAFECELL_SHARED_DATA_DIR) / "robots/staubli_rx160/rx160.urdf";
  if (!std::filesystem::exists(urdf)) GTEST_SKIP() << "no RX160 model at " << urdf;
  const auto out = fresh_directory("safecell-sim-render-rx160");
  const auto cell = std::filesystem::temp_directory_path() / "safecell-rx160-cell.yaml";
  std::ofstream(cell) << "name: rx160\nm_max_m: 0.18\nrobot: {urdf: " << urdf.string()
                      << ", tool: {frame: flange}}\njoints:\n"
                         "  - {name: joint_1}\n  - {name: joint_2}\n  - {name: joint_3}\n"
                         "  - {name: joint_4, discretised: false}\n"
                         "  - {name: joint_5, discretised: false}\n"
                         "  - {name: joint_6, discretised: false}\n"
                         "cameras:\n  - {name: front, look_at: {position_m: [3, 0, 2], target_m: "
                         "[0, 0, 1], horizontal_fov_deg: 70, size_px: [352, 288]}}\n"
                         "feature_grid: {columns: 32, rows: 32}\n";
  const CliRun run = safecell_cli({"sim", "render", "--cell", cell.string(), "--q",
                                   "0,30,60,0,30,0", "--visual", "--out", out.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const cv::Mat image = cv::imread((out / "front.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(image.cols, 352);
  std::filesystem::remove_all(out);
  std::filesystem::remove(cell);
}

TEST(SimRenderCommand, TheGroundTruthSeesAHumanInTheRobotsWay) {
  const auto out = fresh_directory("safecell-sim-render-touch");
  // Stretched forward along +x at shoulder height: the flange reaches x = 1.51 m.
  const CliRun run = safecell_cli(
      {"sim", "render", "--q", "0,90,0,0,0,0", "--human", "1.3,0", "--out", out.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("COLLIDES"), std::string::npos) << run.out;
  std::filesystem::remove_all(out);
}

TEST(SimRenderCommand, BadOptionsGiveOneLineAndExitCode2) {
  const auto out = fresh_directory("safecell-sim-render-bad").string();
  const auto error_of = [&](std::vector<std::string> arguments) {
    arguments.insert(arguments.begin(), {"sim", "render", "--out", out});
    const CliRun run = safecell_cli(arguments);
    EXPECT_EQ(run.exit_code, kExitBadInput) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    return run.err;
  };
  EXPECT_EQ(error_of({"--q", "1,2,3"}), "error: --q '1,2,3': 6 joint values expected, got 3\n");
  EXPECT_EQ(error_of({"--q", "0,0,0,0,0,x"}),
            "error: --q '0,0,0,0,0,x': expected comma-separated numbers, 'x' is not one\n");
  EXPECT_EQ(error_of({"--q", "0,170,0,0,0,0"}),
            "error: --q '0,170,0,0,0,0': joint_2 = 170.00 deg lies outside the cell's range "
            "[-137.50, 137.50] deg\n");
  EXPECT_EQ(error_of({"--q", "0,0,0,0,0,0", "--human", "1"}),
            "error: --human '1': expected x,y or x,y,heading_deg (metres, degrees)\n");
  EXPECT_NE(error_of({}).find("exactly one of --q"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace safecell

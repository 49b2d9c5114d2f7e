#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/cli/cli_app.hpp"

namespace safecell {
namespace {

using test::CliRun;
using test::safecell_cli;

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

TEST(CellInfoCommand, JsonOfTheDefaultCell) {
  const CliRun run = safecell_cli({"cell", "info", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_GE(report["cells"].get<std::uint64_t>(), 150000u);
  EXPECT_LE(report["cells"].get<std::uint64_t>(), 200000u);
  ASSERT_EQ(report["joints"].size(), 6u);
  std::uint64_t product = 1;
  for (const auto& joint : report["joints"]) {
    EXPECT_TRUE(joint.contains("name"));
    EXPECT_GT(joint["l_m"].get<double>(), 0.0);
    EXPECT_TRUE(joint.contains("dq_rad"));
    product *= joint["cells"].get<std::uint64_t>();
  }
  EXPECT_EQ(product, report["cells"].get<std::uint64_t>());
  EXPECT_TRUE(report["joints"][4]["dq_rad"].is_null());             // the wrist is swept
  EXPECT_EQ(report["fingerprint"].get<std::string>().size(), 18u);  // 0x + 16 hex digits
}

TEST(CellInfoCommand, TextNamesEveryJointAndTheTotal) {
  const CliRun run = safecell_cli({"cell", "info"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* expected : {"joint_1", "joint_6", "swept", "C-space cells:", "fingerprint:",
                               "m_max = 0.180 m", "robot: rx130_class", "discretise"}) {
    EXPECT_NE(run.out.find(expected), std::string::npos) << expected << " missing in\n" << run.out;
  }
}

TEST(CellInfoCommand, ACellFileGivesTheSameReportAsTheBuiltInText) {
  const auto path = write_temp("safecell-cli-two.yaml",
                               "name: two\nm_max_m: 0.18\njoints:\n"
                               "  - {name: a, range_deg: [-90, 90], l_m: 1.0}\n"
                               "  - {name: b, range_deg: [-90, 90], l_m: 0.5}\n");
  const CliRun run = safecell_cli({"cell", "info", "--json", "--cell", path.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_EQ(report["cell"], "two");
  EXPECT_EQ(report["source"], path.string());
  // a: dq = 2 asin(0.09) = 0.18024 rad over pi rad -> 17.4 -> 18 cells;
  // b: dq = 2 asin(0.18) = 0.36198 rad -> 8.68 -> 9 cells.
  EXPECT_EQ(report["joints"][0]["cells"], 18);
  EXPECT_EQ(report["joints"][1]["cells"], 9);
  EXPECT_EQ(report["cells"], 162);
  std::filesystem::remove(path);
}

// The default cell votes as the validation found safe; the same cell at the occlusion reach of 3
// is warned about, in the text and in the JSON.
TEST(CellInfoCommand, AVoteTheValidationDoesNotCoverIsWarnedAbout) {
  const CliRun built_in = safecell_cli({"cell", "info", "--json"});
  ASSERT_EQ(built_in.exit_code, 0) << built_in.err;
  EXPECT_TRUE(nlohmann::json::parse(built_in.out)["warnings"].empty()) << built_in.out;
  EXPECT_EQ(safecell_cli({"cell", "info"}).out.find("warning"), std::string::npos);

  std::string yaml(default_cell_yaml());
  const std::string reach = "\nocclusion_reach_cells: 4\n";
  ASSERT_NE(yaml.find(reach), std::string::npos);
  yaml.replace(yaml.find(reach), reach.size(), "\nocclusion_reach_cells: 3\n");
  const auto path = write_temp("safecell-cli-reach-3.yaml", yaml);
  const CliRun text = safecell_cli({"cell", "info", "--cell", path.string()});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("warning: " + path.string() +
                          ": camera_threshold 3 with occlusion_reach_cells 3 -"),
            std::string::npos)
      << text.out;
  const CliRun json = safecell_cli({"cell", "info", "--json", "--cell", path.string()});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_EQ(nlohmann::json::parse(json.out)["warnings"].size(), 1U) << json.out;
  std::filesystem::remove(path);
}

TEST(CellInfoCommand, ABadCellFileGivesOneLineAndExitCode2) {
  const auto path = write_temp("safecell-cli-bad.yaml",
                               "name: bad\nm_max_m: 0.18\njoints:\n"
                               "  - {name: a, range_deg: [90, -90], l_m: 1.0}\n");
  const CliRun run = safecell_cli({"cell", "info", "--cell", path.string()});
  EXPECT_EQ(run.exit_code, kExitBadInput);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err, "error: " + path.string() +
                         ":4: joints[0].range_deg: value [90, -90], expected finite limits with "
                         "lower < upper\n");
  std::filesystem::remove(path);
}

TEST(CellInfoCommand, HelpAndUsageErrors) {
  const CliRun help = safecell_cli({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("cell"), std::string::npos);
  const CliRun nothing = safecell_cli({});
  EXPECT_NE(nothing.exit_code, 0);
  const CliRun unknown = safecell_cli({"cell", "info", "--colour"});
  EXPECT_NE(unknown.exit_code, 0);
  EXPECT_NE(unknown.err.find("--colour"), std::string::npos) << unknown.err;
}

}  // namespace
}  // namespace safecell

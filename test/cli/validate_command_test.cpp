#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "coarse_cell.hpp"

namespace safecell {
namespace {

TEST(ValidateCommand, ReportsTheIssuesKeysAndMissesNothing) {
  const test::ScratchFolder scratch("safecell-validate");
  const auto cell = test::write_coarse_cell(scratch.path());
  const auto run = test::safecell_cli({"validate", "--cell", cell.string(), "--scenes", "3",
                                       "--seed", "5", "--configs", "100", "--json", "--lut-cache",
                                       (scratch.path() / "cache").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const auto report = nlohmann::json::parse(run.out);
  for (const char* key : {"scenes", "objects", "configs_checked", "missed", "false_positive_rate",
                          "phantom_cells", "fusion_ms_p99"}) {
    EXPECT_TRUE(report.contains(key)) << key;
  }
  EXPECT_EQ(report["scenes"].get<int>(), 3);
  EXPECT_EQ(report["configs_checked"].get<int>(), 300);
  EXPECT_EQ(report["missed"].get<int>(), 0);
}

TEST(ValidateCommand, RefusesAnUnknownRemoval) {
  const auto run = test::safecell_cli({"validate", "--scenes", "1", "--removal", "magic"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--removal 'magic'"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace safecell

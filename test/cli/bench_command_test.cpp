#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace safecell {
namespace {

// Runs the real benchmarks briefly: proves the keys and their sense, never the speed.
TEST(BenchCommand, JsonCarriesTheNamedFiguresOfEveryBenchmark) {
  const test::CliRun run = test::safecell_cli({"bench", "--json", "--quick"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  for (const char* key :
       {"features_ms", "features_worst_ms", "sim_render_ms", "sim_render_worst_ms"}) {
    ASSERT_TRUE(report.contains(key)) << key;
    EXPECT_GT(report[key].get<double>(), 0.0) << key;
  }
  EXPECT_GE(report["features_worst_ms"].get<double>(), report["features_ms"].get<double>());
  const auto& masks = report["benchmarks"]["four_frames_to_blocked_masks"]["counters"];
  EXPECT_GT(masks["blocked_cells"].get<double>(), 0.0);  // the human is seen
  EXPECT_EQ(masks["blocked_cells_empty_scene"].get<double>(), 0.0);
}

}  // namespace
}  // namespace safecell

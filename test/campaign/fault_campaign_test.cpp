// The fault campaign of ../shared/SAFETY.md as CI runs it: every fault class against the real
// safecell-controller program on loopback, on the coarse cell, in real time; its table goes to
// the test's output. The faults injected at a rate run 1.5 s at 0.3 per datagram (about 45 maps
// and clock echoes): fewer than the two a latch needs is a chance of about 2 in a million. The
// negative control: a controller whose watchdog and data age limit are 2 s instead of 250 ms must
// fail the same checks, by moving on stale data.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../cli/cli_run.hpp"
#include "../cli/coarse_cell.hpp"
#include "safecell/campaign/fault_class.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

nlohmann::json campaign_json(const fs::path& folder) {
  std::ifstream in(folder / "campaign.json");
  std::ostringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());
}

std::vector<std::string> campaign_arguments(const fs::path& scratch, const fs::path& out) {
  return {"campaign",
          "--cell",
          test::write_coarse_cell(scratch).string(),
          "--lut-cache",
          (scratch / "cache").string(),
          "--out",
          out.string(),
          "--settle",
          "1.5",
          "--fault-seconds",
          "1.5",
          "--recover",
          "3",
          "--rate",
          "0.3"};
}

TEST(FaultCampaign, EveryFaultClassIsHeldInTimeAndNothingWrongIsAccepted) {
  const test::ScratchFolder scratch("campaign");
  const fs::path out = scratch.path() / "campaign";
  const auto run = test::safecell_cli(campaign_arguments(scratch.path(), out));
  std::cout << run.out;
  std::ofstream(SAFECELL_CAMPAIGN_TABLE) << run.out;  // the table, for CI's log
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json result = campaign_json(out);
  ASSERT_EQ(result["trials"].size(), all_fault_classes().size());
  for (const nlohmann::json& trial : result["trials"]) {
    const std::string fault = trial["fault"].get<std::string>();
    EXPECT_TRUE(trial["passed"].get<bool>()) << fault << ": " << trial["failures"].dump();
    EXPECT_GE(trial["injected"].get<int>(), 1) << fault;
    EXPECT_EQ(trial["wrong_maps_accepted"].get<int>(), 0) << fault;
    EXPECT_EQ(trial["stale_motion_cycles"].get<int>(), 0) << fault;
    if (fault != "wrong-fingerprint") {
      EXPECT_GT(trial["maps_applied"].get<int>(), 10) << fault;
    }
  }
}

TEST(FaultCampaign, AControllerWithTooLongAWatchdogFails) {
  // Three faults that silence the link for 1.5 s. A controller with a 2 s watchdog keeps moving
  // on its last map, which must show as motion on stale data. Something else may still hold the
  // robot in one trial by chance (a late cycle under load trips the cycle's own watchdog), so
  // the campaign must fail and at least one trial must show the stale motion itself.
  const test::ScratchFolder scratch("campaign-negative");
  const fs::path out = scratch.path() / "campaign";
  std::vector<std::string> arguments = campaign_arguments(scratch.path(), out);
  for (const char* extra : {"--faults", "link-cut,coprocessor-killed,delay",
                            "--test-only-controller-limits-ms", "2000"}) {
    arguments.emplace_back(extra);
  }
  const auto run = test::safecell_cli(arguments);
  std::cout << run.out;
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  const nlohmann::json result = campaign_json(out);
  ASSERT_EQ(result["trials"].size(), 3U);
  int stale_motion = 0;
  for (const nlohmann::json& trial : result["trials"]) {
    stale_motion += trial["stale_motion_cycles"].get<int>();
  }
  EXPECT_GT(stale_motion, 0) << result.dump(2);
}

}  // namespace
}  // namespace safecell

// The Linux controller module: its configuration file (every refusal names the field and the
// line) and a short run with no coprocessor, in which the robot must be held (waiting) all along.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "safecell/controller/host/controller_module.hpp"

namespace safecell {
namespace {

std::string example() {
  std::ifstream file(SAFECELL_CONTROLLER_EXAMPLE);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string refusal(const std::string& text) {
  try {
    (void)parse_controller_config(text, "controller.yaml");
  } catch (const ControllerConfigError& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST(ControllerConfig, TheExampleLoads) {
  const ControllerConfig config = load_controller_config(SAFECELL_CONTROLLER_EXAMPLE);
  EXPECT_EQ(config.grid.joint_count, 6u);
  EXPECT_FALSE(config.grid.joints[4].discretised);
  EXPECT_EQ(config.task.goals_rad.size(), 2u);
  EXPECT_EQ(config.link.listen.port, 47701);
  EXPECT_EQ(config.safety.fault_stop, StopCategory::kCategory1);
  EXPECT_EQ(config.link.map_work_per_slice, 128u);
}

TEST(ControllerConfig, RefusalsNameTheFieldLineAndValue) {
  const std::string text = example();
  EXPECT_NE(refusal(replaced(text, "period_ms: 4 ", "period_ms: -4 ")).find("timing.period_ms"),
            std::string::npos);
  const std::string bad_period = refusal(replaced(text, "period_ms: 4 ", "period_ms: fast "));
  EXPECT_NE(bad_period.find("controller.yaml:"), std::string::npos) << bad_period;
  EXPECT_NE(bad_period.find("'fast'"), std::string::npos) << bad_period;
  EXPECT_NE(refusal(replaced(text, "fault_stop: category_1", "fault_stop: category_0"))
                .find("expected category_1 or category_2"),
            std::string::npos);
  EXPECT_NE(
      refusal(replaced(text, "listen: 127.0.0.1:47701", "listen: localhost")).find("link.listen"),
      std::string::npos);
  EXPECT_NE(refusal(replaced(text, "- [1.0, 0.3, -0.4, 0.0, 0.0, 0.0]", "- [1.0, 0.3]"))
                .find("task.goals_rad[0]"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(text, "- [1.0, 0.3, -0.4", "- [9.0, 0.3, -0.4")).find("range"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(text, "m_max_m: 0.18 ", "m_max_m: 0 ")).find("grid.m_max_m"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(text, "map_work_per_slice: 128 ", "map_work_per_slice: 0 "))
                .find("link.map_work_per_slice"),
            std::string::npos);
  EXPECT_NE(refusal("grid: [").find("not valid YAML"), std::string::npos);
  EXPECT_NE(refusal("- 1").find("a YAML map"), std::string::npos);
}

// Only grid and robot are required; a file without the other sections takes their defaults
// (yaml-cpp throws on indexing a missing section: the reader must not).
TEST(ControllerConfig, OptionalSectionsMayBeLeftOut) {
  const std::string text = example();
  const std::string minimal = text.substr(0, text.find("\ntiming:") + 1);
  ASSERT_NE(minimal.find("robot:"), std::string::npos);
  const ControllerConfig config = parse_controller_config(minimal, "controller.yaml");
  EXPECT_EQ(config.timing.period_ms, ControllerTiming{}.period_ms);
  EXPECT_EQ(config.pool_blocks, 0u);
  EXPECT_TRUE(config.task.goals_rad.empty());
}

TEST(ControllerModule, WithoutACoprocessorTheRobotIsHeld) {
  ControllerConfig config = load_controller_config(SAFECELL_CONTROLLER_EXAMPLE);
  config.link.listen.port = 0;  // any free port
  config.link.coprocessor.port = 9;
  ControllerModule module(config);
  int lines = 0;
  bool ever_moved = false;
  const TaskOutcome outcome = module.run(0.3, 0.05, [&](const ModuleStatus& status) {
    ++lines;
    ever_moved = ever_moved || status.cycle->state != CycleState::kWaiting;
    EXPECT_NE(status_line(status).find("waiting"), std::string::npos) << status_line(status);
  });
  EXPECT_EQ(outcome, TaskOutcome::kTimedOut);
  EXPECT_FALSE(ever_moved);
  EXPECT_GE(lines, 3);
  EXPECT_GT(module.status().cycles, 30u);
}

}  // namespace
}  // namespace safecell

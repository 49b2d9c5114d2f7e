// The Linux controller module: its configuration file (every refusal names the field and the
// line), a short run with no coprocessor, in which the robot must be held (waiting) all along,
// and the lockstep channel of simulated time.

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "safecell/controller/host/controller_module.hpp"
#include "safecell/controller/host/lockstep_runner.hpp"

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

// Ambiguous or unsafe settings the cell file would refuse: each names the key, the value and what
// was expected. Each case is the example with one line changed; the example itself loads.
TEST(ControllerConfig, AmbiguousAndUnsafeSettingsAreRefused) {
  const std::string text = example();
  const struct {
    const char* from;
    const char* to;
    const char* expected;
  } cases[] = {
      {"  watchdog_ms: 100 ", "  watchdog_ms: 100\n  watchdog_ms: 5000 ",
       "timing.watchdog_ms: given twice (first on line"},
      {"  watchdog_ms: 100 ", "  watchdog_msec: 100 ", "timing.watchdog_msec: unknown key"},
      {"map_store:", "map_storage:", "map_storage: unknown key; expected one of grid, robot"},
      {"human_speed_m_s: 1.6 ", "human_speed_m_s: 0 ",
       "safety.human_speed_m_s: is '0'; expected a number from 1.6 to 10"},
      {"human_speed_m_s: 1.6 ", "human_speed_m_s: 1.2 ", "expected a number from 1.6 to 10"},
      {"min_healthy_cameras: 2 ", "min_healthy_cameras: 0 ",
       "safety.min_healthy_cameras: is '0'; expected 1 to 64"},
      {"listen: 127.0.0.1:47701", "listen: 127.0.0.1:1e999", "link.listen: is '127.0.0.1:1e999'"},
      {"listen: 127.0.0.1:47701", "listen: 127.0.0.1:42286abc", "link.listen: is"},
      {"listen: 127.0.0.1:47701", "listen: 127.0.0.1:0", "with a port of 1..65535"},
      {"coprocessor: 127.0.0.1:47700", "coprocessor: 127.0.0.1:65536", "link.coprocessor: is"},
      {"coprocessor: 127.0.0.1:47700", "coprocessor: 327.0.0.1:47700", "link.coprocessor: is"},
      {"    - {lo_rad: -2.792527, hi_rad: 2.792527, l_m: 1.524, discretised: true}",
       "    - {lo_rad: -2.792527, hi_rad: 2.792527, l_m: 1.524, discretised: true, l_m: 0.1}",
       "grid.joints[0].l_m: given twice"},
  };
  for (const auto& c : cases) {
    const std::string message = refusal(replaced(text, c.from, c.to));
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.to << ": " << message;
    EXPECT_EQ(message.rfind("controller.yaml:", 0), 0u) << message;
  }
  // A slower walking speed with its reason is taken; the reason may not be empty.
  const ControllerConfig slow = parse_controller_config(
      replaced(text, "human_speed_m_s: 1.6 ",
               "human_speed_reason: seated operators behind a fence\n  human_speed_m_s: 1.0 "),
      "controller.yaml");
  EXPECT_EQ(slow.safety.human_speed_m_s, 1.0);
  EXPECT_NE(refusal(replaced(text, "human_speed_m_s: 1.6 ",
                             "human_speed_reason: ''\n  human_speed_m_s: 1.0 "))
                .find("safety.human_speed_reason: is empty"),
            std::string::npos);
}

// A file cut short anywhere (a copy interrupted, an editor's crash) is read or refused with the
// reader's own error, never another exception (exit 70 in the program).
TEST(ControllerConfig, EveryPrefixOfTheExampleIsReadOrRefusedByName) {
  const std::string text = example();
  for (std::size_t cut = 0; cut <= text.size(); ++cut) {
    try {
      (void)parse_controller_config(text.substr(0, cut), "controller.yaml");
    } catch (const ControllerConfigError&) {
    } catch (const std::exception& error) {
      ADD_FAILURE() << "cut at byte " << cut << ": " << error.what() << "\n...\n"
                    << text.substr(cut > 200 ? cut - 200 : 0, cut > 200 ? 200 : cut);
      break;
    }
  }
}

TEST(ControllerConfig, AFileNestedOrSizedBeyondAnyControllerIsRefused) {
  const std::string deep = refusal("grid: " + std::string(100000, '[') + std::string(100000, ']'));
  EXPECT_NE(deep.find("nested deeper than"), std::string::npos) << deep;
  const std::string path = ::testing::TempDir() + "/safecell-huge-controller.yaml";
  std::ofstream(path) << "# " << std::string(2u << 20, 'x') << "\n";
  try {
    (void)load_controller_config(path);
    ADD_FAILURE() << "a 2 MB controller file was read";
  } catch (const ControllerConfigError& error) {
    EXPECT_NE(std::string(error.what()).find("expected at most 1048576"), std::string::npos)
        << error.what();
  }
  std::remove(path.c_str());
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

TEST(ControllerConfig, TaskMotionAndTheTestOnlySwitch) {
  const std::string text = example();
  const ControllerConfig plain = parse_controller_config(text, "controller.yaml");
  EXPECT_EQ(plain.task.motion, TaskMotion::kGrossMotion);
  EXPECT_FALSE(plain.safety.test_only_look_ahead_off);
  const ControllerConfig program = parse_controller_config(
      replaced(text, "motion: gross_motion", "motion: program"), "controller.yaml");
  EXPECT_EQ(program.task.motion, TaskMotion::kProgram);
  EXPECT_NE(refusal(replaced(text, "motion: gross_motion", "motion: teleport")).find("task.motion"),
            std::string::npos);
  const ControllerConfig off = parse_controller_config(
      replaced(text, "  # test_only_look_ahead_off: true", "  test_only_look_ahead_off: true"),
      "controller.yaml");
  EXPECT_TRUE(off.safety.test_only_look_ahead_off);
}

// A pipe as the lockstep channel: the commands written before the runner starts.
struct CommandPipe {
  CommandPipe() { EXPECT_EQ(::pipe(fds), 0); }
  ~CommandPipe() {
    ::close(fds[0]);
    if (fds[1] >= 0) ::close(fds[1]);
  }
  void write(const std::string& text) const {
    EXPECT_EQ(::write(fds[1], text.data(), text.size()), static_cast<ssize_t>(text.size()));
  }
  void close_writer() {
    ::close(fds[1]);
    fds[1] = -1;
  }
  int fds[2] = {-1, -1};
};

ControllerConfig unconnected_config() {
  ControllerConfig config = load_controller_config(SAFECELL_CONTROLLER_EXAMPLE);
  config.link.listen.port = 0;  // any free port
  config.link.coprocessor.port = 9;
  return config;
}

struct LockstepRun {
  int exit_code = 0;
  std::string out;
  std::string log;
};

// A stepped module without a coprocessor, given `commands` (nullptr: the channel closed at once).
LockstepRun run_lockstep_on(const char* commands) {
  const ControllerConfig config = unconnected_config();
  ControllerModule module(config, ModuleTime::kStepped);
  CommandPipe pipe;
  if (commands != nullptr) {
    pipe.write(commands);
  } else {
    pipe.close_writer();
  }
  std::ostringstream out;
  std::ostringstream log;
  const int code = run_lockstep(module, config.timing.period_ms, pipe.fds[0], out, log);
  return {code, out.str(), log.str()};
}

// The lockstep contract (lockstep_runner.hpp): cycles only when told, one truth line each, the
// clock never going back; without a coprocessor the robot is held all along.
TEST(LockstepRunner, CyclesOnlyWhenToldAndReportsTheRobotEachCycle) {
  const LockstepRun run = run_lockstep_on("advance 1100000000 0\nadvance 1100000000 0\nquit\n");
  EXPECT_EQ(run.exit_code, 0) << run.log;
  std::istringstream lines(run.out);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "ready 1000000000");
  int cycles = 0;
  while (std::getline(lines, line) && line.rfind("cycle ", 0) == 0) {
    ++cycles;
    EXPECT_NE(line.find(" waiting 0 "), std::string::npos) << line;
  }
  EXPECT_EQ(cycles, 25) << run.out;  // 100 ms of 4 ms cycles
  EXPECT_EQ(line.rfind("at 1100000000 ", 0), 0U) << line;
  std::getline(lines, line);
  EXPECT_EQ(line.rfind("at 1100000000 ", 0), 0U) << "no cycle is due: " << line;
  std::getline(lines, line);
  EXPECT_EQ(line, "bye 25");
}

TEST(LockstepRunner, RefusesTimeGoingBackAndAClosedChannel) {
  const LockstepRun back = run_lockstep_on("advance 1100000000 0\nadvance 1050000000 0\n");
  EXPECT_EQ(back.exit_code, 2);
  EXPECT_NE(back.log.find("advance 1050000000 0"), std::string::npos) << back.log;
  const LockstepRun closed = run_lockstep_on(nullptr);
  EXPECT_EQ(closed.exit_code, 2);
  EXPECT_NE(closed.log.find("closed"), std::string::npos) << closed.log;
}

// Real time on a shared machine: a cycle that comes late ends in a watchdog fault, which holds
// the robot as well as waiting does (CI saw one under load), so held means waiting or faulted,
// never moving or slowed, and the speed scale stays 0.
TEST(ControllerModule, WithoutACoprocessorTheRobotIsHeld) {
  ControllerConfig config = load_controller_config(SAFECELL_CONTROLLER_EXAMPLE);
  config.link.listen.port = 0;  // any free port
  config.link.coprocessor.port = 9;
  ControllerModule module(config);
  int lines = 0;
  bool ever_moved = false;
  const TaskOutcome outcome = module.run(0.3, 0.05, [&](const ModuleStatus& status) {
    ++lines;
    const CycleState state = status.cycle->state;
    const bool held = state == CycleState::kWaiting || state == CycleState::kFault;
    ever_moved = ever_moved || !held || status.cycle->speed_scale != 0.0;
    EXPECT_TRUE(held) << status_line(status);
  });
  EXPECT_EQ(outcome, TaskOutcome::kTimedOut);
  EXPECT_FALSE(ever_moved);
  EXPECT_GE(lines, 3);
  EXPECT_GT(module.status().cycles, 30u);
}

}  // namespace
}  // namespace safecell

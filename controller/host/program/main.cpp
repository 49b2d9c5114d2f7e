// safecell-controller: the Linux controller module. Reads its configuration, opens the link to
// the coprocessor, runs the safety cycle on the simulated robot at the configured period and
// works through the task's goals with the safe gross-motion service, printing its state.
//
// Exit codes: 0 task completed (or stopped by SIGINT/SIGTERM), 2 a configuration or setup error
// (the message names the file, field and value), 3 a goal could not be reached, 4 the time limit
// passed first, 70 an internal error. SIGUSR1 acknowledges a latched fault (the operator's key).

#include <CLI/CLI.hpp>

#include <sched.h>
#include <sys/mman.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

#include "safecell/controller/host/controller_module.hpp"
#include "safecell/controller/host/lockstep_runner.hpp"

namespace {

safecell::ControllerModule* running = nullptr;

extern "C" void on_signal(int signal) {
  if (running == nullptr) return;
  if (signal == SIGUSR1) {
    running->acknowledge();
  } else {
    running->request_stop();
  }
}

// Real-time scheduling where the machine allows it (root or CAP_SYS_NICE): the cycle then keeps
// its period under load. Memory is locked so that no page fault stalls a cycle. Returns what
// happened, for the first line.
std::string try_realtime(int priority) {
  sched_param param{};
  param.sched_priority = priority;
  if (sched_setscheduler(0, SCHED_FIFO, &param) != 0) {
    return std::string("not real-time (") + std::strerror(errno) +
           "): cycles may come late under load; timing.max_period_ms allows for that";
  }
#if defined(__SANITIZE_ADDRESS__)
  const bool locked = false;  // the sanitizer's shadow memory is terabytes of reserved pages
#else
  const bool locked = mlockall(MCL_CURRENT | MCL_FUTURE) == 0;
#endif
  return "real-time: SCHED_FIFO priority " + std::to_string(priority) +
         (locked ? ", memory locked" : ", memory not locked");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "safecell-controller: the controller module. Holds the forbidden map it gets from the "
      "coprocessor, checks the cells ahead of every moving joint each cycle, slows or stops the "
      "(simulated) robot, and moves it through the task's goals on free paths. SIGUSR1 "
      "acknowledges a latched fault."};
  std::string config_path;
  double duration_s = 0.0;
  double status_hz = 5.0;
  bool quiet = false;
  int realtime_priority = 20;
  bool lockstep = false;
  std::string trace_path;
  app.add_option("--config", config_path, "the controller's YAML file (controller.example.yaml)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--duration", duration_s, "stop after this many seconds (0: run until done)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--status-hz", status_hz, "status lines per second")
      ->check(CLI::Range(0.1, 100.0));
  app.add_flag("--quiet", quiet, "only the final line");
  app.add_option("--realtime-priority", realtime_priority,
                 "SCHED_FIFO priority of the cycle, where allowed (0: ordinary scheduling)")
      ->check(CLI::Range(0, 99));
  app.add_option("--trace", trace_path,
                 "write every cycle and link event as JSON lines to this file (fault campaigns, "
                 "post-mortems; about 150 bytes per cycle)");
  app.add_flag("--lockstep", lockstep,
               "simulated time, stepped over stdin/stdout by safecell validate --closed-loop");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;  // --help is 0; a wrong option or missing file is 2
  }

  try {
    const safecell::ControllerConfig config = safecell::load_controller_config(config_path);
    std::ostream& log = lockstep ? std::cerr : std::cout;
    if (config.safety.test_only_look_ahead_off && !lockstep) {
      std::cerr << "safecell-controller: " << config.source
                << ": safety.test_only_look_ahead_off is only allowed with --lockstep (the "
                   "closed-loop validation in simulated time), never on a robot in real time\n";
      return 2;
    }
    if (config.safety.test_only_look_ahead_off) {
      log << "safecell-controller: WARNING: safety.test_only_look_ahead_off is set: the robot is "
             "NOT slowed or stopped for people. A test setting (the validation's negative "
             "control), never for a robot near people.\n";
    }
    if (lockstep) {
      safecell::ControllerModule module(config, safecell::ModuleTime::kStepped);
      log << "safecell-controller: lockstep on " << config.link.listen.ip << ":"
          << module.listen_port() << ", cycle " << config.timing.period_ms << " ms\n";
      return safecell::run_lockstep(module, config.timing.period_ms, 0, std::cout, log);
    }
    std::ofstream trace;  // before the module, which writes to it until its end
    safecell::ControllerModule module(config);
    if (!trace_path.empty()) {
      trace.open(trace_path, std::ios::trunc);
      if (!trace) {
        std::cerr << "safecell-controller: --trace " << trace_path << ": cannot write ("
                  << std::strerror(errno) << ")\n";
        return 2;
      }
      module.trace_to(trace);
    }
    running = &module;
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    std::signal(SIGUSR1, on_signal);
    const std::string scheduling =
        realtime_priority > 0 ? try_realtime(realtime_priority) : "ordinary scheduling";
    std::cout << "safecell-controller: listening on " << config.link.listen.ip << ":"
              << module.listen_port() << ", coprocessor at " << config.link.coprocessor.ip << ":"
              << config.link.coprocessor.port << ", cycle " << config.timing.period_ms << " ms, "
              << config.task.goals_rad.size() << " goal(s); " << scheduling << "\n";
    const safecell::TaskOutcome outcome =
        module.run(duration_s, 1.0 / status_hz, [quiet](const safecell::ModuleStatus& status) {
          if (!quiet) std::cout << safecell::status_line(status) << "\n" << std::flush;
        });
    running = nullptr;
    const safecell::ModuleStatus& status = module.status();
    std::cout << "safecell-controller: " << to_string(outcome) << " after " << status.cycles
              << " cycles (worst period " << status.worst_period_ms << " ms, late cycles "
              << status.overruns << ")";
    if (!status.detail.empty()) std::cout << ": " << status.detail;
    std::cout << "\n";
    switch (outcome) {
      case safecell::TaskOutcome::kCompleted:
      case safecell::TaskOutcome::kStopped:
        return 0;
      case safecell::TaskOutcome::kFailed:
        return 3;
      case safecell::TaskOutcome::kTimedOut:
        return 4;
    }
    return 70;
  } catch (const safecell::ControllerConfigError& error) {
    std::cerr << "safecell-controller: " << error.what() << "\n";
    return 2;
  } catch (const std::runtime_error& error) {
    std::cerr << "safecell-controller: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "safecell-controller: internal error: " << error.what() << "\n";
    return 70;
  }
}

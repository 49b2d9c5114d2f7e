#include "safecell/closed_loop/lockstep_scenario.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ostream>
#include <sstream>

#include "safecell/closed_loop/controller_session.hpp"
#include "safecell/closed_loop/live_simulated_cameras.hpp"
#include "safecell/closed_loop/lockstep_controller.hpp"
#include "safecell/files/atomic_write.hpp"

namespace safecell {
namespace {

constexpr auto kJointStreamWait = std::chrono::seconds(5);

v1::ControllerState wire_state(const std::string& name) {
  if (name == "waiting") return v1::CONTROLLER_STATE_WAITING;
  if (name == "moving") return v1::CONTROLLER_STATE_MOVING;
  if (name == "slowed") return v1::CONTROLLER_STATE_SLOWED;
  if (name == "stopped") return v1::CONTROLLER_STATE_STOPPED;
  return v1::CONTROLLER_STATE_FAULT;
}

ControllerSetup scenario_setup(const LockstepParts& parts, const LockstepSettings& settings,
                               const RobotTask& task) {
  ControllerSetup setup = controller_setup_of(parts.cell, parts.grid);
  setup.start_rad = task.start_rad;
  setup.goals_rad = task.goals_rad;
  setup.repeat = false;
  setup.program_motion = task.program_motion;
  setup.test_only_look_ahead_off = settings.look_ahead_off;
  return setup;
}

// The robot at time_ns, between the cycles around it (linear; a cycle is 4 ms).
std::vector<double> robot_at(const std::vector<TruthSample>& truth, std::uint64_t time_ns) {
  const auto after = std::lower_bound(
      truth.begin(), truth.end(), time_ns,
      [](const TruthSample& sample, std::uint64_t t) { return sample.time_ns < t; });
  if (after == truth.begin()) return truth.front().q;
  if (after == truth.end()) return truth.back().q;
  const TruthSample& before = *(after - 1);
  const double f = static_cast<double>(time_ns - before.time_ns) /
                   static_cast<double>(after->time_ns - before.time_ns);
  std::vector<double> q(before.q.size());
  for (std::size_t j = 0; j < q.size(); ++j) q[j] = before.q[j] + f * (after->q[j] - before.q[j]);
  return q;
}

}  // namespace

ScenarioResult run_lockstep_scenario(LockstepParts& parts, const LockstepSettings& settings,
                                     const RobotTask& task,
                                     const std::optional<PersonVisitPlan>& person) {
  std::uint64_t sim_now_ns = 0;  // the coprocessor's clock: the controller's, stepped
  std::optional<LockstepController> lockstep;
  const std::filesystem::path log_file = parts.folder / "controller.log";
  ControllerSessionSettings session_settings;
  session_settings.program = parts.program;
  session_settings.camera_references = parts.camera_references;
  session_settings.folder = parts.folder;
  session_settings.fps = settings.fps;
  session_settings.sync_error_s = parts.sync_error_s;
  session_settings.extra_args = {"--lockstep"};
  session_settings.channel = ProcessChannel::kCommandPipes;
  session_settings.clock = [&sim_now_ns] { return sim_now_ns; };
  session_settings.on_started = [&](ControllerProcess& process) {
    lockstep.emplace(process, parts.grid.joint_count(),
                     [log_file] { return controller_log_tail(log_file); });
    sim_now_ns = lockstep->start_ns();
  };
  std::ostream quiet(nullptr);
  ControllerSession session(parts.cell, parts.grid, parts.pipeline, parts.lut_fingerprint,
                            scenario_setup(parts, settings, task), session_settings, quiet);
  const std::uint64_t start_ns = lockstep->start_ns();
  const auto seconds = [start_ns](std::uint64_t ns) {
    return static_cast<double>(ns - start_ns) * 1e-9;
  };
  const std::optional<PersonVisit> visit =
      person ? std::optional<PersonVisit>(PersonVisit(*person)) : std::nullopt;

  std::vector<TruthSample> truth;
  ClosedLoopRecord record;
  std::uint64_t exposure_ns = 0;
  LiveSimulatedCameras cameras(
      parts.sim,
      [&](std::uint64_t at_ns) {
        SimScene scene{robot_at(truth, at_ns), {}};
        if (visit) {
          if (auto pose = visit->at(seconds(at_ns))) scene.humans.push_back(*pose);
        }
        return scene;
      },
      [&exposure_ns] { return exposure_ns; });

  ScenarioResult result;
  result.outcome = "time limit";
  const auto period_ns = static_cast<std::uint64_t>(std::llround(1e9 / settings.fps));
  const auto latency_ns = static_cast<std::uint64_t>(std::llround(settings.latency_ms * 1e6));
  const auto max_ns = static_cast<std::uint64_t>(std::llround(settings.max_seconds * 1e9));
  double fault_since_s = -1.0;  // the fault has held since then; < 0: no fault
  for (std::uint64_t k = 1; k * period_ns <= max_ns; ++k) {
    exposure_ns = start_ns + k * period_ns;
    const std::uint64_t arrives_ns = exposure_ns + latency_ns;
    const LockstepStep step = lockstep->advance(arrives_ns, session.transport().datagrams_sent());
    for (const TruthSample& sample : step.cycles) {
      JointRecord joints;
      joints.time_s = seconds(sample.time_ns);
      joints.q = sample.q;
      joints.velocity = sample.velocity;
      joints.state = wire_state(sample.state);
      joints.speed_scale = sample.speed_scale;
      record.joints.push_back(std::move(joints));
      truth.push_back(sample);
    }
    // The controller's joint stream of this step into the sensing service, all of it, taken in
    // at the step's end (the frames' times lie up to then: earlier would be from the future).
    sim_now_ns = arrives_ns;
    const auto give_up = std::chrono::steady_clock::now() + kJointStreamWait;
    while (session.transport().datagrams_received() < step.controller_sent) {
      if (session.link().poll(std::chrono::microseconds(0)) == 0) {
        (void)session.link().poll(std::chrono::microseconds(200));
      }
      if (std::chrono::steady_clock::now() > give_up) {
        throw ClosedLoopSetupError(
            "the controller announced " + std::to_string(step.controller_sent) + " datagrams, " +
            std::to_string(session.transport().datagrams_received()) + " came within 5 s");
      }
    }
    if (step.ended) {
      result.outcome = *step.ended;
      result.task_completed = *step.ended == "task completed";
      result.task_time_s =
          step.cycles.empty() ? seconds(arrives_ns) : seconds(step.cycles.back().time_ns);
      break;
    }
    // The operator: a latched fault holds the robot until acknowledged.
    if (!record.joints.empty() && record.joints.back().state == v1::CONTROLLER_STATE_FAULT) {
      const double now_s = record.joints.back().time_s;
      if (fault_since_s < 0.0) fault_since_s = now_s;
      if (now_s - fault_since_s >= settings.acknowledge_after_s) {
        lockstep->acknowledge();
        fault_since_s = -1.0;
      }
    } else {
      fault_since_s = -1.0;
    }
    const ServiceCycle& cycle = session.service().process(cameras.acquire());
    ++result.frames;
    if (!cycle.all_forbidden.empty()) {
      ++result.all_forbidden_frames;
      ++result.all_forbidden_because[all_forbidden_kind(cycle.all_forbidden)];
    } else if (cycle.speed_limit < 1.0) {
      ++result.separation_slowed_frames;
    }
  }
  result.simulated_s = seconds(sim_now_ns);
  result.controller_cycles = lockstep->quit();
  (void)session.process().stop(std::chrono::seconds(2));

  result.contacts = check_contacts(*parts.cell.robot, record, [&](double time_s) {
    return visit ? visit->at(time_s) : std::nullopt;
  });
  if (!settings.trace_file.empty()) {
    std::ostringstream csv;
    csv.precision(6);
    csv << "time_s,state,speed_scale";
    for (std::size_t j = 0; j < parts.grid.joint_count(); ++j) csv << ",q" << j + 1;
    for (std::size_t j = 0; j < parts.grid.joint_count(); ++j) csv << ",dq" << j + 1;
    csv << ",person_x_m,person_y_m,distance_m\n";
    for (std::size_t i = 0; i < record.joints.size(); ++i) {
      const JointRecord& joints = record.joints[i];
      csv << joints.time_s << ',' << state_name(joints.state) << ',' << joints.speed_scale;
      for (const double q : joints.q) csv << ',' << q;
      for (const double v : joints.velocity) csv << ',' << v;
      const std::optional<HumanPose> pose = visit ? visit->at(joints.time_s) : std::nullopt;
      if (pose) {
        csv << ',' << pose->position_m.x() << ',' << pose->position_m.y() << ','
            << result.contacts.distance_m[i] << '\n';
      } else {
        csv << ",,,\n";
      }
    }
    write_file_atomically(settings.trace_file, csv.str());
  }
  result.contacts.distance_m.clear();
  result.states = state_figures(record);
  result.states.latency_ms.clear();
  result.states.latency_at_s.clear();
  return result;
}

}  // namespace safecell

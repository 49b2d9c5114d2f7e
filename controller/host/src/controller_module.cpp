#include "safecell/controller/host/controller_module.hpp"

#include <time.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <vector>

#include "safecell/controller/host/map_store_memory.hpp"
#include "safecell/controller/host/planner_memory.hpp"
#include "safecell/controller/host/simulated_robot.hpp"
#include "safecell/controller/host/system_entropy.hpp"
#include "safecell/controller/host/udp_link_port.hpp"
#include "safecell/controller/map_view.hpp"
#include "safecell/cspace/cell_bits.hpp"

namespace safecell {
namespace {

std::uint64_t monotonic_ns() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<std::uint64_t>(now.tv_sec) * 1'000'000'000u +
         static_cast<std::uint64_t>(now.tv_nsec);
}

void sleep_until(std::uint64_t deadline_ns) {
  timespec at{};
  at.tv_sec = static_cast<time_t>(deadline_ns / 1'000'000'000u);
  at.tv_nsec = static_cast<long>(deadline_ns % 1'000'000'000u);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &at, nullptr) != 0) {
  }
}

// The module's clock: monotonic, or stepped by a driver (simulated time).
class HostClock final : public ClockPort {
 public:
  explicit HostClock(ModuleTime time) : stepped_(time == ModuleTime::kStepped) {}
  std::uint64_t now_ns() noexcept override { return stepped_ ? stepped_ns_ : monotonic_ns(); }
  void set(std::uint64_t now_ns) noexcept { stepped_ns_ = now_ns; }

 private:
  bool stepped_;
  std::uint64_t stepped_ns_ = 0;
};

CspaceGrid grid_of(const ControllerConfig& config) {
  const auto grid = CspaceGrid::create(config.grid);
  if (!grid.ok()) throw ControllerConfigError(config.source + ": grid refused");
  return grid.value();
}

}  // namespace

const char* to_string(TaskOutcome outcome) noexcept {
  switch (outcome) {
    case TaskOutcome::kCompleted:
      return "task completed";
    case TaskOutcome::kFailed:
      return "task failed";
    case TaskOutcome::kStopped:
      return "stopped on request";
    case TaskOutcome::kTimedOut:
      return "time limit reached";
  }
  return "unknown";
}

struct ControllerModule::Parts {
  Parts(const ControllerConfig& config, ModuleTime time)
      : grid(grid_of(config)),
        store(config.pool_blocks != 0
                  ? MapStoreLayout::compressed(grid.cell_count(), config.pool_blocks)
                  : MapStoreLayout::of(grid.cell_count())),
        port(config.link.listen, config.link.coprocessor),
        link(link_config(config, grid), port, store.store(), entropy),
        robot(config.robot),
        clock(time),
        watchdog(watchdog_config(config)),
        cycle(grid, cycle_config(config), robot, clock, link, store.store(), watchdog),
        planner_layout(PlannerLayout::for_grid(grid.cell_count())),
        planner_memory(planner_layout),
        planner(grid, planner_layout, planner_memory.memory()),
        motion(grid, planner, motion_config(config)),
        free_slots(
            (cell_bits::words_for(grid.cell_count()) + kStoreBlockWords - 1) / kStoreBlockWords,
            kFreeSlot),
        free_map(free_slots.data(), nullptr, grid.cell_count()) {}

  static ControllerLinkConfig link_config(const ControllerConfig& config, const CspaceGrid& grid) {
    ControllerLinkConfig out;
    out.controller_id = config.link.controller_id;
    out.coprocessor_id = config.link.coprocessor_id;
    out.grid_fingerprint = grid.fingerprint();
    out.lut_fingerprint = config.link.lut_fingerprint;
    out.map_work_per_poll = config.link.map_work_per_slice;
    out.watchdog_ns = static_cast<std::uint64_t>(config.timing.watchdog_ms * 1e6);
    out.max_data_age_ns = static_cast<std::uint64_t>(config.timing.max_data_age_ms * 1e6);
    out.max_clock_lead_ns = static_cast<std::uint64_t>(config.timing.max_clock_lead_ms * 1e6);
    return out;
  }
  static WatchdogConfig watchdog_config(const ControllerConfig& config) {
    // Cycles may come half a period early, and late up to the configured window.
    const double period_ns = config.timing.period_ms * 1e6;
    return {static_cast<std::uint64_t>(period_ns * 0.5),
            static_cast<std::uint64_t>(config.timing.max_period_ms * 1e6),
            static_cast<std::uint64_t>(config.timing.budget_ms * 1e6)};
  }
  static SafetyCycleConfig cycle_config(const ControllerConfig& config) {
    SafetyCycleConfig out;
    // t_cycle: the next check may come as late as the watchdog's window allows.
    out.look_ahead.control_cycle_s = config.timing.max_period_ms * 1e-3;
    out.look_ahead.actuation_s = config.robot.actuation_s;
    out.look_ahead.human_speed_m_s = config.safety.human_speed_m_s;
    out.look_ahead.stop = SimulatedRobot::measure_stop_model(config.robot);
    out.look_ahead.max_cells = config.safety.max_look_ahead_cells;
    out.min_healthy_cameras = config.safety.min_healthy_cameras;
    out.look_ahead_stop = config.safety.look_ahead_stop;
    out.fault_stop = config.safety.fault_stop;
    out.look_ahead_switched_off = config.safety.test_only_look_ahead_off;
    return out;
  }
  static GrossMotionConfig motion_config(const ControllerConfig& config) {
    GrossMotionConfig out;
    for (std::uint32_t j = 0; j < config.robot.joint_count; ++j) {
      out.max_speed_rad_s[j] = config.robot.joints[j].max_speed_rad_s;
      out.accel_rad_s2[j] = config.robot.joints[j].accel_rad_s2;
    }
    return out;
  }

  CspaceGrid grid;
  HostMapStore store;
  UdpLinkPort port;
  SystemEntropy entropy;
  ControllerLink link;
  SimulatedRobot robot;
  HostClock clock;
  Watchdog watchdog;
  SafetyCycle cycle;
  PlannerLayout planner_layout;
  PlannerMemoryHost planner_memory;
  GridPlanner planner;
  GrossMotion motion;
  // An all-free map: what TaskMotion::kProgram plans on.
  std::vector<std::uint32_t> free_slots;
  MapView free_map;
  double planned[kMaxJoints] = {};  // the velocities planned after the last cycle
  std::uint64_t start_ns = 0;
  std::uint64_t last_start_ns = 0;
};

ControllerModule::ControllerModule(const ControllerConfig& config, ModuleTime time)
    : config_(config), parts_(std::make_unique<Parts>(config, time)) {}

ControllerModule::~ControllerModule() = default;

std::uint16_t ControllerModule::listen_port() const { return parts_->port.local_port(); }
std::uint64_t ControllerModule::now_ns() const noexcept { return parts_->clock.now_ns(); }
void ControllerModule::set_time_ns(std::uint64_t now_ns) noexcept { parts_->clock.set(now_ns); }
int ControllerModule::socket_fd() const noexcept { return parts_->port.socket_fd(); }
std::uint64_t ControllerModule::datagrams_received() const noexcept {
  return parts_->port.datagrams_received();
}
std::uint64_t ControllerModule::datagrams_sent() const noexcept {
  return parts_->port.datagrams_sent();
}

void ControllerModule::trace_to(std::ostream& out) {
  trace_ = std::make_unique<CycleTrace>(out, parts_->grid.cell_count());
}

void ControllerModule::service_link(std::uint64_t until_ns) {
  (void)parts_->cycle.service_link(until_ns);
}

namespace {

JointAngles goal_angles(const ControllerConfig& config, std::size_t index) {
  JointAngles goal;
  for (std::size_t j = 0; j < config.task.goals_rad[index].size(); ++j) {
    goal.rad[j] = config.task.goals_rad[index][j];
  }
  return goal;
}

}  // namespace

void ControllerModule::begin(std::uint64_t start_ns) {
  Parts& p = *parts_;
  p.start_ns = start_ns;
  p.last_start_ns = 0;
  p.robot.set_time_ns(start_ns);
  for (double& velocity : p.planned) velocity = 0.0;
  status_ = ModuleStatus{};
  status_.goals = config_.task.goals_rad.size();
  outcome_ = TaskOutcome::kStopped;
  if (status_.goals > 0) (void)p.motion.move_to(goal_angles(config_, 0));
}

bool ControllerModule::cycle(std::uint64_t now) {
  Parts& p = *parts_;
  const auto period_ns = static_cast<std::uint64_t>(config_.timing.period_ms * 1e6);
  if (p.last_start_ns != 0) {
    const double period_ms = static_cast<double>(now - p.last_start_ns) * 1e-6;
    if (period_ms > status_.worst_period_ms) status_.worst_period_ms = period_ms;
    if (now - p.last_start_ns > 2 * period_ns) ++status_.overruns;
  }
  p.last_start_ns = now;
  if (now > p.robot.time_ns()) p.robot.step(static_cast<double>(now - p.robot.time_ns()) * 1e-9);
  robot_joints_ = p.robot.read();
  if (acknowledge_requested_.exchange(false)) {
    p.cycle.acknowledge();
    if (trace_) trace_->acknowledged(now);
  }
  // The safety cycle first, on the deadline, with the velocities planned after the last one:
  // the planner's time (a re-plan can take milliseconds) then never shifts the cycle's start,
  // which the watchdog's window judges.
  const CycleReport& report = p.cycle.run(p.planned, true);
  if (trace_) trace_->record(now, report, p.link, p.store.store());
  const double work_ms = static_cast<double>(p.clock.now_ns() - report.start_ns) * 1e-6;
  if (work_ms > status_.worst_cycle_ms) status_.worst_cycle_ms = work_ms;
  const RobotJoints joints = p.robot.read();
  if (config_.task.motion == TaskMotion::kProgram) {
    p.motion.plan_velocity(joints, p.free_map, 1, now, p.planned);
  } else {
    p.motion.plan_velocity(joints, p.store.store().view(), p.store.store().version(), now,
                           p.planned);
  }
  ++status_.cycles;
  status_.elapsed_s = static_cast<double>(now - p.start_ns) * 1e-9;
  status_.cycle = &report;
  status_.motion = &p.motion.progress();
  status_.stop_requested = p.link.stop_requested();
  status_.stop_cause = status_.stop_requested ? fault_cause_name(p.link.stop_cause()) : "";

  const MotionStatus motion = p.motion.progress().status;
  if (motion == MotionStatus::kArrived && status_.goal < status_.goals) {
    if (++status_.goal == status_.goals && config_.task.repeat) status_.goal = 0;
    if (status_.goal < status_.goals) {
      (void)p.motion.move_to(goal_angles(config_, status_.goal));
    } else {
      outcome_ = TaskOutcome::kCompleted;
      return true;
    }
  } else if (motion == MotionStatus::kFailed) {
    const PlanResult& plan = p.motion.progress().last_plan;
    std::ostringstream detail;
    detail << "goal " << status_.goal + 1 << ": " << to_string(plan.status);
    if (plan.has_blocking_cell) {
      detail << " (blocked at cell " << plan.blocking_cell;
      if (plan.blocked_joint != 0xFF) detail << " along joint " << plan.blocked_joint + 1;
      detail << ", nearest reached cell " << plan.closest_cell << ")";
    }
    status_.detail = detail.str();
    outcome_ = TaskOutcome::kFailed;
    return true;
  }
  if (stop_requested_) {
    outcome_ = TaskOutcome::kStopped;
    return true;
  }
  return false;
}

TaskOutcome ControllerModule::run(double max_duration_s, double status_period_s,
                                  const std::function<void(const ModuleStatus&)>& status) {
  Parts& p = *parts_;
  const auto period_ns = static_cast<std::uint64_t>(config_.timing.period_ms * 1e6);
  const std::uint64_t start = monotonic_ns();
  begin(start);
  std::uint64_t deadline = start;
  std::uint64_t next_status = start;
  for (;;) {
    deadline += period_ns;
    // Until the next cycle: whenever a frame arrives, map work in slices (an update is applied
    // when it comes, not at the next cycle: exposure to applied stays short), up to shortly
    // before the deadline; then the last stretch asleep.
    for (std::uint64_t t = monotonic_ns(); t + period_ns / 8 < deadline; t = monotonic_ns()) {
      if (!p.port.wait_readable(static_cast<int>((deadline - period_ns / 8 - t) / 1000))) break;
      (void)p.cycle.service_link(deadline - period_ns / 8);
    }
    sleep_until(deadline);
    const std::uint64_t now = monotonic_ns();
    // Late by more than half a period (a long re-plan, the host busy): the schedule starts again
    // from now, so that the cycles missed are not run back to back (the watchdog would call that
    // too early; the look-ahead has allowed for the late one through its window).
    if (now > deadline + period_ns / 2) deadline = now;
    bool done = cycle(now);
    if (!done && max_duration_s > 0.0 && status_.elapsed_s >= max_duration_s) {
      outcome_ = TaskOutcome::kTimedOut;
      done = true;
    }
    if (status && (done || now >= next_status)) {
      status(status_);
      if (trace_) trace_->flush();
      next_status = now + static_cast<std::uint64_t>(status_period_s * 1e9);
    }
    if (done) break;
    // The idle time until a quarter period before the next cycle: more map work, in slices.
    (void)p.cycle.service_link(deadline + period_ns - period_ns / 4);
  }
  // Leave the robot held (a controlled stop, power kept); the coprocessor sees the joint stream
  // end and its own watchdog report it.
  p.robot.stop(StopCategory::kCategory2);
  if (trace_) trace_->flush();
  return outcome_;
}

std::string status_line(const ModuleStatus& status) {
  std::ostringstream line;
  line.setf(std::ios::fixed);
  line.precision(1);
  line << status.elapsed_s << " s";
  if (status.cycle == nullptr) return line.str();
  const CycleReport& cycle = *status.cycle;
  line << " | " << to_string(cycle.state);
  line.precision(2);
  line << " | scale " << cycle.speed_scale;
  line << " | map v" << cycle.map_version;
  line.precision(0);
  line << " age " << cycle.map_age_s * 1e3 << " ms";
  if (status.goals > 0) {
    line << " | goal " << (status.goal < status.goals ? status.goal + 1 : status.goals) << "/"
         << status.goals;
  }
  if (status.motion != nullptr) line << " " << to_string(status.motion->status);
  if (cycle.state == CycleState::kFault) {
    line << " | fault: " << to_string(cycle.fault);
    if (cycle.fault == CycleFault::kLink) line << " (" << to_string(cycle.link_block) << ")";
    if (cycle.fault == CycleFault::kWatchdog)
      line << " (" << to_string(cycle.watchdog_fault) << ")";
    if (cycle.fault == CycleFault::kCameraCount) {
      line << " (the maps are fused from " << cycle.camera_count
           << " cameras; safety.min_healthy_cameras must be 1.." << cycle.camera_count << ")";
    }
  } else if (cycle.state == CycleState::kWaiting) {
    line << " | " << to_string(cycle.link_block);
  } else if (cycle.state == CycleState::kSlowed || cycle.state == CycleState::kStopped) {
    line << " | " << to_string(cycle.look_ahead.reason);
    if (cycle.look_ahead.critical_joint != kNoCriticalJoint) {
      line << ", joint " << cycle.look_ahead.critical_joint + 1;
    }
    if (cycle.look_ahead.has_blocking_cell) line << ", cell " << cycle.look_ahead.blocking_cell;
  }
  if (status.stop_requested) {
    line << " | stop requested by the coprocessor (" << status.stop_cause << ")";
  }
  if (status.overruns > 0) line << " | late cycles " << status.overruns;
  line << " | worst cycle " << std::fixed << std::setprecision(3) << status.worst_cycle_ms << " ms";
  return line.str();
}

}  // namespace safecell

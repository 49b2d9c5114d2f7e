#include "safecell/controller/safety_cycle.hpp"

namespace safecell {
namespace {

safecell_v1_ControllerState wire_state(CycleState state) noexcept {
  switch (state) {
    case CycleState::kWaiting:
      return safecell_v1_ControllerState_CONTROLLER_STATE_WAITING;
    case CycleState::kMoving:
      return safecell_v1_ControllerState_CONTROLLER_STATE_MOVING;
    case CycleState::kSlowed:
      return safecell_v1_ControllerState_CONTROLLER_STATE_SLOWED;
    case CycleState::kStopped:
      return safecell_v1_ControllerState_CONTROLLER_STATE_STOPPED;
    case CycleState::kFault:
      return safecell_v1_ControllerState_CONTROLLER_STATE_FAULT;
  }
  return safecell_v1_ControllerState_CONTROLLER_STATE_FAULT;
}

}  // namespace

const char* to_string(CycleState state) noexcept {
  switch (state) {
    case CycleState::kWaiting:
      return "waiting";
    case CycleState::kMoving:
      return "moving";
    case CycleState::kSlowed:
      return "slowed";
    case CycleState::kStopped:
      return "stopped";
    case CycleState::kFault:
      return "fault";
  }
  return "unknown";
}

const char* to_string(CycleFault fault) noexcept {
  switch (fault) {
    case CycleFault::kNone:
      return "none";
    case CycleFault::kLink:
      return "link";
    case CycleFault::kMapRefused:
      return "map hash mismatch";
    case CycleFault::kCameras:
      return "too few healthy cameras";
    case CycleFault::kCameraCount:
      return "min_healthy_cameras above the cell's camera count";
    case CycleFault::kWatchdog:
      return "watchdog";
    case CycleFault::kJoints:
      return "joints unreadable";
  }
  return "unknown";
}

SafetyCycle::SafetyCycle(const CspaceGrid& grid, const SafetyCycleConfig& config, RobotPort& robot,
                         ClockPort& clock, ControllerLink& link, MapStore& store,
                         Watchdog& watchdog) noexcept
    : grid_(grid),
      config_(config),
      robot_(robot),
      clock_(clock),
      link_(link),
      store_(store),
      watchdog_(watchdog),
      look_ahead_(grid, config.look_ahead) {}

const CycleReport& SafetyCycle::run(const double* planned_rad_s, bool command_velocities) noexcept {
  const std::uint64_t now = clock_.now_ns();
  watchdog_.begin_cycle(now);
  report_ = CycleReport{};
  report_.start_ns = now;
  // The look-ahead's t_cycle: the configured period, or the measured one when longer.
  double period_s = config_.look_ahead.control_cycle_s;
  if (last_start_ns_ != 0 && now > last_start_ns_) {
    report_.period_s = static_cast<double>(now - last_start_ns_) * 1e-9;
    if (report_.period_s > period_s) period_s = report_.period_s;
  }
  last_start_ns_ = now;
  look_ahead_.set_control_cycle_s(period_s);

  report_.joints = robot_.read();
  watchdog_.checkpoint(CycleStep::kReadJoints);
  (void)link_.poll(now);  // one slice; service_link() does more between cycles
  watchdog_.checkpoint(CycleStep::kPollLink);

  const CycleFault fault = detect_fault(report_.joints, now);
  if (fault != CycleFault::kNone && latched_ == CycleFault::kNone) latched_ = fault;
  report_.fault = latched_;
  report_.map_version = store_.version();
  report_.healthy_cameras = link_.healthy_cameras();
  report_.camera_count = link_.camera_count();
  const std::uint64_t capture = store_.capture_ns();
  report_.map_age_s =
      capture != 0 && now > capture ? static_cast<double>(now - capture) * 1e-9 : 0.0;
  if (config_.look_ahead_switched_off) {
    report_.look_ahead = LookAheadResult{};
    report_.look_ahead.speed_scale = 1.0;
    report_.look_ahead.reason = LookAheadReason::kSwitchedOff;
  } else if (report_.map_version != 0 && report_.joints.valid) {
    MotionState motion;
    for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
      motion.position.rad[j] = report_.joints.position_rad[j];
      motion.velocity_rad_s[j] = report_.joints.velocity_rad_s[j];
      motion.planned_rad_s[j] = planned_rad_s[j];
    }
    report_.look_ahead = look_ahead_.check(store_.view(), motion, report_.map_age_s);
  }
  watchdog_.checkpoint(CycleStep::kLookAhead);

  command(planned_rad_s, command_velocities);
  watchdog_.checkpoint(CycleStep::kCommand);
  // The budget ends here: the robot has its command. The report below is I/O whose time a host
  // cannot bound (a loopback send runs the receiver's network stack); if it keeps the thread, the
  // next cycle starts late, and the window (max_period, the look-ahead's t_cycle) catches that.
  const std::uint64_t commanded_ns = clock_.now_ns();

  JointSample sample;
  sample.joint_count = report_.joints.joint_count;
  sample.read_time_ns = report_.joints.read_time_ns;
  for (std::uint32_t j = 0; j < sample.joint_count && j < kMaxJoints; ++j) {
    sample.position_rad[j] = report_.joints.position_rad[j];
    sample.velocity_rad_s[j] = report_.joints.velocity_rad_s[j];
  }
  // A slow-down the map's speed limit decided has no joint or cell of the look-ahead behind it.
  const std::uint8_t critical =
      report_.separation_decides ? kNoCriticalJoint : report_.look_ahead.critical_joint;
  MotionReport motion;
  motion.state = wire_state(report_.state);
  motion.speed_scale = report_.speed_scale;
  motion.critical_joint = critical == kNoCriticalJoint ? 0U : critical + 1U;
  motion.has_blocking_cell = !report_.separation_decides && report_.look_ahead.has_blocking_cell;
  motion.blocking_cell = report_.look_ahead.blocking_cell;
  link_.send_joint_state(sample, motion, now);
  watchdog_.checkpoint(CycleStep::kReport);

  const WatchdogFault watchdog_fault = watchdog_.end_cycle(commanded_ns);
  if (watchdog_fault != WatchdogFault::kNone && report_.state != CycleState::kFault) {
    // Found at the cycle's end (an overrun, a broken flow): stop now, not a cycle later.
    if (latched_ == CycleFault::kNone) latched_ = CycleFault::kWatchdog;
    report_.fault = latched_;
    report_.watchdog_fault = watchdog_fault;
    report_.state = CycleState::kFault;
    report_.speed_scale = 0.0;
    report_.stop_category = config_.fault_stop;
    robot_.stop(config_.fault_stop);
  }
  return report_;
}

int SafetyCycle::service_link(std::uint64_t until_ns) noexcept {
  int slices = 0;
  for (std::uint64_t now = clock_.now_ns(); now < until_ns; now = clock_.now_ns()) {
    ++slices;
    if (!link_.poll(now)) break;
  }
  return slices;
}

CycleFault SafetyCycle::detect_fault(const RobotJoints& joints, std::uint64_t now_ns) noexcept {
  if (!joints.valid || joints.joint_count != grid_.joint_count()) return CycleFault::kJoints;
  report_.watchdog_fault = watchdog_.stalled(now_ns);
  if (report_.watchdog_fault != WatchdogFault::kNone) return CycleFault::kWatchdog;
  report_.link_block = link_.block(now_ns);
  if (report_.link_block == LinkBlock::kLatched ||
      report_.link_block == LinkBlock::kStopRequested ||
      report_.link_block == LinkBlock::kMapTooOld) {
    return CycleFault::kLink;
  }
  if (link_.hash_mismatches() != hash_mismatches_seen_) {
    hash_mismatches_seen_ = link_.hash_mismatches();
    return CycleFault::kMapRefused;
  }
  if (store_.version() != 0) {
    // Checked first: a count the cell cannot reach is a configuration fault, not a camera one.
    if (link_.camera_count() < config_.min_healthy_cameras) return CycleFault::kCameraCount;
    if (link_.healthy_cameras() < config_.min_healthy_cameras) return CycleFault::kCameras;
  }
  return CycleFault::kNone;
}

void SafetyCycle::command(const double* planned_rad_s, bool command_velocities) noexcept {
  report_.speed_scale = 0.0;
  if (latched_ != CycleFault::kNone) {
    report_.state = CycleState::kFault;
    report_.stop_category = config_.fault_stop;
    robot_.stop(config_.fault_stop);
    return;
  }
  if (report_.link_block != LinkBlock::kNone || store_.version() == 0) {
    report_.state = CycleState::kWaiting;  // no session or no verified keyframe yet
    report_.stop_category = StopCategory::kCategory2;
    robot_.stop(StopCategory::kCategory2);
    return;
  }
  const LookAheadResult& look_ahead = report_.look_ahead;
  // The held map's limit holds for as long as the map does: a newer map (or none within T_wd, a
  // fault) replaces it. Below the look-ahead's smallest scale it is a stop like the look-ahead's.
  report_.separation_limit = config_.look_ahead_switched_off ? 1.0 : link_.separation_speed_limit();
  report_.separation_decides = report_.separation_limit < look_ahead.speed_scale;
  double scale = look_ahead.speed_scale;
  if (report_.separation_decides) {
    scale = report_.separation_limit < config_.look_ahead.min_speed_scale
                ? 0.0
                : report_.separation_limit;
  }
  if (scale == 0.0) {
    report_.state = CycleState::kStopped;
    report_.stop_category = config_.look_ahead_stop;
    robot_.stop(config_.look_ahead_stop);
    return;
  }
  report_.speed_scale = scale;
  report_.state = scale < 1.0 ? CycleState::kSlowed : CycleState::kMoving;
  if (command_velocities) {
    double velocity[kMaxJoints] = {};
    for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
      velocity[j] = planned_rad_s[j] * scale;
    }
    if (!robot_.command_joint_velocity(velocity, grid_.joint_count())) {
      robot_.command_speed_scale(scale);
    }
  } else {
    robot_.command_speed_scale(scale);
  }
}

void SafetyCycle::acknowledge() noexcept {
  latched_ = CycleFault::kNone;
  hash_mismatches_seen_ = link_.hash_mismatches();
  link_.acknowledge();
  watchdog_.acknowledge();
  last_start_ns_ = 0;
  (void)robot_.restore_power();
}

}  // namespace safecell

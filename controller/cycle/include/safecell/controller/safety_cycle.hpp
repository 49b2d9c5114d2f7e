#pragma once
// One control cycle of the controller core, in this order (each step a watchdog checkpoint):
//
//   read joints   RobotPort::read()
//   poll link     frames in: map updates into the MapStore (one bounded slice of the work,
//                 ControllerLinkConfig::map_work_per_poll), clock echoes, stop requests
//   look-ahead    with the map's measured age and the measured cycle period
//   command       stop (a category per cause), or the speed scale / joint velocities: the
//                 look-ahead's scale, capped by the held map's speed limit (the coprocessor's
//                 protective separation: someone near the robot, ControllerLink)
//   report        the joint state and the held map's version back to the coprocessor
//
// Faults stop the robot (category 1 by default) and latch until acknowledge(): the link's
// (no map update within T_wd, a second detected error within its window, a stop request), a
// whole map update whose hash did not match, fewer healthy cameras than the threshold, joints
// the robot could not read, and the watchdog's (too early, too late, overrun, flow, stalled).
// Before a session is up and a keyframe verified the robot is held (waiting, category 2). A
// look-ahead stop (category 2 by default) is not latched: the robot resumes when the cells ahead
// are free again.
// Between cycles, service_link() uses the idle time for more slices of map work, so a large
// update is in within a few cycles while each cycle stays short.
// Thread context: run() and service_link() from the controller's cycle task, run() at its
// configured rate (one thread: the link's work never runs while a cycle does). Real-time: no
// allocation; a cycle is bounded by one link slice, the look-ahead's box and the report, and
// service_link() ends at most one slice after its deadline.

#include <cstdint>

#include "safecell/controller/clock_port.hpp"
#include "safecell/controller/controller_link.hpp"
#include "safecell/controller/look_ahead.hpp"
#include "safecell/controller/map_store.hpp"
#include "safecell/controller/robot_port.hpp"
#include "safecell/controller/watchdog.hpp"

namespace safecell {

struct SafetyCycleConfig {
  LookAheadConfig look_ahead;             // its control_cycle_s is the configured period
  std::uint32_t min_healthy_cameras = 1;  // the fusion's camera threshold; 1..the cell's cameras
  StopCategory look_ahead_stop = StopCategory::kCategory2;
  StopCategory fault_stop = StopCategory::kCategory1;
  // The closed-loop validation's negative control, never a product setting: the look-ahead is
  // not run and the planned speed goes to the robot (the map's speed limit is not applied
  // either), so that the validation can show that its ground truth finds the contacts the
  // look-ahead prevents. Faults still stop the robot.
  bool look_ahead_switched_off = false;
};

enum class CycleState : std::uint8_t { kWaiting, kMoving, kSlowed, kStopped, kFault };

enum class CycleFault : std::uint8_t {
  kNone = 0,
  kLink,        // CycleReport::link_block says which
  kMapRefused,  // a whole update whose hash did not match
  kCameras,     // fewer healthy cameras than the threshold
  // The cell has fewer cameras than min_healthy_cameras: the configuration can never be met (the
  // controller file was not written for this cell).
  kCameraCount,
  kWatchdog,  // CycleReport::watchdog_fault says which
  kJoints,    // the robot's joints could not be read
};

const char* to_string(CycleState state) noexcept;
const char* to_string(CycleFault fault) noexcept;

struct CycleReport {
  CycleState state = CycleState::kWaiting;
  CycleFault fault = CycleFault::kNone;  // the latched fault, the first one since acknowledge()
  LinkBlock link_block = LinkBlock::kNone;
  WatchdogFault watchdog_fault = WatchdogFault::kNone;
  double speed_scale = 0.0;
  // The held map's speed limit (1: none) and whether it, not the look-ahead, set the speed scale
  // (a slow-down or stop for someone within the protective separation distance).
  double separation_limit = 1.0;
  bool separation_decides = false;
  StopCategory stop_category = StopCategory::kCategory2;  // when stopped, waiting or faulted
  LookAheadResult look_ahead;
  std::uint64_t map_version = 0;
  double map_age_s = 0.0;
  // The held map's healthy cameras and the cell's camera count (0 without a map).
  std::uint32_t healthy_cameras = 0;
  std::uint32_t camera_count = 0;
  std::uint64_t start_ns = 0;
  double period_s = 0.0;  // measured from the last cycle's start
  RobotJoints joints;
};

class SafetyCycle {
 public:
  SafetyCycle(const CspaceGrid& grid, const SafetyCycleConfig& config, RobotPort& robot,
              ClockPort& clock, ControllerLink& link, MapStore& store, Watchdog& watchdog) noexcept;

  // One cycle. planned_rad_s: the motion's joint velocities at speed scale 1 this cycle (the
  // gross-motion service's, or the robot program's), grid.joint_count() of them. With
  // command_velocities the robot gets planned * scale as joint velocities, else the scale alone.
  const CycleReport& run(const double* planned_rad_s, bool command_velocities) noexcept;

  // Between cycles: further link slices while the link has work and the clock is before
  // until_ns (the next cycle's start less one slice's worst time). Returns the slices run.
  int service_link(std::uint64_t until_ns) noexcept;

  // An operator's acknowledgement: clears the latched faults (link, watchdog, the cycle's own)
  // and restores the robot's power. The next cycle checks everything afresh.
  void acknowledge() noexcept;

  const CycleReport& last() const noexcept { return report_; }

 private:
  CycleFault detect_fault(const RobotJoints& joints, std::uint64_t now_ns) noexcept;
  void command(const double* planned_rad_s, bool command_velocities) noexcept;

  const CspaceGrid& grid_;
  SafetyCycleConfig config_;
  RobotPort& robot_;
  ClockPort& clock_;
  ControllerLink& link_;
  MapStore& store_;
  Watchdog& watchdog_;
  LookAhead look_ahead_;
  CycleReport report_;
  CycleFault latched_ = CycleFault::kNone;
  std::uint64_t hash_mismatches_seen_ = 0;
  std::uint64_t last_start_ns_ = 0;
};

}  // namespace safecell

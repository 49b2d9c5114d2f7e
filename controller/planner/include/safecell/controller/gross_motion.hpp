#pragma once
// The safe gross-motion service (paper §3) that other robot programs use: move_to(goal) plans a
// path of free cells (GridPlanner) and, once per cycle, gives the joint velocities that follow it
// at speed scale 1; the safety cycle scales them by its look-ahead, so every step of the service
// runs under the look-ahead like any other motion.
//
//   local steps  a goal within local_cells cells along every joint is approached in a straight
//                line when every cell of the box between here and there is free (the local
//                planner; no search), until a new map forbids one of them
//
//   re-planning  when the map changes and a cell still ahead on the path became forbidden, or the
//                robot left the path (pushed by a stop, cutting a corner)
//   blocked      no path now: the robot is held where it is (the last safe cell) and the service
//                tries again with every new map; after give_up_s without a path it fails, naming
//                the cell nearest the goal it could reach and the forbidden cell and joint that
//                stopped it
//   arrived      every joint within goal_tolerance_rad of the goal
// Thread context: the controller's cycle (plan_velocity() just before SafetyCycle::run()).
// Real-time: a cycle without a re-plan is O(path look-up); a re-plan is the planner's bound.

#include <cstdint>

#include "safecell/base/status.hpp"
#include "safecell/controller/grid_planner.hpp"
#include "safecell/controller/robot_port.hpp"

namespace safecell {

struct GrossMotionConfig {
  double max_speed_rad_s[kMaxJoints]{};  // per joint, the motion's speed at scale 1
  double accel_rad_s2[kMaxJoints]{};     // used to slow down into the goal
  double goal_tolerance_rad = 0.005;
  // Blocked this long without a path: failed. Longer than a person stands next to the arm: the
  // coprocessor's protective separation forbids the whole map for as long as they do.
  double give_up_s = 30.0;
  std::uint32_t local_cells = 4;  // the local planner's reach (0: always search)
};

enum class MotionStatus : std::uint8_t { kIdle, kMoving, kBlocked, kArrived, kFailed };

const char* to_string(MotionStatus status) noexcept;

struct MotionProgress {
  MotionStatus status = MotionStatus::kIdle;
  PlanResult last_plan;          // why it is blocked or failed, when it is
  std::uint32_t plans = 0;       // plans made for this goal, the first included
  std::uint32_t path_index = 0;  // the robot's cell on the path
  std::uint32_t path_length = 0;
  CellIndex goal_cell = 0;
  bool direct = false;  // on a straight line to the goal (the local planner)
};

class GrossMotion {
 public:
  GrossMotion(const CspaceGrid& grid, GridPlanner& planner,
              const GrossMotionConfig& config) noexcept;

  // A new goal (replaces any other). kOutOfRange for a goal outside the grid, kInvalidArgument
  // for NaN.
  Status move_to(const JointAngles& goal) noexcept;
  void cancel() noexcept;

  // This cycle's joint velocities at speed scale 1 into planned_rad_s (zeros when idle, blocked,
  // arrived or failed). now_ns: the controller's clock (for give_up_s).
  void plan_velocity(const RobotJoints& joints, const MapView& map, std::uint64_t map_version,
                     std::uint64_t now_ns, double* planned_rad_s) noexcept;

  const MotionProgress& progress() const noexcept { return progress_; }

 private:
  bool replan(const MapView& map, CellIndex from, std::uint64_t now_ns) noexcept;
  // The local planner: every cell of the box between the two cells free, within local_cells.
  bool straight_free(const MapView& map, CellIndex from, CellIndex to) const noexcept;
  bool path_ahead_blocked(const MapView& map) const noexcept;
  bool find_on_path(CellIndex cell) noexcept;

  const CspaceGrid& grid_;
  GridPlanner& planner_;
  GrossMotionConfig config_;
  JointAngles goal_{};
  MotionProgress progress_;
  std::uint64_t planned_on_version_ = 0;
  std::uint64_t blocked_since_ns_ = 0;
};

}  // namespace safecell

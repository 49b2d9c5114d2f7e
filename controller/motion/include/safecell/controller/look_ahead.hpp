#pragma once
// The look-ahead of paper §2, once per control cycle: is every cell the robot can reach before it
// could stop free, and how fast may it go?
//
//   current cell    the cell of the measured joints; forbidden -> stop.
//   the box         from the current cell along every moving joint at once, n_j cells in joint
//                   j's direction of travel (a motion of several joints crosses diagonal cells, so
//                   the whole box is checked, not each joint's line of cells). n_j is the relation
//                   (shared/safety) for joint j at its speed, with the map's measured age and
//                   the frame period (what appears just after an exposure shows a period later).
//   free level      L: the largest k such that every cell of the box within k cells of the
//                   current cell (along every moving joint) is free. Joint j has F_j = min(L, n_j)
//                   free cells for sure; past the grid's edge (a joint limit) counts as free.
//   the answer      stop when the relation fails at the measured speed with F_j cells (the robot
//                   could not stop in time if the next cycle asked it to); else the largest speed
//                   scale for which it holds at the planned speed: 1 with room to spare, less as
//                   the free distance shrinks (slow down), 0 below min_speed_scale (stop).
// The critical joint (least slack), the blocking cell (a forbidden cell at the lowest level) and
// the reason come with every answer.
//
// Cost: O(lines of the box along joint 0), each a word search in the map; the box is at most
// (max_cells + 1)^(moving joints) cells. Thread context: the controller's cycle. Real-time: no
// allocation, no recursion, loops bounded by the box and kMaxJoints.

#include <cstdint>

#include "safecell/controller/map_view.hpp"
#include "safecell/controller/stop_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/safety/safety_relation.hpp"

namespace safecell {

struct LookAheadConfig {
  double control_cycle_s = 0.004;  // t_cycle: the measured period; the next check is this far off
  double actuation_s = 0.0;        // from a command to the robot acting on it
  // t_s: the coprocessor's frame period. A person may step into view just after an exposure and
  // shows only in the next frame's map, one period later than the measured age says.
  double sensor_period_s = 1.0 / 30.0;
  double human_speed_m_s = kHumanWalkingSpeed_m_s;
  StopModel stop;
  std::uint32_t max_cells = 24;   // look-ahead cap per joint (more needed: the scale drops)
  double min_speed_scale = 0.02;  // a scale below this is a stop
};

// The joints as read this cycle.
struct MotionState {
  JointAngles position;
  double velocity_rad_s[kMaxJoints]{};  // measured
  // The velocity the motion has at speed scale 1 (its direction of travel); zero for a joint the
  // motion does not move. A robot interface that cannot say gives its joints' maximum speeds
  // towards the motion's goal.
  double planned_rad_s[kMaxJoints]{};
};

enum class LookAheadReason : std::uint8_t {
  kClear,                  // full speed
  kFreeDistanceShrinking,  // slowed: the free cells ahead allow less than the planned speed
  kNoFreeDistance,         // slowed to zero (a controlled stop)
  kRelationViolated,       // the robot could not stop in time from its measured speed
  kCurrentCellForbidden,
  kOutsideGrid,   // the joints lie outside the grid's ranges
  kInvalidInput,  // NaN or infinite joints, a negative or infinite map age
  kSwitchedOff,   // not checked: the closed-loop validation's negative control (never in use)
};

const char* to_string(LookAheadReason reason) noexcept;

struct LookAheadResult {
  double speed_scale = 0.0;  // 0 .. 1; 0 is a stop
  LookAheadReason reason = LookAheadReason::kInvalidInput;
  CellIndex current_cell = 0;
  bool has_blocking_cell = false;
  CellIndex blocking_cell = 0;  // a forbidden cell at the lowest level of the box
  // The joint that decides the response: the one that limits the speed scale when the robot is
  // slowed (or stopped for kNoFreeDistance), else the one of least slack.
  std::uint8_t critical_joint = kNoCriticalJoint;
  // The relation at the measured speed: the joint of least slack and its t_c - (reaction + t_d).
  std::uint8_t least_slack_joint = kNoCriticalJoint;
  double slack_s = 0.0;
  std::uint32_t free_level = 0;              // L (capped at max_cells)
  std::uint32_t box_cells[kMaxJoints]{};     // n_j checked, 0 for still joints
  std::uint32_t needed_cells[kMaxJoints]{};  // the relation's n_j at the measured speed
  std::uint32_t lines_checked = 0;           // box lines searched (for the benchmark)

  bool stop() const noexcept { return speed_scale == 0.0; }
};

class LookAhead {
 public:
  // Precondition (checked): config.stop is valid() for the grid's joints.
  LookAhead(const CspaceGrid& grid, const LookAheadConfig& config) noexcept;

  // map_age_s: the held map's measured age (capture -> now), seconds.
  LookAheadResult check(const MapView& map, const MotionState& motion,
                        double map_age_s) const noexcept;

  const LookAheadConfig& config() const noexcept { return config_; }
  void set_control_cycle_s(double period_s) noexcept { config_.control_cycle_s = period_s; }

 private:
  struct Box {
    std::int8_t direction[kMaxJoints]{};  // -1, 0 (not in the box), +1
    std::uint32_t extent[kMaxJoints]{};   // cells scanned from the current one, within the grid
    bool reaches_edge[kMaxJoints]{};      // the extent stops at the grid's edge
  };
  // The lowest level of a forbidden cell in the box (sets blocking), or UINT32_MAX.
  std::uint32_t lowest_forbidden_level(const MapView& map, const GridCoords& current,
                                       const Box& box, LookAheadResult& result) const noexcept;
  SafetyTiming timing(double map_age_s) const noexcept;

  const CspaceGrid& grid_;
  LookAheadConfig config_;
  JointCellGeometry geometry_[kMaxJoints]{};
};

}  // namespace safecell

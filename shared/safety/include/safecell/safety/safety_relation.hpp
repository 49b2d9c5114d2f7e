#pragma once
// The paper's safety relation t_s + t_p <= t_c - t_d, with every delay of the real system named
// (../shared/SAFETY.md):
//
//   t_s + t_p + t_net + T_wd + t_cycle + t_d <= t_c,   t_c = d / (v_robot + v_human)
//
// d is the look-ahead distance: n free cells ahead along a joint, each cell worth the distance
// the robot's farthest point travels across it (at most m_max). v_robot is that point's speed,
// l_i * joint speed. The relation is quasi-static, as in the paper: it ignores the directions of
// motion and treats each joint on its own; the joint with the least slack is the critical one.
//
// Every function validates its inputs (NaN, negative, infinite) and answers kInvalidArgument
// rather than a meaningless number. Real-time safe: no allocation, at most kMaxJoints iterations.

#include <cstdint>

#include "safecell/base/result.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

// ISO 13855 approach speeds of a human body (and of a hand or arm closer than 0.5 m).
inline constexpr double kHumanWalkingSpeed_m_s = 1.6;
inline constexpr double kHumanReachSpeed_m_s = 2.0;

// Every delay between an obstacle appearing and the robot acting on the controller's answer.
struct ReactionDelays {
  double sensor_period_s = 0.0;  // t_s: an obstacle may appear just after an exposure
  double processing_s = 0.0;     // t_p: frames to forbidden map on the coprocessor
  double network_s = 0.0;        // t_net: map frame on the link until applied in the controller
  double watchdog_s = 0.0;       // T_wd: the robot may run on the last map until the watchdog fires
  double control_cycle_s = 0.0;  // t_cycle: the look-ahead is checked once per control cycle
  // At run time the controller knows how old its map is: data_age_s is the measured age of the
  // held map (exposure -> now), which contains t_s, t_p, t_net and the part of T_wd that has
  // passed, so those are 0 then; the age is measured again every cycle, which covers the rest.
  double data_age_s = 0.0;
  double actuation_s = 0.0;  // from a command (a speed scale, a stop) to the robot acting on it
};

struct SafetyTiming {
  ReactionDelays delays;
  double human_speed_m_s = kHumanWalkingSpeed_m_s;
};

// The cell geometry along one joint, as the relation sees it.
struct JointCellGeometry {
  double l_m = 0.0;             // l_i
  double cell_width_rad = 0.0;  // actual cell width along the joint
  double m_max_m = 0.0;
  bool discretised = true;  // a swept joint never leaves its cell: no look-ahead needed
};

struct JointMotion {
  double speed_rad_s = 0.0;  // magnitude; 0 means the joint stands still
  double stop_time_s = 0.0;  // t_d: time to stop from this speed (worst case: from full speed)
};

JointCellGeometry joint_cell_geometry(const CspaceGrid& grid, std::uint32_t joint);

// Sum of all reaction delays (everything but t_d).
Result<double> total_reaction_s(const ReactionDelays& delays) noexcept;

// Distance the farthest point of the robot needs to cross `cells` cells along the joint:
// cells * min(m_max, l_i * cell width).
Result<double> look_ahead_distance_m(std::uint32_t cells, const JointCellGeometry& cell) noexcept;

// t_c = distance / (robot speed + human speed); +infinity when nothing moves.
Result<double> time_to_collision_s(double distance_m, double robot_speed_m_s,
                                   double human_speed_m_s) noexcept;

// The smallest look-ahead (cells) for which the relation holds at this joint speed; 0 for a joint
// that stands still or is swept (the paper assumes the human does not run into a still robot).
Result<std::uint32_t> min_look_ahead_cells(const JointCellGeometry& cell, const JointMotion& motion,
                                           const SafetyTiming& timing) noexcept;

// The largest joint speed for which the relation holds with `look_ahead_cells` free cells; 0 when
// even a still robot would not be safe, +infinity for a swept joint.
Result<double> max_safe_speed_rad_s(std::uint32_t look_ahead_cells, const JointCellGeometry& cell,
                                    double stop_time_s, const SafetyTiming& timing) noexcept;

inline constexpr std::uint8_t kNoCriticalJoint = 0xFF;

struct CriticalJoint {
  std::uint8_t joint = kNoCriticalJoint;  // kNoCriticalJoint when no discretised joint moves
  double time_to_collision_s = 0.0;
  double slack_s = 0.0;  // t_c - (reaction + t_d); negative means the relation is violated
};

// The moving joint with the least slack, given each joint's free look-ahead in cells.
Result<CriticalJoint> critical_joint(const JointCellGeometry* cells, const JointMotion* motions,
                                     const std::uint32_t* look_ahead_cells,
                                     std::uint32_t joint_count,
                                     const SafetyTiming& timing) noexcept;

}  // namespace safecell

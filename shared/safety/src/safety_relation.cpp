#include "safecell/safety/safety_relation.hpp"

#include "safecell/base/freestanding_math.hpp"

namespace safecell {
namespace {

bool geometry_valid(const JointCellGeometry& cell) noexcept {
  return is_finite_non_negative(cell.l_m) && is_finite(cell.cell_width_rad) &&
         cell.cell_width_rad > 0.0 && is_finite(cell.m_max_m) && cell.m_max_m > 0.0;
}

bool timing_valid(const SafetyTiming& timing) noexcept {
  return total_reaction_s(timing.delays).ok() && is_finite_non_negative(timing.human_speed_m_s);
}

double cell_travel_m(const JointCellGeometry& cell) noexcept {
  const double arc_m = cell.l_m * cell.cell_width_rad;
  return arc_m < cell.m_max_m ? arc_m : cell.m_max_m;
}

}  // namespace

JointCellGeometry joint_cell_geometry(const CspaceGrid& grid, std::uint32_t joint) {
  const JointSpec& spec = grid.joint(joint);
  return JointCellGeometry{spec.l_m, grid.cell_width_rad(joint), grid.m_max_m(), spec.discretised};
}

Result<double> total_reaction_s(const ReactionDelays& delays) noexcept {
  const double parts[] = {delays.sensor_period_s, delays.processing_s,    delays.network_s,
                          delays.watchdog_s,      delays.control_cycle_s, delays.data_age_s,
                          delays.actuation_s};
  double total = 0.0;
  for (const double part : parts) {
    if (!is_finite_non_negative(part)) return Status::kInvalidArgument;
    total += part;
  }
  return total;
}

Result<double> look_ahead_distance_m(std::uint32_t cells, const JointCellGeometry& cell) noexcept {
  if (!geometry_valid(cell)) return Status::kInvalidArgument;
  return static_cast<double>(cells) * cell_travel_m(cell);
}

Result<double> time_to_collision_s(double distance_m, double robot_speed_m_s,
                                   double human_speed_m_s) noexcept {
  if (!is_finite_non_negative(distance_m) || !is_finite_non_negative(robot_speed_m_s) ||
      !is_finite_non_negative(human_speed_m_s)) {
    return Status::kInvalidArgument;
  }
  const double closing_speed_m_s = robot_speed_m_s + human_speed_m_s;
  if (closing_speed_m_s == 0.0) return infinity();
  return distance_m / closing_speed_m_s;
}

Result<std::uint32_t> min_look_ahead_cells(const JointCellGeometry& cell, const JointMotion& motion,
                                           const SafetyTiming& timing) noexcept {
  if (!geometry_valid(cell) || !timing_valid(timing) ||
      !is_finite_non_negative(motion.speed_rad_s) || !is_finite_non_negative(motion.stop_time_s)) {
    return Status::kInvalidArgument;
  }
  if (!cell.discretised || motion.speed_rad_s == 0.0) return 0u;
  const double budget_s = total_reaction_s(timing.delays).value() + motion.stop_time_s;
  const double closing_speed_m_s = motion.speed_rad_s * cell.l_m + timing.human_speed_m_s;
  const double cells = closing_speed_m_s * budget_s / cell_travel_m(cell);
  if (!(cells <= 4294967295.0)) return Status::kOverflow;
  return static_cast<std::uint32_t>(ceil_to_u64(cells));
}

Result<double> max_safe_speed_rad_s(std::uint32_t look_ahead_cells, const JointCellGeometry& cell,
                                    double stop_time_s, const SafetyTiming& timing) noexcept {
  if (!geometry_valid(cell) || !timing_valid(timing) || !is_finite_non_negative(stop_time_s)) {
    return Status::kInvalidArgument;
  }
  if (!cell.discretised) return infinity();
  const double budget_s = total_reaction_s(timing.delays).value() + stop_time_s;
  const double distance_m = static_cast<double>(look_ahead_cells) * cell_travel_m(cell);
  if (budget_s == 0.0 || cell.l_m == 0.0) return infinity();
  // (v l + v_h) * budget <= distance, solved for v.
  const double speed_rad_s = (distance_m / budget_s - timing.human_speed_m_s) / cell.l_m;
  return speed_rad_s > 0.0 ? speed_rad_s : 0.0;
}

Result<CriticalJoint> critical_joint(const JointCellGeometry* cells, const JointMotion* motions,
                                     const std::uint32_t* look_ahead_cells,
                                     std::uint32_t joint_count,
                                     const SafetyTiming& timing) noexcept {
  if (cells == nullptr || motions == nullptr || look_ahead_cells == nullptr ||
      joint_count > kMaxJoints || !timing_valid(timing)) {
    return Status::kInvalidArgument;
  }
  const double reaction_s = total_reaction_s(timing.delays).value();
  CriticalJoint critical;
  for (std::uint32_t j = 0; j < joint_count; ++j) {
    const JointMotion& motion = motions[j];
    if (!is_finite_non_negative(motion.speed_rad_s) ||
        !is_finite_non_negative(motion.stop_time_s)) {
      return Status::kInvalidArgument;
    }
    SAFECELL_TRY_ASSIGN(const double distance_m,
                        look_ahead_distance_m(look_ahead_cells[j], cells[j]));
    if (!cells[j].discretised || motion.speed_rad_s == 0.0) continue;
    SAFECELL_TRY_ASSIGN(
        const double t_c_s,
        time_to_collision_s(distance_m, motion.speed_rad_s * cells[j].l_m, timing.human_speed_m_s));
    const double slack_s = t_c_s - (reaction_s + motion.stop_time_s);
    if (critical.joint == kNoCriticalJoint || slack_s < critical.slack_s) {
      critical = CriticalJoint{static_cast<std::uint8_t>(j), t_c_s, slack_s};
    }
  }
  return critical;
}

}  // namespace safecell

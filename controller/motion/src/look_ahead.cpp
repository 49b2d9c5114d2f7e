#include "safecell/controller/look_ahead.hpp"

#include "safecell/base/assert.hpp"
#include "safecell/base/freestanding_math.hpp"

namespace safecell {
namespace {

constexpr std::uint32_t kNoLevel = 0xFFFFFFFFu;

double magnitude(double value) noexcept { return value < 0.0 ? -value : value; }
std::uint32_t larger(std::uint32_t a, std::uint32_t b) noexcept { return a > b ? a : b; }
std::uint32_t smaller(std::uint32_t a, std::uint32_t b) noexcept { return a < b ? a : b; }

LookAheadResult stopped(LookAheadReason reason) noexcept {
  LookAheadResult result;
  result.reason = reason;
  return result;
}

}  // namespace

const char* to_string(LookAheadReason reason) noexcept {
  switch (reason) {
    case LookAheadReason::kClear:
      return "clear";
    case LookAheadReason::kFreeDistanceShrinking:
      return "free distance shrinking";
    case LookAheadReason::kNoFreeDistance:
      return "no free distance";
    case LookAheadReason::kRelationViolated:
      return "cannot stop in time";
    case LookAheadReason::kCurrentCellForbidden:
      return "current cell forbidden";
    case LookAheadReason::kOutsideGrid:
      return "joints outside the grid";
    case LookAheadReason::kInvalidInput:
      return "invalid joints or map age";
    case LookAheadReason::kSwitchedOff:
      return "look-ahead switched off (test only)";
  }
  return "unknown";
}

LookAhead::LookAhead(const CspaceGrid& grid, const LookAheadConfig& config) noexcept
    : grid_(grid), config_(config) {
  SAFECELL_ASSERT(config.stop.valid() && config.stop.joint_count == grid.joint_count());
  SAFECELL_ASSERT(config.max_cells > 0 && is_finite_non_negative(config.control_cycle_s) &&
                  is_finite_non_negative(config.actuation_s) &&
                  is_finite_non_negative(config.sensor_period_s) &&
                  is_finite_non_negative(config.human_speed_m_s));
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j)
    geometry_[j] = joint_cell_geometry(grid, j);
}

SafetyTiming LookAhead::timing(double map_age_s) const noexcept {
  SafetyTiming timing;
  timing.delays.control_cycle_s = config_.control_cycle_s;
  timing.delays.actuation_s = config_.actuation_s;
  timing.delays.data_age_s = map_age_s;
  timing.delays.sensor_period_s = config_.sensor_period_s;
  timing.human_speed_m_s = config_.human_speed_m_s;
  return timing;
}

LookAheadResult LookAhead::check(const MapView& map, const MotionState& motion,
                                 double map_age_s) const noexcept {
  const std::uint32_t joints = grid_.joint_count();
  if (!is_finite_non_negative(map_age_s)) return stopped(LookAheadReason::kInvalidInput);
  for (std::uint32_t j = 0; j < joints; ++j) {
    if (!is_finite(motion.velocity_rad_s[j]) || !is_finite(motion.planned_rad_s[j])) {
      return stopped(LookAheadReason::kInvalidInput);
    }
  }
  const Result<GridCoords> coords = grid_.coords_containing(motion.position);
  if (!coords.ok()) {
    return stopped(coords.error() == Status::kOutOfRange ? LookAheadReason::kOutsideGrid
                                                         : LookAheadReason::kInvalidInput);
  }
  const GridCoords& current = coords.value();
  LookAheadResult result;
  result.current_cell = grid_.index_of(current).value();
  if (map.forbidden(result.current_cell)) {
    result.reason = LookAheadReason::kCurrentCellForbidden;
    result.has_blocking_cell = true;
    result.blocking_cell = result.current_cell;
    return result;
  }
  const SafetyTiming timing = this->timing(map_age_s);

  // The box: every discretised joint that moves or is planned to, as far as the relation asks at
  // the larger of its measured and planned speeds.
  Box box;
  for (std::uint32_t j = 0; j < joints; ++j) {
    const double planned = motion.planned_rad_s[j];
    const double measured = motion.velocity_rad_s[j];
    const double direction = planned != 0.0 ? planned : measured;
    if (!geometry_[j].discretised || direction == 0.0) continue;
    const double speed =
        magnitude(planned) > magnitude(measured) ? magnitude(planned) : magnitude(measured);
    const JointMotion joint_motion{speed, config_.stop.stop_time_s(j, speed)};
    const Result<std::uint32_t> cells = min_look_ahead_cells(geometry_[j], joint_motion, timing);
    const std::uint32_t wanted =
        cells.ok() ? smaller(cells.value(), config_.max_cells) : config_.max_cells;
    box.direction[j] = direction > 0.0 ? 1 : -1;
    const std::uint32_t room =
        box.direction[j] > 0 ? grid_.cells_along(j) - 1 - current.along[j] : current.along[j];
    box.extent[j] = smaller(wanted < 1 ? 1 : wanted, room);
    box.reaches_edge[j] = box.extent[j] == room;
    result.box_cells[j] = box.extent[j];
  }
  const std::uint32_t lowest = lowest_forbidden_level(map, current, box, result);
  const std::uint32_t free_level = lowest == kNoLevel ? kNoLevel : lowest - 1;
  result.free_level = smaller(free_level, config_.max_cells);

  // F_j: the free cells joint j has for sure (the box within the free level is free). A side that
  // reaches the grid's edge within the free level has every cell the joint could ever use.
  std::uint32_t free_cells[kMaxJoints]{};
  JointMotion measured_motion[kMaxJoints]{};
  for (std::uint32_t j = 0; j < joints; ++j) {
    if (box.direction[j] == 0) continue;
    const bool edge_free = box.reaches_edge[j] && box.extent[j] <= free_level;
    free_cells[j] = edge_free ? config_.max_cells : smaller(free_level, box.extent[j]);
    const double speed = magnitude(motion.velocity_rad_s[j]);
    measured_motion[j] = JointMotion{speed, config_.stop.stop_time_s(j, speed)};
    const Result<std::uint32_t> needed =
        min_look_ahead_cells(geometry_[j], measured_motion[j], timing);
    result.needed_cells[j] = needed.ok() ? needed.value() : kNoLevel;
  }

  // The relation at the measured speed: could the robot still stop in time?
  const Result<CriticalJoint> critical =
      critical_joint(geometry_, measured_motion, free_cells, joints, timing);
  if (!critical.ok()) {
    result.reason = LookAheadReason::kInvalidInput;
    return result;
  }
  result.least_slack_joint = critical.value().joint;
  result.critical_joint = result.least_slack_joint;
  result.slack_s = critical.value().slack_s;
  for (std::uint32_t j = 0; j < joints; ++j) {
    if (box.direction[j] != 0 && result.needed_cells[j] > free_cells[j]) {
      result.reason = LookAheadReason::kRelationViolated;
      return result;
    }
  }

  // The largest speed scale for which the relation holds at the planned speed.
  double scale = 1.0;
  for (std::uint32_t j = 0; j < joints; ++j) {
    const double planned = magnitude(motion.planned_rad_s[j]);
    if (box.direction[j] == 0 || planned == 0.0) continue;
    const Result<double> safe = max_safe_speed_rad_s(free_cells[j], geometry_[j],
                                                     config_.stop.stop_time_s(j, planned), timing);
    const double joint_scale = safe.ok() ? safe.value() / planned : 0.0;
    if (joint_scale < scale) {
      scale = joint_scale;
      result.critical_joint = static_cast<std::uint8_t>(j);
    }
  }
  if (scale < config_.min_speed_scale) {
    result.reason = LookAheadReason::kNoFreeDistance;
    return result;
  }
  result.speed_scale = scale;
  result.reason = scale < 1.0 ? LookAheadReason::kFreeDistanceShrinking : LookAheadReason::kClear;
  return result;
}

std::uint32_t LookAhead::lowest_forbidden_level(const MapView& map, const GridCoords& current,
                                                const Box& box,
                                                LookAheadResult& result) const noexcept {
  const std::uint32_t joints = grid_.joint_count();
  std::uint32_t lowest = kNoLevel;
  std::uint32_t offset[kMaxJoints]{};  // the odometer over joints 1.., cells from the current one
  for (;;) {
    std::uint32_t base_level = 0;
    CellIndex line_start = current.along[0];
    for (std::uint32_t j = 1; j < joints; ++j) {
      base_level = larger(base_level, offset[j]);
      const std::uint32_t along =
          box.direction[j] >= 0 ? current.along[j] + offset[j] : current.along[j] - offset[j];
      line_start += along * grid_.stride(j);
    }
    if (base_level < lowest) {
      // The nearest forbidden cell along joint 0 from this line's start, in joint 0's direction.
      ++result.lines_checked;
      const std::uint32_t extent = box.extent[0];
      CellIndex found = 0;
      bool hit = false;
      if (box.direction[0] >= 0) {
        const CellIndex end = line_start + extent + 1;
        found = map.first_forbidden(line_start, end);
        hit = found != end;
      } else {
        const CellIndex begin = line_start - extent;
        found = map.last_forbidden(begin, line_start + 1);
        hit = found != line_start + 1;
      }
      if (hit) {
        const std::uint32_t along0 = found > line_start ? found - line_start : line_start - found;
        const std::uint32_t level = larger(base_level, along0);
        if (level < lowest) {
          lowest = level;
          result.has_blocking_cell = true;
          result.blocking_cell = found;
        }
      }
    }
    std::uint32_t j = 1;
    while (j < joints && offset[j] == box.extent[j]) offset[j++] = 0;
    if (j >= joints) break;
    ++offset[j];
  }
  return lowest;
}

}  // namespace safecell

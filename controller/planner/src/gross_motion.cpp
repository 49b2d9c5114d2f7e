#include "safecell/controller/gross_motion.hpp"

#include "safecell/base/freestanding_math.hpp"

namespace safecell {
namespace {

double magnitude(double value) noexcept { return value < 0.0 ? -value : value; }

// Cells of the path the robot may skip ahead to (it may cross a cell within one cycle).
constexpr std::uint32_t kSearchAhead = 8;

}  // namespace

const char* to_string(MotionStatus status) noexcept {
  switch (status) {
    case MotionStatus::kIdle:
      return "idle";
    case MotionStatus::kMoving:
      return "moving";
    case MotionStatus::kBlocked:
      return "blocked";
    case MotionStatus::kArrived:
      return "arrived";
    case MotionStatus::kFailed:
      return "failed";
  }
  return "unknown";
}

GrossMotion::GrossMotion(const CspaceGrid& grid, GridPlanner& planner,
                         const GrossMotionConfig& config) noexcept
    : grid_(grid), planner_(planner), config_(config) {}

Status GrossMotion::move_to(const JointAngles& goal) noexcept {
  const Result<CellIndex> cell = grid_.cell_containing(goal);
  if (!cell.ok()) return cell.error();
  goal_ = goal;
  progress_ = MotionProgress{};
  progress_.status = MotionStatus::kMoving;
  progress_.goal_cell = cell.value();
  planned_on_version_ = 0;  // plan with the next cycle's map
  blocked_since_ns_ = 0;
  return Status::kOk;
}

void GrossMotion::cancel() noexcept { progress_.status = MotionStatus::kIdle; }

bool GrossMotion::replan(const MapView& map, CellIndex from, std::uint64_t now_ns) noexcept {
  progress_.last_plan = planner_.plan(map, from, progress_.goal_cell);
  ++progress_.plans;
  if (progress_.last_plan.status == PlanStatus::kFound) {
    progress_.status = MotionStatus::kMoving;
    progress_.path_index = 0;
    progress_.path_length = progress_.last_plan.length;
    blocked_since_ns_ = 0;
    return true;
  }
  progress_.path_length = 0;
  if (blocked_since_ns_ == 0) blocked_since_ns_ = now_ns;
  const bool gave_up =
      now_ns - blocked_since_ns_ > static_cast<std::uint64_t>(config_.give_up_s * 1e9) ||
      progress_.last_plan.status == PlanStatus::kInvalid;
  progress_.status = gave_up ? MotionStatus::kFailed : MotionStatus::kBlocked;
  return false;
}

bool GrossMotion::straight_free(const MapView& map, CellIndex from, CellIndex to) const noexcept {
  const GridCoords a = grid_.coords_of(from).value();
  const GridCoords b = grid_.coords_of(to).value();
  GridCoords lo{};
  GridCoords extent{};
  for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
    lo.along[j] = a.along[j] < b.along[j] ? a.along[j] : b.along[j];
    extent.along[j] = (a.along[j] < b.along[j] ? b.along[j] : a.along[j]) - lo.along[j];
    if (extent.along[j] > config_.local_cells) return false;
  }
  // Every cell of the box, with an odometer over the joints (at most (local_cells + 1)^joints).
  GridCoords offset{};
  for (;;) {
    CellIndex cell = 0;
    for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
      cell += (lo.along[j] + offset.along[j]) * grid_.stride(j);
    }
    if (map.forbidden(cell)) return false;
    std::uint32_t j = 0;
    while (j < grid_.joint_count() && offset.along[j] == extent.along[j]) offset.along[j++] = 0;
    if (j == grid_.joint_count()) return true;
    ++offset.along[j];
  }
}

bool GrossMotion::path_ahead_blocked(const MapView& map) const noexcept {
  for (std::uint32_t k = progress_.path_index + 1; k < progress_.path_length; ++k) {
    if (map.forbidden(planner_.path()[k])) return true;
  }
  return false;
}

bool GrossMotion::find_on_path(CellIndex cell) noexcept {
  const std::uint32_t last = progress_.path_index + kSearchAhead < progress_.path_length
                                 ? progress_.path_index + kSearchAhead
                                 : progress_.path_length - 1;
  for (std::uint32_t k = progress_.path_index; k <= last && progress_.path_length > 0; ++k) {
    if (planner_.path()[k] == cell) {
      progress_.path_index = k;
      return true;
    }
  }
  return false;
}

void GrossMotion::plan_velocity(const RobotJoints& joints, const MapView& map,
                                std::uint64_t map_version, std::uint64_t now_ns,
                                double* planned_rad_s) noexcept {
  for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) planned_rad_s[j] = 0.0;
  const MotionStatus status = progress_.status;
  if (status == MotionStatus::kIdle || status == MotionStatus::kArrived ||
      status == MotionStatus::kFailed || map_version == 0 || !joints.valid) {
    return;
  }
  JointAngles position;
  for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) position.rad[j] = joints.position_rad[j];
  const Result<CellIndex> here = grid_.cell_containing(position);
  if (!here.ok()) return;  // outside the grid: the safety cycle stops the robot

  const bool new_map = map_version != planned_on_version_;
  // The local planner: straight to a near goal while the box between is free.
  if (progress_.direct && new_map && !straight_free(map, here.value(), progress_.goal_cell)) {
    progress_.direct = false;
    progress_.path_length = 0;  // search from here
  }
  if (!progress_.direct && (new_map || progress_.path_length == 0) && config_.local_cells > 0 &&
      straight_free(map, here.value(), progress_.goal_cell)) {
    progress_.direct = true;
    progress_.status = MotionStatus::kMoving;
    blocked_since_ns_ = 0;
  }
  if (!progress_.direct) {
    // Blocked: try again with each new map. Moving: search again when the robot left the path
    // or a new map forbids a cell still ahead on it.
    if (status == MotionStatus::kBlocked && !new_map) return;
    const bool search = status == MotionStatus::kBlocked || progress_.path_length == 0 ||
                        !find_on_path(here.value()) || (new_map && path_ahead_blocked(map));
    planned_on_version_ = map_version;
    if (search && !replan(map, here.value(), now_ns)) return;
  }
  planned_on_version_ = map_version;

  // Towards the next cell's centre on the path, or the goal itself within the goal cell (or on
  // the local planner's straight line).
  const bool in_goal_cell = progress_.direct || progress_.path_index + 1 >= progress_.path_length;
  JointAngles target = goal_;
  if (!in_goal_cell) {
    const GridCoords next = grid_.coords_of(planner_.path()[progress_.path_index + 1]).value();
    const JointAngles centre = grid_.cell_centre(next).value();
    for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
      if (grid_.joint(j).discretised) target.rad[j] = centre.rad[j];
    }
  }
  double offset[kMaxJoints] = {};
  bool arrived = in_goal_cell;
  for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
    offset[j] = target.rad[j] - position.rad[j];
    arrived = arrived && magnitude(offset[j]) <= config_.goal_tolerance_rad;
  }
  if (arrived) {
    progress_.status = MotionStatus::kArrived;
    return;
  }
  // All joints in step: the slowest joint (against its limit) sets the pace; into the goal, no
  // faster than each joint can still brake on the distance left.
  double pace = infinity();
  for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
    const double distance = magnitude(offset[j]);
    if (distance == 0.0) continue;
    double speed = config_.max_speed_rad_s[j];
    if (in_goal_cell && config_.accel_rad_s2[j] > 0.0) {
      const double braking = sqrt_of(2.0 * config_.accel_rad_s2[j] * distance) * 0.5;
      if (braking < speed) speed = braking;
    }
    if (speed / distance < pace) pace = speed / distance;
  }
  if (!is_finite(pace)) return;
  for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) planned_rad_s[j] = offset[j] * pace;
}

}  // namespace safecell

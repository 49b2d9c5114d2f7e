#include "safecell/cell/entry_zones.hpp"

#include <algorithm>

namespace safecell {
namespace {

bool on_x_wall(const EntryConfig& entry) {
  return entry.wall == CellWall::kMinusX || entry.wall == CellWall::kPlusX;
}

// +1 for the +x and +y walls, -1 for the others: which way "out" points.
double outward_sign(const EntryConfig& entry) {
  return entry.wall == CellWall::kPlusX || entry.wall == CellWall::kPlusY ? 1.0 : -1.0;
}

}  // namespace

double separation_distance_m(const SeparationDistanceConfig& separation) {
  return separation.approach_speed_m_s * (separation.response_s + separation.stopping_s) +
         separation.intrusion_m;
}

std::vector<PlacedShape> entry_zone_volumes(const CellConfig& cell) {
  std::vector<PlacedShape> volumes;
  if (!cell.entries) return volumes;
  const double half_x = cell.size_m[0] / 2.0;
  const double half_y = cell.size_m[1] / 2.0;
  const double height = cell.size_m[2];
  const double s = separation_distance_m(cell.entry_separation);
  for (const EntryConfig& entry : *cell.entries) {
    const bool x_wall = on_x_wall(entry);
    const double half_along = x_wall ? half_y : half_x;
    const double half_across = x_wall ? half_x : half_y;
    const double from = std::max(-half_along, entry.span_m[0] - s);
    const double to = std::min(half_along, entry.span_m[1] + s);
    const double depth = std::min(s, 2.0 * half_across);
    const double across_centre = outward_sign(entry) * (half_across - depth / 2.0);
    const double along_centre = (from + to) / 2.0;
    const Eigen::Vector3d size = x_wall ? Eigen::Vector3d(depth, to - from, height)
                                        : Eigen::Vector3d(to - from, depth, height);
    PlacedShape box{Box{size}, Eigen::Isometry3d::Identity()};
    box.pose.translation() = x_wall ? Eigen::Vector3d(across_centre, along_centre, height / 2.0)
                                    : Eigen::Vector3d(along_centre, across_centre, height / 2.0);
    volumes.push_back(box);
  }
  return volumes;
}

CellModel with_entry_zones_forbidden(const CellModel& cell) {
  CellModel tables = cell;
  for (auto& volume : entry_zone_volumes(cell.config)) tables.obstacles.push_back(volume);
  return tables;
}

Eigen::Vector2d entry_floor_point(const CellConfig& cell, const EntryConfig& entry, double along,
                                  double inward_m) {
  const double at =
      entry.span_m[0] + std::clamp(along, 0.0, 1.0) * (entry.span_m[1] - entry.span_m[0]);
  const double half_across = (on_x_wall(entry) ? cell.size_m[0] : cell.size_m[1]) / 2.0;
  const double across = outward_sign(entry) * (half_across - inward_m);
  return on_x_wall(entry) ? Eigen::Vector2d(across, at) : Eigen::Vector2d(at, across);
}

}  // namespace safecell

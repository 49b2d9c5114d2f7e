#include "safecell/closed_loop/fence_walk.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "safecell/cell/entry_zones.hpp"

namespace safecell {
namespace {

constexpr double kOn_m = 1e-6;  // how near the rectangle a point counts as on it

}  // namespace

InsetRectangle::InsetRectangle(const CellModel& cell)
    : hx(cell.config.size_m[0] / 2.0 - kFenceInset_m),
      hy(cell.config.size_m[1] / 2.0 - kFenceInset_m) {}

Eigen::Vector2d InsetRectangle::point(double along) const {
  if (along < 2.0 * hx) return {-hx + along, -hy};
  if (along < 2.0 * hx + 2.0 * hy) return {hx, -hy + (along - 2.0 * hx)};
  if (along < 4.0 * hx + 2.0 * hy) return {hx - (along - 2.0 * hx - 2.0 * hy), hy};
  return {-hx, hy - (along - 4.0 * hx - 2.0 * hy)};
}

double InsetRectangle::along(const Eigen::Vector2d& p) const {
  const bool inside = std::abs(p.x()) <= hx + kOn_m && std::abs(p.y()) <= hy + kOn_m;
  const bool on_edge =
      std::abs(std::abs(p.x()) - hx) < kOn_m || std::abs(std::abs(p.y()) - hy) < kOn_m;
  if (!(inside && on_edge)) {
    throw std::logic_error("InsetRectangle::along: (" + std::to_string(p.x()) + ", " +
                           std::to_string(p.y()) + ") is not on the rectangle");
  }
  if (std::abs(p.y() + hy) < kOn_m) return p.x() + hx;
  if (std::abs(p.x() - hx) < kOn_m) return 2.0 * hx + (p.y() + hy);
  if (std::abs(p.y() - hy) < kOn_m) return 2.0 * hx + 2.0 * hy + (hx - p.x());
  return 4.0 * hx + 2.0 * hy + (hy - p.y());
}

std::vector<Eigen::Vector2d> InsetRectangle::walk(const Eigen::Vector2d& from,
                                                  const Eigen::Vector2d& to) const {
  const double length = perimeter();
  const double a = along(from);
  const double forward = std::fmod(along(to) - a + length, length);
  const bool ahead = forward <= length / 2.0;
  const double corners[] = {0.0, 2.0 * hx, 2.0 * hx + 2.0 * hy, 4.0 * hx + 2.0 * hy};
  std::vector<std::pair<double, Eigen::Vector2d>> passed;  // (distance walked, corner)
  for (const double corner : corners) {
    const double way =
        ahead ? std::fmod(corner - a + length, length) : std::fmod(a - corner + length, length);
    if (way > 0.0 && way < (ahead ? forward : length - forward)) {
      passed.emplace_back(way, point(corner));
    }
  }
  std::sort(passed.begin(), passed.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Eigen::Vector2d> path;
  path.reserve(passed.size() + 1);
  for (const auto& [way, corner] : passed) path.push_back(corner);
  path.push_back(to);
  return path;
}

Doorway fence_doorway(const CellModel& cell, const EntryConfig& entry, double along) {
  const InsetRectangle rectangle(cell);
  Doorway door{entry_floor_point(cell.config, entry, along, -kOutside_m),
               entry_floor_point(cell.config, entry, along, kFenceInset_m)};
  // Along the wall, keep to the rectangle's extent.
  const bool x_wall = entry.wall == CellWall::kMinusX || entry.wall == CellWall::kPlusX;
  for (Eigen::Vector2d* p : {&door.outside_m, &door.inside_m}) {
    if (x_wall) {
      p->y() = std::clamp(p->y(), -rectangle.hy, rectangle.hy);
    } else {
      p->x() = std::clamp(p->x(), -rectangle.hx, rectangle.hx);
    }
  }
  return door;
}

}  // namespace safecell

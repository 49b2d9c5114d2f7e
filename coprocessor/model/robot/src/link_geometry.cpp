#include "safecell/robot/link_geometry.hpp"

#include <type_traits>
#include <variant>

#include "safecell/geometry/shape_bounds.hpp"

namespace safecell {
namespace {

LinkGeometry geometry_of(const RobotLink& link) {
  LinkGeometry geometry;
  geometry.link = link.name;
  for (const PlacedShape& placed : link.collision) {
    std::visit(
        [&](const auto& shape) {
          using T = std::decay_t<decltype(shape)>;
          if constexpr (std::is_same_v<T, Box>) {
            ++geometry.boxes;
          } else if constexpr (std::is_same_v<T, Sphere>) {
            ++geometry.spheres;
          } else if constexpr (std::is_same_v<T, Cylinder>) {
            ++geometry.cylinders;
          } else if constexpr (std::is_same_v<T, Capsule>) {
            ++geometry.capsules;
          } else {
            ++geometry.meshes;
            geometry.triangles += shape->triangles.size();
          }
        },
        placed.shape);
    for (const Eigen::Vector3d& point : extreme_points(placed)) geometry.bounds_m.extend(point);
  }
  return geometry;
}

void add_count(std::string& text, std::size_t count, const char* one, const char* many) {
  if (count == 0) return;
  text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + (count == 1 ? one : many);
}

}  // namespace

std::vector<LinkGeometry> collision_geometry_of(const RobotModel& robot) {
  std::vector<LinkGeometry> links{geometry_of(robot.base)};
  for (const RobotLink& link : robot.links) links.push_back(geometry_of(link));
  return links;
}

std::string shape_list(const LinkGeometry& geometry) {
  std::string text;
  add_count(text, geometry.meshes, "mesh", "meshes");
  add_count(text, geometry.boxes, "box", "boxes");
  add_count(text, geometry.spheres, "sphere", "spheres");
  add_count(text, geometry.cylinders, "cylinder", "cylinders");
  add_count(text, geometry.capsules, "capsule", "capsules");
  return text.empty() ? "none" : text;
}

}  // namespace safecell

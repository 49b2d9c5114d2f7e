#include "safecell/sim/ground_truth.hpp"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <limits>

#include "fcl_bodies.hpp"
#include "mesh_containment.hpp"

namespace safecell {
namespace {

// GJK stops when an iteration improves the distance by less than this; the pairs with a
// closed-form solution in FCL (sphere with sphere, box, capsule or cylinder; capsule with capsule)
// do not iterate. FCL's own GJK (GST_INDEP) converges to it, libccd's stops near 1e-4 m.
constexpr double kGjkTolerance_m = 1e-9;

// Whether `inner`, whose surface does not cross the surface of the mesh `outer`, lies inside it.
bool mesh_contains(const FclBody& outer, const FclBody& inner) {
  return outer.mesh && outer.object.getAABB().contain(inner.inner_point_m) &&
         mesh_contains_point(*outer.mesh,
                             outer.object.getTransform().inverse() * inner.inner_point_m);
}

bool bodies_collide(const FclBody& a, const FclBody& b) {
  if (!a.object.getAABB().overlap(b.object.getAABB())) return false;
  fcl::CollisionRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;
  fcl::CollisionResultd result;
  fcl::collide(&a.object, &b.object, request, result);
  return result.isCollision() || mesh_contains(a, b) || mesh_contains(b, a);
}

// Only meaningful for bodies that do not collide.
double bodies_distance_m(const FclBody& a, const FclBody& b) {
  fcl::DistanceRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;
  request.distance_tolerance = kGjkTolerance_m;
  fcl::DistanceResultd result;
  fcl::distance(&a.object, &b.object, request, result);
  return std::max(result.min_distance, 0.0);
}

}  // namespace

struct GroundTruth::Impl {
  MeshHierarchyCache cache;  // updated by the const queries
  std::vector<FclBody> obstacles;

  std::vector<FclBody> robot_bodies(const std::vector<PlacedShape>& robot) {
    return make_fcl_bodies(robot, "GroundTruth: robot", cache);
  }

  // The obstacles the robot touches, in ascending order: only the first when `first_only`.
  std::vector<std::size_t> colliding(const std::vector<PlacedShape>& robot, bool first_only) {
    const std::vector<FclBody> parts = robot_bodies(robot);
    std::vector<std::size_t> hits;
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      const bool hit = std::any_of(parts.begin(), parts.end(), [&](const FclBody& part) {
        return bodies_collide(part, obstacles[i]);
      });
      if (!hit) continue;
      hits.push_back(i);
      if (first_only) break;
    }
    return hits;
  }
};

GroundTruth::GroundTruth(const std::vector<PlacedShape>& obstacles)
    : impl_(std::make_unique<Impl>()) {
  impl_->obstacles = make_fcl_bodies(obstacles, "GroundTruth: obstacles", impl_->cache);
}

GroundTruth::~GroundTruth() = default;
GroundTruth::GroundTruth(GroundTruth&&) noexcept = default;
GroundTruth& GroundTruth::operator=(GroundTruth&&) noexcept = default;

std::size_t GroundTruth::obstacle_count() const { return impl_->obstacles.size(); }

bool GroundTruth::collides(const std::vector<PlacedShape>& robot) const {
  return first_colliding_obstacle(robot).has_value();
}

std::optional<std::size_t> GroundTruth::first_colliding_obstacle(
    const std::vector<PlacedShape>& robot) const {
  const std::vector<std::size_t> hits = impl_->colliding(robot, true);
  if (hits.empty()) return std::nullopt;
  return hits.front();
}

std::vector<std::size_t> GroundTruth::colliding_obstacles(
    const std::vector<PlacedShape>& robot) const {
  return impl_->colliding(robot, false);
}

double GroundTruth::min_distance_m(const std::vector<PlacedShape>& robot) const {
  const std::vector<FclBody> robot_bodies = impl_->robot_bodies(robot);
  double closest_m = std::numeric_limits<double>::infinity();
  for (const FclBody& obstacle : impl_->obstacles) {
    for (const FclBody& part : robot_bodies) {
      // The boxes' gap bounds the bodies' distance from below.
      if (part.object.getAABB().distance(obstacle.object.getAABB()) >= closest_m) continue;
      if (bodies_collide(part, obstacle)) return 0.0;
      closest_m = std::min(closest_m, bodies_distance_m(part, obstacle));
    }
  }
  return closest_m;
}

std::size_t GroundTruth::cached_mesh_count() const { return impl_->cache.size(); }

}  // namespace safecell

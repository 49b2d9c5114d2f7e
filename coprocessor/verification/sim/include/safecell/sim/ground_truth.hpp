#pragma once
// The exact collision ground truth of a scene: does the robot, given as placed shapes in the cell
// frame, touch any obstacle (boxes, humans), and how far apart are they? Computed with FCL:
// boxes, spheres, cylinders and capsules exactly as the primitives they are, triangle meshes as
// bounding-volume hierarchies of their triangles. A closed mesh counts as solid: a shape wholly
// inside it collides (checked by ray parity; an open mesh is only its surface).
//
// Built once per scene; the queries are const but not thread-safe (they update the cache of mesh
// hierarchies, which keeps a robot's meshes from being rebuilt on every call): give each thread
// its own GroundTruth.

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "safecell/geometry/shape.hpp"

namespace safecell {

class GroundTruth {
 public:
  // Throws std::invalid_argument when a shape is malformed: a negative or non-finite size, a
  // non-finite pose, a null mesh, or a mesh without triangles or with an index out of range.
  // The robot shapes given to the queries are checked the same way.
  explicit GroundTruth(const std::vector<PlacedShape>& obstacles);
  ~GroundTruth();
  GroundTruth(GroundTruth&&) noexcept;
  GroundTruth& operator=(GroundTruth&&) noexcept;
  GroundTruth(const GroundTruth&) = delete;
  GroundTruth& operator=(const GroundTruth&) = delete;

  std::size_t obstacle_count() const;

  bool collides(const std::vector<PlacedShape>& robot) const;

  // The lowest index of an obstacle that the robot touches; none when it is clear.
  std::optional<std::size_t> first_colliding_obstacle(const std::vector<PlacedShape>& robot) const;
  // Every obstacle the robot touches, in ascending order; empty when it is clear.
  std::vector<std::size_t> colliding_obstacles(const std::vector<PlacedShape>& robot) const;

  // The smallest distance between any robot shape and any obstacle: 0 when they collide,
  // infinity when either set is empty. Exact up to FCL's GJK tolerance (1e-9 m) for primitive
  // pairs without a closed-form solution.
  double min_distance_m(const std::vector<PlacedShape>& robot) const;

  // Meshes whose hierarchies are cached (diagnostic: a mesh is built once per pointer).
  std::size_t cached_mesh_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace safecell

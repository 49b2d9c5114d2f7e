#pragma once
// Placed shapes as FCL collision objects (internal to the sim module). Primitives map to FCL's
// primitives, which share geometry's conventions (full box sizes; cylinders and capsules along
// local z, centred); meshes map to OBBRSS hierarchies, built once per mesh and cached.

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision_object.h>

#include <cstddef>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "safecell/geometry/shape.hpp"

namespace safecell {

using MeshHierarchy = fcl::BVHModel<fcl::OBBRSSd>;

// One placed shape as FCL sees it.
struct FclBody {
  fcl::CollisionObjectd object;
  std::shared_ptr<const TriangleMesh> mesh;  // set for a mesh, which counts as solid if closed
  Eigen::Vector3d inner_point_m;             // a point of the shape, in the cell frame
};

// Hierarchies by mesh address. An entry whose mesh has died is rebuilt when the address is
// reused, and dropped when another mesh is added.
class MeshHierarchyCache {
 public:
  // Checks a mesh (throwing std::invalid_argument that names `field`) and builds its hierarchy
  // on the first call for it only.
  std::shared_ptr<MeshHierarchy> hierarchy_of(const std::shared_ptr<const TriangleMesh>& mesh,
                                              const std::string& field);
  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    std::weak_ptr<const TriangleMesh> mesh;
    std::shared_ptr<MeshHierarchy> hierarchy;
  };
  std::unordered_map<const TriangleMesh*, Entry> entries_;
};

// `name` (such as "robot") names the set in error messages. Throws std::invalid_argument for a
// malformed shape.
std::vector<FclBody> make_fcl_bodies(const std::vector<PlacedShape>& shapes,
                                     const std::string& name, MeshHierarchyCache& cache);

}  // namespace safecell

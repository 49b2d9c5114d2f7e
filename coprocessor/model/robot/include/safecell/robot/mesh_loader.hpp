#pragma once
// Triangle meshes from files (assimp: STL, OBJ, DAE, PLY, ...), in metres after `scale`.

#include <Eigen/Core>
#include <filesystem>
#include <memory>

#include "safecell/geometry/shape.hpp"

namespace safecell {

// Throws RobotError naming the file when it is missing, unreadable or holds no triangles.
std::shared_ptr<const TriangleMesh> load_mesh(
    const std::filesystem::path& path, const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

}  // namespace safecell

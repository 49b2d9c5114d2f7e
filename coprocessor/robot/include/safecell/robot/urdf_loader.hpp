#pragma once
// Loading a robot from a plain URDF file (urdfdom): the chain from the root link to the tool
// link, collision geometry as primitives and meshes (STL and every format assimp reads, paths
// relative to the URDF file). Fixed joints are folded into the links they hang from.

#include <filesystem>
#include <string>

#include "safecell/robot/robot_model.hpp"

namespace safecell {

struct UrdfOptions {
  // The link that ends the chain; empty: the leaf reached through the most movable joints.
  std::string tool_link;
};

// Throws RobotError for files that cannot be read or parsed, unknown joint types, loops, no path
// from the root to the tool link, movable side branches, and missing or unreadable meshes.
RobotModel load_urdf_file(const std::filesystem::path& path, const UrdfOptions& options = {});

// As load_urdf_file() from text; mesh paths are relative to mesh_directory.
RobotModel parse_urdf(const std::string& xml, const std::string& source,
                      const std::filesystem::path& mesh_directory, const UrdfOptions& options = {});

}  // namespace safecell

#pragma once
// Loading a robot from a plain URDF file (urdfdom): the chain from the root link to the tool
// link, collision geometry as primitives and meshes (STL and every format assimp reads, paths
// relative to the URDF file). Fixed joints are folded into the links they hang from.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "safecell/robot/robot_model.hpp"

namespace safecell {

struct UrdfOptions {
  // The link that ends the chain; empty: the leaf reached through the most movable joints.
  std::string tool_link;
  // Shapes (in the named link's frame) for links whose URDF gives no collision geometry. A link
  // that moves must have collision geometry, its own, a fixed link's folded into it, or these.
  std::map<std::string, std::vector<PlacedShape>> collision_stand_ins;
};

// Throws RobotError for files that cannot be read or parsed, anything urdfdom reports as an error,
// elements and attributes it does not read (urdf_xml_check.hpp), shapes of no size, unknown joint
// types, loops, no path from the root to the tool link, movable side branches, missing or
// unreadable meshes, and a moving link with no collision geometry.
RobotModel load_urdf_file(const std::filesystem::path& path, const UrdfOptions& options = {});

// As load_urdf_file() from text; mesh paths are relative to mesh_directory.
RobotModel parse_urdf(const std::string& xml, const std::string& source,
                      const std::filesystem::path& mesh_directory, const UrdfOptions& options = {});

}  // namespace safecell

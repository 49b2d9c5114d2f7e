#include "safecell/robot/mesh_loader.hpp"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>

#include "safecell/robot/robot_error.hpp"

namespace safecell {
namespace {

// assimp's single-precision matrix, widened entry by entry.
Eigen::Matrix4d to_matrix(const aiMatrix4x4& m) {
  Eigen::Matrix4d result;
  for (unsigned row = 0; row < 4; ++row) {
    for (unsigned col = 0; col < 4; ++col) {
      result(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(col)) =
          static_cast<double>(m[row][col]);
    }
  }
  return result;
}

// Appends the triangles of a node and its children, with the node transforms applied.
void collect(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& parent,
             const Eigen::Vector3d& scale, TriangleMesh& out) {
  const Eigen::Matrix4d transform = parent * to_matrix(node.mTransformation);
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const auto first = static_cast<std::uint32_t>(out.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      const Eigen::Vector4d placed =
          transform * Eigen::Vector4d(static_cast<double>(p.x), static_cast<double>(p.y),
                                      static_cast<double>(p.z), 1.0);
      out.vertices.push_back(placed.head<3>().cwiseProduct(scale));
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no surface
      out.triangles.push_back(
          {first + face.mIndices[0], first + face.mIndices[1], first + face.mIndices[2]});
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    collect(scene, *node.mChildren[c], transform, scale, out);
  }
}

}  // namespace

std::shared_ptr<const TriangleMesh> load_mesh(const std::filesystem::path& path,
                                              const Eigen::Vector3d& scale) {
  if (!std::filesystem::is_regular_file(path)) {
    throw RobotError(path.string() + ": mesh file not found");
  }
  Assimp::Importer importer;
  // A mesh's coordinates are its link's frame, whatever the file says is up (the convention of
  // URDF and of the ROS tools that show it): assimp would turn a COLLADA file that says Z_UP about
  // x into its own Y-up, laying a robot's links on their side. Units (COLLADA's <unit meter>) are
  // still applied.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene =
      importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                           aiProcess_SortByPType | aiProcess_FindInvalidData);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw RobotError(path.string() + ": not a readable mesh: " + importer.GetErrorString());
  }
  auto mesh = std::make_shared<TriangleMesh>();
  collect(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), scale, *mesh);
  if (mesh->triangles.empty()) throw RobotError(path.string() + ": mesh holds no triangles");
  for (const Eigen::Vector3d& vertex : mesh->vertices) {
    if (!vertex.allFinite()) throw RobotError(path.string() + ": a vertex is not finite");
  }
  return mesh;
}

}  // namespace safecell

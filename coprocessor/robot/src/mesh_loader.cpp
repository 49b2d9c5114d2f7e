#include "safecell/robot/mesh_loader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>

#include "safecell/robot/robot_error.hpp"

namespace safecell {
namespace {

Eigen::Matrix4d to_matrix(const aiMatrix4x4& m) {
  Eigen::Matrix4d result;
  result << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2,
      m.d3, m.d4;
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
      const Eigen::Vector4d placed = transform * Eigen::Vector4d(p.x, p.y, p.z, 1.0);
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
  const aiScene* scene =
      importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                           aiProcess_SortByPType | aiProcess_FindInvalidData);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw RobotError(path.string() + ": not a readable mesh: " + importer.GetErrorString());
  }
  auto mesh = std::make_shared<TriangleMesh>();
  collect(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), scale, *mesh);
  if (mesh->triangles.empty()) throw RobotError(path.string() + ": mesh holds no triangles");
  return mesh;
}

}  // namespace safecell

// A part written as STL (metres) and as COLLADA (millimetres, Z_UP, as CAD exports and the
// Universal Robots' descriptions have it) must load as the same geometry: the mesh's own
// coordinates, its units applied, nothing turned to another up axis.

#include "safecell/robot/mesh_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>

#include "robot_fixtures.hpp"
#include "safecell/geometry/tessellate.hpp"
#include "safecell/robot/robot_error.hpp"

#include <unistd.h>

namespace safecell {
namespace {

std::filesystem::path scratch(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("safecell-mesh-" + std::to_string(::getpid()) + "-" + name);
}

void write_stl(const TriangleMesh& mesh, const std::filesystem::path& path) {
  std::ofstream out(path);
  out.precision(17);
  out << "solid part\n";
  for (const auto& triangle : mesh.triangles) {
    out << " facet normal 0 0 0\n  outer loop\n";
    for (const std::uint32_t index : triangle) {
      const Eigen::Vector3d& v = mesh.vertices[index];
      out << "   vertex " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    }
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid part\n";
}

// COLLADA 1.4.1 with the coordinates in `unit_m` units and the given up axis.
void write_collada(const TriangleMesh& mesh, double unit_m, const std::string& up_axis,
                   const std::filesystem::path& path) {
  std::ofstream out(path);
  out.precision(17);
  out << R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="unit" meter=")"
      << unit_m << R"("/><up_axis>)" << up_axis << R"(</up_axis></asset>
  <library_geometries><geometry id="part"><mesh>
    <source id="points"><float_array id="xyz" count=")"
      << 3 * mesh.vertices.size() << "\">";
  for (const Eigen::Vector3d& v : mesh.vertices) {
    out << v.x() / unit_m << ' ' << v.y() / unit_m << ' ' << v.z() / unit_m << ' ';
  }
  out << R"(</float_array>
      <technique_common><accessor source="#xyz" count=")"
      << mesh.vertices.size() << R"(" stride="3"><param name="X" type="float"/>
        <param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common>
    </source>
    <vertices id="vertices"><input semantic="POSITION" source="#points"/></vertices>
    <triangles count=")"
      << mesh.triangles.size()
      << R"("><input semantic="VERTEX" source="#vertices" offset="0"/><p>)";
  for (const auto& triangle : mesh.triangles) {
    out << triangle[0] << ' ' << triangle[1] << ' ' << triangle[2] << ' ';
  }
  out << R"(</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="scene"><node id="part_node">
    <instance_geometry url="#part"/></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
}

Eigen::AlignedBox3d bounds_of(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : mesh.vertices) box.extend(v);
  return box;
}

// Every triangle of `a` has a triangle of `b` with the same corners within `tolerance_m`.
void expect_same_geometry(const TriangleMesh& a, const TriangleMesh& b, double tolerance_m) {
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  const Eigen::AlignedBox3d box_a = bounds_of(a);
  const Eigen::AlignedBox3d box_b = bounds_of(b);
  EXPECT_TRUE(box_a.min().isApprox(box_b.min(), tolerance_m) &&
              box_a.max().isApprox(box_b.max(), tolerance_m))
      << "bounds " << box_a.min().transpose() << " .. " << box_a.max().transpose() << " against "
      << box_b.min().transpose() << " .. " << box_b.max().transpose();
  auto corners = [](const TriangleMesh& mesh) {
    std::vector<std::array<double, 9>> all;
    for (const auto& t : mesh.triangles) {
      std::array<double, 9> c{};
      for (std::size_t k = 0; k < 3; ++k) {
        for (Eigen::Index axis = 0; axis < 3; ++axis) {
          c[3 * k + static_cast<std::size_t>(axis)] = mesh.vertices[t[k]][axis];
        }
      }
      all.push_back(c);
    }
    std::sort(all.begin(), all.end());
    return all;
  };
  const auto ca = corners(a);
  const auto cb = corners(b);
  double worst = 0.0;
  for (std::size_t i = 0; i < ca.size(); ++i) {
    for (std::size_t k = 0; k < 9; ++k) worst = std::max(worst, std::abs(ca[i][k] - cb[i][k]));
  }
  EXPECT_LT(worst, tolerance_m);
}

// An upright part: 0.1 x 0.2 m across, 0.6 m tall, standing on z = 0.1.
TriangleMesh upright_part() {
  PlacedShape box{Box{{0.1, 0.2, 0.6}}, Eigen::Isometry3d::Identity()};
  box.pose.translation() = Eigen::Vector3d(0.05, 0.0, 0.4);
  return tessellate(box);
}

TEST(MeshLoader, ColladaInMillimetresWithZUpIsTheSameGeometryAsTheStl) {
  const TriangleMesh part = upright_part();
  const auto stl = scratch("part.stl");
  const auto dae = scratch("part.dae");
  write_stl(part, stl);
  write_collada(part, 0.001, "Z_UP", dae);
  const auto from_stl = load_mesh(stl);
  const auto from_dae = load_mesh(dae);
  expect_same_geometry(*from_stl, *from_dae, 1e-6);
  // The part stands: 0.6 m along z, not laid along y.
  EXPECT_NEAR(bounds_of(*from_dae).sizes().z(), 0.6, 1e-6);
  std::filesystem::remove(stl);
  std::filesystem::remove(dae);
}

TEST(MeshLoader, Rx160ForearmAsColladaIsTheSameGeometryAsItsStl) {
  const auto stl = test::rx160_urdf_path().parent_path() / "meshes/collision/link_3.stl";
  if (!std::filesystem::exists(stl)) GTEST_SKIP() << "no RX160 model";
  const auto from_stl = load_mesh(stl);
  const auto dae = scratch("link_3.dae");
  write_collada(*from_stl, 0.001, "Z_UP", dae);
  expect_same_geometry(*from_stl, *load_mesh(dae), 1e-6);
  std::filesystem::remove(dae);
}

TEST(MeshLoader, AVertexThatIsNotFiniteIsRefused) {
  TriangleMesh part = upright_part();
  part.vertices[0].x() = std::numeric_limits<double>::infinity();
  const auto dae = scratch("infinite.dae");
  write_collada(part, 1.0, "Z_UP", dae);
  EXPECT_THROW(static_cast<void>(load_mesh(dae)), RobotError);
  std::filesystem::remove(dae);
}

}  // namespace
}  // namespace safecell

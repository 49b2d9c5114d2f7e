#include "safecell/geometry/tessellate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// The true support function h(d) = max over the shape of d . p, for a unit direction d.
double true_support(const Shape& shape, const Eigen::Vector3d& d) {
  return std::visit(
      [&d](const auto& s) -> double {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          return (s.size_m / 2.0).dot(d.cwiseAbs());
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return s.radius_m;
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return s.radius_m * std::hypot(d.x(), d.y()) + s.length_m / 2.0 * std::abs(d.z());
        } else if constexpr (std::is_same_v<T, Capsule>) {
          return s.radius_m + s.length_m / 2.0 * std::abs(d.z());
        } else {
          return 0.0;
        }
      },
      shape);
}

double mesh_support(const TriangleMesh& mesh, const Eigen::Vector3d& d) {
  double best = -1e300;
  for (const auto& vertex : mesh.vertices) best = std::max(best, d.dot(vertex));
  return best;
}

// Every edge of a closed surface belongs to exactly two triangles.
bool is_closed(const TriangleMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const auto a = t[static_cast<std::size_t>(k)];
      const auto b = t[static_cast<std::size_t>((k + 1) % 3)];
      if (a == b) return false;
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  }
  for (const auto& [edge, count] : edges) {
    if (count != 2) return false;
  }
  return !edges.empty();
}

const Shape kShapes[] = {Box{{0.4, 0.2, 0.1}}, Sphere{0.3}, Cylinder{0.1, 0.5}, Capsule{0.08, 0.4}};

TEST(Tessellate, MeshesAreClosedSurfaces) {
  for (const auto& shape : kShapes) {
    for (const int segments : {8, 24, 48}) {
      EXPECT_TRUE(is_closed(tessellate(shape, segments)))
          << "shape " << shape.index() << " segments " << segments;
    }
  }
}

// Circumscribed: in every direction the mesh reaches at least as far as the true shape, and
// not much farther.
TEST(Tessellate, EnclosesTheTrueShapeTightly) {
  test::PropertyRun run(2000);
  std::normal_distribution<double> gauss;
  for (const auto& shape : kShapes) {
    const TriangleMesh mesh = tessellate(shape, 24);
    for (int i = 0; i < run.iterations(); ++i) {
      const Eigen::Vector3d d =
          Eigen::Vector3d(gauss(run.rng()), gauss(run.rng()), gauss(run.rng())).normalized();
      const double exact = true_support(shape, d);
      const double meshed = mesh_support(mesh, d);
      ASSERT_GE(meshed, exact - 1e-12)
          << "shape " << shape.index() << " direction " << d.transpose();
      ASSERT_LE(meshed, exact * 1.03 + 1e-12) << "shape " << shape.index();
    }
  }
}

TEST(Tessellate, PlacedShapesMoveWithTheirPose) {
  PlacedShape placed{Sphere{0.1}, Eigen::Isometry3d::Identity()};
  placed.pose.translation() = Eigen::Vector3d(1.0, 2.0, 3.0);
  const TriangleMesh mesh = tessellate(placed);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& vertex : mesh.vertices) centre += vertex;
  centre /= static_cast<double>(mesh.vertices.size());
  EXPECT_NEAR((centre - Eigen::Vector3d(1.0, 2.0, 3.0)).norm(), 0.0, 1e-9);
}

TEST(Tessellate, MeshesPassThrough) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->triangles = {{0, 1, 2}};
  const TriangleMesh copy = tessellate(Shape{std::shared_ptr<const TriangleMesh>(mesh)});
  EXPECT_EQ(copy.vertices, mesh->vertices);
  EXPECT_EQ(copy.triangles, mesh->triangles);
}

}  // namespace
}  // namespace safecell

#include "safecell/geometry/grown_shape.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace safecell {
namespace {

TEST(GrownShape, PrimitivesGrowByTheMarginAllRound) {
  const Eigen::Isometry3d pose(Eigen::Translation3d(1.0, 2.0, 3.0));
  const auto box = std::get<Box>(grown_by({Box{{0.2, 0.4, 0.6}}, pose}, 0.01).shape);
  EXPECT_TRUE(box.size_m.isApprox(Eigen::Vector3d(0.22, 0.42, 0.62)));
  EXPECT_DOUBLE_EQ(std::get<Sphere>(grown_by({Sphere{0.1}, pose}, 0.01).shape).radius_m, 0.11);
  const auto cylinder = std::get<Cylinder>(grown_by({Cylinder{0.1, 0.5}, pose}, 0.01).shape);
  EXPECT_DOUBLE_EQ(cylinder.radius_m, 0.11);
  EXPECT_DOUBLE_EQ(cylinder.length_m, 0.52);
  const auto capsule = std::get<Capsule>(grown_by({Capsule{0.1, 0.5}, pose}, 0.01).shape);
  EXPECT_DOUBLE_EQ(capsule.radius_m, 0.11);
  EXPECT_DOUBLE_EQ(capsule.length_m, 0.5);  // the caps grow with the radius
  EXPECT_TRUE(grown_by({Box{{0.2, 0.4, 0.6}}, pose}, 0.01).pose.isApprox(pose));
}

TEST(GrownShape, MeshVerticesMoveOutFromTheCentroidByTheMargin) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
  mesh->triangles = {{0, 2, 1}, {0, 1, 3}};
  const PlacedShape grown = grown_by({std::shared_ptr<const TriangleMesh>(mesh)}, 0.05);
  const auto& vertices = std::get<std::shared_ptr<const TriangleMesh>>(grown.shape)->vertices;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    EXPECT_NEAR(vertices[v].norm(), 1.05, 1e-12) << "vertex " << v;
  }
  EXPECT_NEAR(mesh->vertices[0].norm(), 1.0, 1e-12) << "the original mesh is left alone";
}

TEST(GrownShape, ANegativeOrNonFiniteMarginIsRefused) {
  EXPECT_THROW((void)grown_by({Sphere{0.1}}, -0.01), std::invalid_argument);
  EXPECT_THROW((void)grown_by({Sphere{0.1}}, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace safecell

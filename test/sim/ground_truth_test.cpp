#include "safecell/sim/ground_truth.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "safecell/geometry/tessellate.hpp"
#include "safecell/sim/human_figure.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

constexpr double kPi = std::numbers::pi;

PlacedShape placed(Shape shape, const Eigen::Vector3d& position_m,
                   const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  PlacedShape result{std::move(shape), Eigen::Isometry3d::Identity()};
  result.pose.translation() = position_m;
  result.pose.linear() = rotation;
  return result;
}

PlacedShape sphere(double radius_m, const Eigen::Vector3d& centre_m) {
  return placed(Sphere{radius_m}, centre_m);
}

Eigen::Matrix3d about_y(double angle_rad) {
  return Eigen::AngleAxisd(angle_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

std::shared_ptr<const TriangleMesh> box_mesh(double edge_m) {
  return std::make_shared<const TriangleMesh>(tessellate(Box{Eigen::Vector3d::Constant(edge_m)}));
}

TEST(GroundTruth, TwoSpheresOneMetreApart) {
  // Centres 1 m apart, radii 0.3 m: 1 - 0.3 - 0.3 = 0.4 m between the surfaces.
  const GroundTruth truth({sphere(0.3, {0.0, 0.0, 0.0})});
  EXPECT_NEAR(truth.min_distance_m({sphere(0.3, {1.0, 0.0, 0.0})}), 0.4, 1e-12);
  EXPECT_FALSE(truth.collides({sphere(0.3, {1.0, 0.0, 0.0})}));
  EXPECT_EQ(truth.first_colliding_obstacle({sphere(0.3, {1.0, 0.0, 0.0})}), std::nullopt);
  // Centres 0.5 m apart: 0.1 m of overlap.
  EXPECT_TRUE(truth.collides({sphere(0.3, {0.0, 0.5, 0.0})}));
  EXPECT_EQ(truth.min_distance_m({sphere(0.3, {0.0, 0.5, 0.0})}), 0.0);
  EXPECT_EQ(truth.first_colliding_obstacle({sphere(0.3, {0.0, 0.5, 0.0})}), 0u);
}

TEST(GroundTruth, BoxAgainstCapsuleSideOnAndEndOn) {
  // A 1 m cube centred at the origin: its faces at +-0.5 m.
  const GroundTruth truth({placed(Box{Eigen::Vector3d(1.0, 1.0, 1.0)}, Eigen::Vector3d::Zero())});
  const Capsule capsule{0.2, 1.0};  // 1.4 m long in all, along its local z
  // Upright beside the +x face: the side reaches x = centre - 0.2.
  EXPECT_TRUE(truth.collides({placed(capsule, {0.699, 0.1, 0.2})}));   // 1 mm into the cube
  EXPECT_FALSE(truth.collides({placed(capsule, {0.701, 0.1, 0.2})}));  // 1 mm clear
  EXPECT_NEAR(truth.min_distance_m({placed(capsule, {0.701, 0.1, 0.2})}), 0.001, 1e-8);
  // Upright above the top face: the lower cap reaches z = centre - 0.5 - 0.2.
  EXPECT_TRUE(truth.collides({placed(capsule, {0.1, -0.2, 1.199})}));
  EXPECT_NEAR(truth.min_distance_m({placed(capsule, {0.1, -0.2, 1.201})}), 0.001, 1e-8);
  // Turned to lie along x, end on to the +x face: the cap reaches x = centre - 0.7;
  // at x = 1.23 it is 0.03 m clear.
  EXPECT_NEAR(truth.min_distance_m({placed(capsule, {1.23, 0.0, 0.0}, about_y(kPi / 2.0))}), 0.03,
              1e-8);
  EXPECT_TRUE(truth.collides({placed(capsule, {1.19, 0.0, 0.0}, about_y(kPi / 2.0))}));
  // Lying along x above the top face: 0.75 - 0.2 - 0.5 = 0.05 m clear.
  EXPECT_NEAR(truth.min_distance_m({placed(capsule, {0.0, 0.0, 0.75}, about_y(kPi / 2.0))}), 0.05,
              1e-8);
}

TEST(GroundTruth, CylinderRunsAlongItsLocalZ) {
  // Radius 0.2 m, 2 m long, turned to lie along x: it spans x = -1..1.
  const GroundTruth truth(
      {placed(Cylinder{0.2, 2.0}, Eigen::Vector3d::Zero(), about_y(kPi / 2.0))});
  EXPECT_NEAR(truth.min_distance_m({sphere(0.1, {0.9, 0.0, 0.5})}), 0.2, 1e-12);  // 0.5-0.2-0.1
  EXPECT_NEAR(truth.min_distance_m({sphere(0.1, {1.5, 0.0, 0.0})}), 0.4, 1e-12);  // 1.5-1.0-0.1
}

TEST(GroundTruth, SphereInsideABoxCollides) {
  const GroundTruth truth({placed(Box{Eigen::Vector3d(2.0, 2.0, 2.0)}, {0.0, 0.0, 1.0})});
  EXPECT_TRUE(truth.collides({sphere(0.1, {0.3, 0.2, 1.1})}));
  EXPECT_EQ(truth.min_distance_m({sphere(0.1, {0.3, 0.2, 1.1})}), 0.0);
}

TEST(GroundTruth, TessellatedBoxMeshAgainstSpheres) {
  // The 1 m cube as 12 triangles, centred at the origin.
  const GroundTruth truth({placed(box_mesh(1.0), Eigen::Vector3d::Zero())});
  // 1.0 - 0.5 - 0.25 = 0.25 m from the +x face.
  EXPECT_NEAR(truth.min_distance_m({sphere(0.25, {1.0, 0.0, 0.0})}), 0.25, 1e-9);
  EXPECT_FALSE(truth.collides({sphere(0.25, {1.0, 0.0, 0.0})}));
  // Nearest the edge (0.5, 0.5, z): sqrt(0.3^2 + 0.3^2) - 0.1 = 0.324264068711929 m.
  EXPECT_NEAR(truth.min_distance_m({sphere(0.1, {0.8, 0.8, 0.0})}), 0.324264068711929, 1e-9);
  // Through the +x face.
  EXPECT_TRUE(truth.collides({sphere(0.25, {0.7, 0.0, 0.0})}));
  EXPECT_EQ(truth.min_distance_m({sphere(0.25, {0.7, 0.0, 0.0})}), 0.0);
  // Wholly inside: no triangle is touched, but the closed mesh is solid.
  EXPECT_TRUE(truth.collides({sphere(0.1, {0.1, 0.05, -0.1})}));
  EXPECT_EQ(truth.min_distance_m({sphere(0.1, {0.1, 0.05, -0.1})}), 0.0);
}

TEST(GroundTruth, RobotMeshAgainstSphere) {
  const GroundTruth truth({sphere(0.25, {3.0, 0.0, 0.0})});
  // The cube moved to x = 2 and turned a quarter about z: its +x face still at x = 2.5.
  const Eigen::Matrix3d quarter =
      Eigen::AngleAxisd(kPi / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_NEAR(truth.min_distance_m({placed(box_mesh(1.0), {2.0, 0.0, 0.0}, quarter)}), 0.25, 1e-9);
  EXPECT_TRUE(truth.collides({placed(box_mesh(1.0), {2.3, 0.0, 0.0}, quarter)}));
}

TEST(GroundTruth, ShapesInsideOthersCollide) {
  // A small mesh inside a large mesh, either way round, and a mesh inside a sphere.
  const GroundTruth big_mesh({placed(box_mesh(2.0), Eigen::Vector3d::Zero())});
  EXPECT_TRUE(big_mesh.collides({placed(box_mesh(0.2), {0.3, -0.4, 0.5})}));
  EXPECT_FALSE(big_mesh.collides({placed(box_mesh(0.2), {1.3, -0.4, 0.5})}));
  const GroundTruth small_mesh({placed(box_mesh(0.2), {0.3, -0.4, 0.5})});
  EXPECT_TRUE(small_mesh.collides({placed(box_mesh(2.0), Eigen::Vector3d::Zero())}));
  const GroundTruth ball({sphere(1.0, Eigen::Vector3d::Zero())});
  EXPECT_TRUE(ball.collides({placed(box_mesh(0.2), {0.1, 0.2, 0.3})}));
}

TEST(GroundTruth, NamesTheFirstObstacleHit) {
  const GroundTruth truth({sphere(0.2, {5.0, 0.0, 0.0}), sphere(0.2, {0.0, 0.0, 0.0}),
                           placed(Box{Eigen::Vector3d(0.2, 0.2, 0.2)}, {0.3, 0.0, 0.0})});
  EXPECT_EQ(truth.obstacle_count(), 3u);
  // A robot of two spheres: the first touches obstacle 2, the second obstacle 1.
  const std::vector<PlacedShape> robot{sphere(0.1, {0.45, 0.0, 0.0}),
                                       sphere(0.1, {0.0, 0.0, 0.25})};
  EXPECT_EQ(truth.first_colliding_obstacle(robot), 1u);
  EXPECT_EQ(truth.first_colliding_obstacle({robot[0]}), 2u);
  // Every obstacle touched, not only the first.
  EXPECT_EQ(truth.colliding_obstacles(robot), (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(truth.colliding_obstacles({robot[1]}), (std::vector<std::size_t>{1}));
  EXPECT_TRUE(truth.colliding_obstacles({sphere(0.1, {0.0, 5.0, 0.0})}).empty());
}

TEST(GroundTruth, AgainstAStandingHuman) {
  HumanPose pose;
  pose.gait_amplitude = 0.0;
  const GroundTruth truth(human_shapes(pose));
  // The head's top is 1.75 m high: a 0.1 m ball centred at 2.35 m is 0.5 m above it.
  EXPECT_NEAR(truth.min_distance_m({sphere(0.1, {0.0, 0.0, 2.35})}), 0.5, 1e-9);
  // A ball inside the head (centre 1.64 m) clears the torso, whose cap ends at 1.53 m.
  EXPECT_EQ(truth.first_colliding_obstacle({sphere(0.05, {0.0, 0.0, 1.64})}),
            static_cast<std::size_t>(HumanPart::kHead));
}

TEST(GroundTruth, EmptySetsAreInfinitelyFarApart) {
  const double infinity = std::numeric_limits<double>::infinity();
  EXPECT_EQ(GroundTruth({}).min_distance_m({sphere(1.0, Eigen::Vector3d::Zero())}), infinity);
  EXPECT_FALSE(GroundTruth({}).collides({sphere(1.0, Eigen::Vector3d::Zero())}));
  EXPECT_EQ(GroundTruth({sphere(1.0, Eigen::Vector3d::Zero())}).min_distance_m({}), infinity);
}

TEST(GroundTruth, BuildsEachMeshHierarchyOnce) {
  const auto obstacle_mesh = box_mesh(1.0);
  const GroundTruth truth({placed(obstacle_mesh, Eigen::Vector3d::Zero())});
  EXPECT_EQ(truth.cached_mesh_count(), 1u);
  const auto link = box_mesh(0.3);
  for (int call = 0; call < 3; ++call) {
    static_cast<void>(truth.min_distance_m({placed(link, {2.0, 0.0, 0.0})}));
  }
  EXPECT_EQ(truth.cached_mesh_count(), 2u);
  // A second mesh adds an entry; once it is gone, the next new mesh replaces it.
  auto other = box_mesh(0.3);
  EXPECT_FALSE(truth.collides({placed(other, {2.0, 0.0, 0.0})}));
  EXPECT_EQ(truth.cached_mesh_count(), 3u);
  other.reset();
  EXPECT_TRUE(truth.collides({placed(box_mesh(0.3), {0.5, 0.0, 0.0})}));
  EXPECT_EQ(truth.cached_mesh_count(), 3u);
}

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(GroundTruth, MalformedShapesAreNamed) {
  EXPECT_EQ(error_of([] {
              static_cast<void>(GroundTruth(
                  {sphere(0.1, Eigen::Vector3d::Zero()), sphere(-0.1, Eigen::Vector3d::Zero())}));
            }),
            "GroundTruth: obstacles[1].radius_m: value -0.1, expected a finite size above 0 m");
  EXPECT_EQ(error_of([] {
              static_cast<void>(GroundTruth(
                  {placed(Box{Eigen::Vector3d(1.0, std::numeric_limits<double>::quiet_NaN(), 1.0)},
                          Eigen::Vector3d::Zero())}));
            }),
            "GroundTruth: obstacles[0].size_m: value nan, expected a finite size above 0 m");
  EXPECT_EQ(error_of([] {
              static_cast<void>(GroundTruth({placed(Capsule{0.1, -1.0}, Eigen::Vector3d::Zero())}));
            }),
            "GroundTruth: obstacles[0].length_m: value -1, expected a finite size of at least 0 m");
  const GroundTruth truth({sphere(0.1, Eigen::Vector3d::Zero())});
  EXPECT_EQ(error_of([&] {
              static_cast<void>(truth.collides(
                  {placed(std::shared_ptr<const TriangleMesh>{}, Eigen::Vector3d::Zero())}));
            }),
            "GroundTruth: robot[0]: null mesh");
  auto broken = std::make_shared<TriangleMesh>(tessellate(Box{Eigen::Vector3d::Ones()}));
  broken->triangles.back()[2] = 8;  // the cube has vertices 0..7
  EXPECT_EQ(error_of([&] {
              static_cast<void>(truth.collides(
                  {placed(std::shared_ptr<const TriangleMesh>(broken), Eigen::Vector3d::Zero())}));
            }),
            "GroundTruth: robot[0]: triangle index 8 beyond the mesh's 8 vertices");
  PlacedShape nowhere = sphere(0.1, Eigen::Vector3d::Zero());
  nowhere.pose.translation().x() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of([&] { static_cast<void>(truth.min_distance_m({nowhere})); }),
            "GroundTruth: robot[0].pose: not finite");
}

// Two random spheres: distance and collision against |c1 - c2| - r1 - r2.
TEST(GroundTruth, SpherePairsMatchTheAnalyticDistance) {
  test::PropertyRun run(2000);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0), radius(0.01, 0.6);
  for (int i = 0; i < run.iterations(); ++i) {
    const Eigen::Vector3d a(coordinate(run.rng()), coordinate(run.rng()), coordinate(run.rng()));
    const Eigen::Vector3d b(coordinate(run.rng()), coordinate(run.rng()), coordinate(run.rng()));
    const double radius_a = radius(run.rng());
    const double radius_b = radius(run.rng());
    const double gap_m = (a - b).norm() - radius_a - radius_b;
    const GroundTruth truth({sphere(radius_a, a)});
    const std::vector<PlacedShape> robot{sphere(radius_b, b)};
    ASSERT_NEAR(truth.min_distance_m(robot), std::max(gap_m, 0.0), 1e-6)
        << "iteration " << i << " gap " << gap_m;
    if (std::abs(gap_m) > 1e-9) {
      ASSERT_EQ(truth.collides(robot), gap_m < 0.0) << "iteration " << i << " gap " << gap_m;
    }
  }
}

// Distance from a point to a box, a capsule or a cylinder in its own frame, by hand.
double point_to_shape_m(const Shape& shape, const Eigen::Vector3d& p) {
  if (const auto* box = std::get_if<Box>(&shape)) {
    const Eigen::Vector3d half = box->size_m / 2.0;
    return (p - p.cwiseMax(-half).cwiseMin(half)).norm();
  }
  if (const auto* capsule = std::get_if<Capsule>(&shape)) {
    const double half = capsule->length_m / 2.0;
    const Eigen::Vector3d on_axis(0.0, 0.0, std::clamp(p.z(), -half, half));
    return std::max((p - on_axis).norm() - capsule->radius_m, 0.0);
  }
  const auto& cylinder = std::get<Cylinder>(shape);
  const double radial_m = std::max(std::hypot(p.x(), p.y()) - cylinder.radius_m, 0.0);
  const double axial_m = std::max(std::abs(p.z()) - cylinder.length_m / 2.0, 0.0);
  return std::hypot(radial_m, axial_m);
}

Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

// A sphere against a randomly placed box, capsule or cylinder: the analytic distance checks the
// mapping of sizes and of the local z axis.
TEST(GroundTruth, SphereAgainstPlacedPrimitivesMatchesTheAnalyticDistance) {
  test::PropertyRun run(1000);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5), size(0.05, 1.0);
  int clear = 0;
  int hit = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    Shape shape;
    switch (run.rng()() % 3) {
      case 0:
        shape = Box{Eigen::Vector3d(size(run.rng()), size(run.rng()), size(run.rng()))};
        break;
      case 1:
        shape = Capsule{size(run.rng()) / 2.0, size(run.rng())};
        break;
      default:
        shape = Cylinder{size(run.rng()) / 2.0, size(run.rng())};
    }
    const Eigen::Vector3d position(coordinate(run.rng()), coordinate(run.rng()), 0.0);
    const PlacedShape obstacle = placed(shape, position, random_rotation(run.rng()));
    // Near the shape, so that about half of the spheres touch it.
    const Eigen::Vector3d centre =
        position +
        0.3 * Eigen::Vector3d(coordinate(run.rng()), coordinate(run.rng()), coordinate(run.rng()));
    const double radius_m = size(run.rng()) / 4.0;
    const double gap_m = point_to_shape_m(shape, obstacle.pose.inverse() * centre) - radius_m;
    const GroundTruth truth({obstacle});
    const std::vector<PlacedShape> robot{sphere(radius_m, centre)};
    if (gap_m > 1e-9) {
      ASSERT_NEAR(truth.min_distance_m(robot), gap_m, 1e-6) << "iteration " << i;
      ASSERT_FALSE(truth.collides(robot)) << "iteration " << i << " gap " << gap_m;
      ++clear;
    } else if (gap_m < -1e-9) {
      ASSERT_TRUE(truth.collides(robot)) << "iteration " << i << " gap " << gap_m;
      ASSERT_EQ(truth.min_distance_m(robot), 0.0) << "iteration " << i;
      ++hit;
    }
  }
  if (run.full_length()) {  // both outcomes are exercised
    EXPECT_GT(clear, run.iterations() / 10);
    EXPECT_GT(hit, run.iterations() / 10);
  }
}

}  // namespace
}  // namespace safecell

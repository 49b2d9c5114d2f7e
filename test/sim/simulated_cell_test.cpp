#include "safecell/sim/simulated_cell.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "safecell/camera/default_cameras.hpp"
#include "safecell/geometry/tessellate.hpp"
#include "safecell/robot/default_robot.hpp"
#include "safecell/robot/kinematics.hpp"

namespace safecell {
namespace {

const std::vector<double> kPose{0.4, 0.5, 0.6, 0.3, 0.8, 0.2};

SimulatedCell default_cell_sim(const SensorSettings& sensor) {
  Eigen::Isometry3d table_pose = Eigen::Isometry3d::Identity();
  table_pose.translation() = Eigen::Vector3d(-1.2, 1.2, 0.4);
  return SimulatedCell(default_robot(), default_cameras(), Eigen::Vector3d(4.0, 4.0, 3.0),
                       {PlacedShape{Box{{0.8, 0.6, 0.8}}, table_pose}}, sensor);
}

SimScene scene_with_human(double x, double y) {
  HumanPose human;
  human.position_m = Eigen::Vector2d(x, y);
  return SimScene{kPose, {human}};
}

double differing_fraction(const cv::Mat& a, const cv::Mat& b, const cv::Mat& where, int by) {
  cv::Mat difference;
  cv::absdiff(a, b, difference);
  const cv::Mat differs = difference > by;
  cv::Mat both;
  cv::bitwise_and(differs, where, both);
  return static_cast<double>(cv::countNonZero(both)) / std::max(1, cv::countNonZero(where));
}

TEST(SimulatedCell, FramesAreDeterministicForASeed) {
  SimulatedCell first = default_cell_sim(SensorSettings{2.0, 0.0, 30.0, 7});
  SimulatedCell second = default_cell_sim(SensorSettings{2.0, 0.0, 30.0, 7});
  const auto a = first.render(scene_with_human(1.5, -1.0), 3, 0.1);
  const auto b = second.render(scene_with_human(1.5, -1.0), 3, 0.1);
  ASSERT_EQ(a.size(), 4u);
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_EQ(cv::norm(a[c], b[c], cv::NORM_INF), 0.0) << "camera " << c;
    EXPECT_EQ(a[c].type(), CV_8UC1);
    EXPECT_EQ(a[c].cols, 704);
    EXPECT_EQ(a[c].rows, 576);
  }
  // Another frame index draws new noise; another seed too.
  EXPECT_GT(cv::norm(a[0], first.render(scene_with_human(1.5, -1.0), 4, 0.1)[0], cv::NORM_INF),
            0.0);
  SimulatedCell other = default_cell_sim(SensorSettings{2.0, 0.0, 30.0, 8});
  EXPECT_GT(cv::norm(a[0], other.render(scene_with_human(1.5, -1.0), 3, 0.1)[0], cv::NORM_INF),
            0.0);
}

TEST(SimulatedCell, NoiseHasTheConfiguredSpread) {
  SimulatedCell sim = default_cell_sim(SensorSettings{2.0, 0.0, 30.0, 1});
  const SimScene scene{kPose, {}};
  cv::Mat a, b;
  sim.render(scene, 1, 0.0)[0].convertTo(a, CV_32F);
  sim.render(scene, 2, 0.0)[0].convertTo(b, CV_32F);
  cv::Scalar mean, stddev;
  cv::meanStdDev(a - b, mean, stddev);
  // The difference of two independent N(0, 2) samples has sigma 2 sqrt(2) = 2.83.
  EXPECT_NEAR(stddev[0], 2.83, 0.3);
  EXPECT_NEAR(mean[0], 0.0, 0.1);
}

// The robot's silhouette in the image is the projection of its geometry.
TEST(SimulatedCell, RobotSilhouetteMatchesTheProjectionOfItsGeometry) {
  SimulatedCell sim = default_cell_sim(SensorSettings{0.0, 0.0, 30.0, 1});
  for (std::size_t c = 0; c < sim.camera_count(); ++c) {
    const cv::Mat rendered = sim.robot_coverage(c, kPose);
    cv::Mat projected = cv::Mat::zeros(rendered.size(), CV_8UC1);
    for (const auto& shape : collision_shapes_at(sim.robot(), kPose)) {
      const TriangleMesh mesh = tessellate(shape, 16);
      for (const auto& triangle : mesh.triangles) {
        std::vector<cv::Point> corners;
        for (const auto index : triangle) {
          const auto pixel = sim.camera(c).project(mesh.vertices[index]);
          ASSERT_TRUE(pixel.has_value());
          // 8 fractional bits: fillConvexPoly rounds sub-pixel corners to the pixel grid.
          corners.emplace_back(static_cast<int>(std::lround(pixel->x() * 256)),
                               static_cast<int>(std::lround(pixel->y() * 256)));
        }
        cv::fillConvexPoly(projected, corners, 255, cv::LINE_8, 8);
      }
    }
    cv::Mat both, either;
    cv::bitwise_and(rendered, projected, both);
    cv::bitwise_or(rendered, projected, either);
    const double overlap = static_cast<double>(cv::countNonZero(both)) / cv::countNonZero(either);
    EXPECT_GT(cv::countNonZero(rendered), 2000) << "camera " << c;
    EXPECT_GT(overlap, 0.95) << "camera " << c;
  }
}

TEST(SimulatedCell, RobotAndHumanStandOutFromTheBackground) {
  SimulatedCell sim = default_cell_sim(SensorSettings{0.0, 0.0, 30.0, 1});
  const SimScene empty_scene{kPose, {}};
  const auto without = sim.render_surfaces({}, 0, 0.0);  // the empty cell
  const auto with_robot = sim.render(empty_scene, 0, 0.0);
  const auto with_human = sim.render(scene_with_human(1.4, -0.9), 0, 0.0);
  for (std::size_t c = 0; c < sim.camera_count(); ++c) {
    const cv::Mat robot = sim.robot_coverage(c, kPose);
    EXPECT_GT(differing_fraction(with_robot[c], without[c], robot, 10), 0.6) << "camera " << c;
    cv::Mat human_only;
    cv::absdiff(with_human[c], with_robot[c], human_only);
    EXPECT_GT(cv::countNonZero(human_only > 10), 1500) << "camera " << c;
  }
}

TEST(SimulatedCell, LightingDriftChangesTheBrightness) {
  SimulatedCell sim = default_cell_sim(SensorSettings{0.0, 0.1, 4.0, 1});
  const SimScene scene{kPose, {}};
  // Gain 1 + 0.1 sin(2 pi t / 4 s): 1.0 at t = 0, 1.1 at t = 1 s.
  const double at_zero = cv::mean(sim.render(scene, 0, 0.0)[1])[0];
  const double at_peak = cv::mean(sim.render(scene, 1, 1.0)[1])[0];
  EXPECT_NEAR(at_peak / at_zero, 1.1, 0.01);
}

}  // namespace
}  // namespace safecell

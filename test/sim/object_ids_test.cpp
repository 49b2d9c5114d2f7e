// The renderer's object-id image: which body a simulated scene shows front-most at each pixel,
// checked against the geometry (the rasteriser's id buffer: rasteriser_test.cpp).

#include <gtest/gtest.h>

#include "safecell/camera/default_cameras.hpp"
#include "safecell/robot/default_robot.hpp"
#include "safecell/sim/body_id.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {
namespace {

TEST(BodyCode, KindAndIndexRoundTrip) {
  for (const BodyKind kind : {BodyKind::kBackground, BodyKind::kRobot, BodyKind::kStaticObstacle,
                              BodyKind::kHuman, BodyKind::kObject}) {
    for (const std::size_t index : {std::size_t{0}, std::size_t{7}, kMaxBodiesPerKind - 1}) {
      const BodyCode code = body_code(kind, index);
      EXPECT_EQ(body_kind(code), kind);
      EXPECT_EQ(body_index(code), index);
    }
  }
  EXPECT_THROW((void)body_code(BodyKind::kHuman, kMaxBodiesPerKind), std::out_of_range);
  EXPECT_EQ(body_name(body_code(BodyKind::kHuman, 1)), "human 2");
  EXPECT_EQ(body_name(body_code(BodyKind::kObject, 0)), "object 1");
}

TEST(ObjectIds, ASimulatedSceneShowsEachBodyWhereItsGeometryIs) {
  Eigen::Isometry3d table_pose = Eigen::Isometry3d::Identity();
  table_pose.translation() = Eigen::Vector3d(-1.2, 1.2, 0.4);
  SimulatedCell sim(default_robot(), default_cameras(), Eigen::Vector3d(4.0, 4.0, 3.0),
                    {PlacedShape{Box{{0.8, 0.6, 0.8}}, table_pose}}, SensorSettings{});
  HumanPose human;
  human.position_m = {1.2, -1.0};
  PlacedShape crate{Box{{0.5, 0.5, 0.5}}, Eigen::Isometry3d::Identity()};
  crate.pose.translation() = Eigen::Vector3d(-1.0, -1.2, 0.25);
  const SimScene scene{{0.4, 0.5, 0.6, 0.3, 0.8, 0.2}, {human}, {crate}};
  std::vector<cv::Mat> ids;
  const auto frames = sim.render(scene, 1, 0.0, &ids);
  ASSERT_EQ(ids.size(), sim.camera_count());
  const auto surfaces = sim.moving_surfaces(scene);
  for (std::size_t c = 0; c < sim.camera_count(); ++c) {
    ASSERT_EQ(ids[c].type(), CV_16UC1);
    ASSERT_EQ(ids[c].size(), frames[c].size());
    // Where a body is front-most, its own coverage holds the pixel; where its projection is (the
    // projected centre of the crate and of the table's top), the body or something nearer shows.
    for (const BodyCode body : {body_code(BodyKind::kRobot), body_code(BodyKind::kHuman, 0),
                                body_code(BodyKind::kObject, 0)}) {
      std::vector<SurfaceMesh> own;
      for (const auto& surface : surfaces) {
        if (surface.body == body) own.push_back(surface);
      }
      const cv::Mat coverage = sim.coverage(c, own);
      const cv::Mat shown = ids[c] == body;
      EXPECT_GT(cv::countNonZero(shown), 0) << body_name(body) << " in camera " << c;
      cv::Mat outside;
      cv::bitwise_and(shown, ~coverage, outside);
      EXPECT_EQ(cv::countNonZero(outside), 0) << body_name(body) << " in camera " << c;
    }
    const auto crate_centre =
        sim.camera(c).project(crate.pose.translation() + Eigen::Vector3d(0, 0, 0.25));
    ASSERT_TRUE(crate_centre.has_value());
    const BodyCode at_crate = ids[c].at<BodyCode>(static_cast<int>(std::lround(crate_centre->y())),
                                                  static_cast<int>(std::lround(crate_centre->x())));
    EXPECT_NE(body_kind(at_crate), BodyKind::kBackground) << "camera " << c;
    const auto table_top =
        sim.camera(c).project(table_pose.translation() + Eigen::Vector3d(0, 0, 0.4));
    ASSERT_TRUE(table_top.has_value());
    EXPECT_EQ(ids[c].at<BodyCode>(static_cast<int>(std::lround(table_top->y())),
                                  static_cast<int>(std::lround(table_top->x()))),
              body_code(BodyKind::kStaticObstacle, 0))
        << "camera " << c;
  }
}

}  // namespace
}  // namespace safecell

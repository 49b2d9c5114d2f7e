// The renderer's object-id image: which body is front-most at each pixel, checked against the
// geometry of hand-built scenes.

#include <gtest/gtest.h>

#include "safecell/camera/default_cameras.hpp"
#include "safecell/robot/default_robot.hpp"
#include "safecell/sim/body_id.hpp"
#include "safecell/sim/rasteriser.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {
namespace {

// A camera at the origin looking along the cell's +x axis, 101 x 101 pixels, 50 px focal length.
CameraIntrinsics small_intrinsics() {
  CameraIntrinsics k;
  k.fx_px = k.fy_px = 50.0;
  k.cx_px = k.cy_px = 50.0;
  k.width_px = k.height_px = 101;
  return k;
}

Eigen::Isometry3d looking_along_x() {
  Eigen::Matrix3d camera_axes;
  camera_axes << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  Eigen::Isometry3d cell_to_camera = Eigen::Isometry3d::Identity();
  cell_to_camera.linear() = camera_axes;
  return cell_to_camera;
}

TriangleMesh facing_square(double x, double half) {
  TriangleMesh mesh;
  mesh.vertices = {{x, -half, -half}, {x, half, -half}, {x, half, half}, {x, -half, half}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

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

TEST(ObjectIds, TheNearerSurfaceOwnsThePixelInEitherDrawingOrder) {
  const BodyCode near = body_code(BodyKind::kHuman, 0);
  const BodyCode far = body_code(BodyKind::kStaticObstacle, 3);
  for (const bool near_first : {false, true}) {
    Rasteriser rasteriser(small_intrinsics(), looking_along_x());
    if (near_first) rasteriser.draw(facing_square(2.0, 0.5), 200, near);
    rasteriser.draw(facing_square(4.0, 4.5), 100, far);
    if (!near_first) rasteriser.draw(facing_square(2.0, 0.5), 200, near);
    // The near square covers pixel centres 38..62 (half size 0.5 m at 2 m: +-12.5 px).
    EXPECT_EQ(rasteriser.ids().at<BodyCode>(50, 50), near);
    EXPECT_EQ(rasteriser.ids().at<BodyCode>(38, 62), near);
    EXPECT_EQ(rasteriser.ids().at<BodyCode>(37, 50), far);
    EXPECT_EQ(rasteriser.ids().at<BodyCode>(50, 5), far);
    rasteriser.clear();
    EXPECT_EQ(cv::countNonZero(rasteriser.ids()), 0) << "cleared to background";
  }
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

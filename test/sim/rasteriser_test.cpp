#include "safecell/sim/rasteriser.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace safecell {
namespace {

// A camera at the origin looking along the cell's +x axis (camera z), 101 x 101 pixels.
CameraIntrinsics small_intrinsics() {
  CameraIntrinsics k;
  k.fx_px = k.fy_px = 50.0;
  k.cx_px = k.cy_px = 50.0;
  k.width_px = k.height_px = 101;
  return k;
}

Eigen::Isometry3d looking_along_x() {
  Eigen::Matrix3d camera_axes;  // rows: camera x (right), y (down), z (forward) in cell terms
  camera_axes << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  Eigen::Isometry3d cell_to_camera = Eigen::Isometry3d::Identity();
  cell_to_camera.linear() = camera_axes;
  return cell_to_camera;
}

// A square facing the camera at distance x, half size h.
TriangleMesh facing_square(double x, double h) {
  TriangleMesh mesh;
  mesh.vertices = {{x, -h, -h}, {x, h, -h}, {x, h, h}, {x, -h, h}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

TEST(Rasteriser, NearerSurfacesHideFartherOnesInEitherOrder) {
  for (const bool near_first : {false, true}) {
    Rasteriser rasteriser(small_intrinsics(), looking_along_x());
    const TriangleMesh near = facing_square(2.0, 0.5), far = facing_square(4.0, 4.5);
    if (near_first) rasteriser.draw(near, 200);
    rasteriser.draw(far, 100);
    if (!near_first) rasteriser.draw(near, 200);
    // Lit at an angle: brightness = albedo (0.45 + 0.55 |n . l|), the same factor for both.
    const auto centre = rasteriser.gray().at<std::uint8_t>(50, 50);
    const auto edge = rasteriser.gray().at<std::uint8_t>(50, 5);
    EXPECT_GT(centre, edge) << "near first: " << near_first;
    EXPECT_NEAR(rasteriser.depth().at<float>(50, 50), 2.0f, 1e-5f);
    EXPECT_NEAR(rasteriser.depth().at<float>(50, 5), 4.0f, 1e-4f);
  }
}

TEST(Rasteriser, SquareCoversItsProjection) {
  Rasteriser rasteriser(small_intrinsics(), looking_along_x());
  // Half size 0.5 m at 2 m: +-0.25 in normalised coordinates = +-12.5 pixels around the centre,
  // so pixel centres 38..62 (25 columns and rows) are inside.
  rasteriser.draw(facing_square(2.0, 0.5), 255);
  const cv::Mat covered = rasteriser.depth() < 1e9f;
  EXPECT_EQ(cv::countNonZero(covered), 25 * 25);
  EXPECT_EQ(covered.at<std::uint8_t>(38, 38), 255);
  EXPECT_EQ(covered.at<std::uint8_t>(37, 50), 0);
}

TEST(Rasteriser, TrianglesReachingBehindTheCameraAreClipped) {
  Rasteriser rasteriser(small_intrinsics(), looking_along_x());
  // A floor-like quad from behind the camera to far ahead, 1 m below it.
  TriangleMesh floor;
  floor.vertices = {{-5, -5, -1}, {20, -5, -1}, {20, 5, -1}, {-5, 5, -1}};
  floor.triangles = {{0, 1, 2}, {0, 2, 3}};
  rasteriser.draw(floor, 120);
  const cv::Mat covered = rasteriser.depth() < 1e9f;
  // The lower half of the image sees the floor, the upper half does not.
  EXPECT_EQ(covered.at<std::uint8_t>(100, 50), 255);
  EXPECT_EQ(covered.at<std::uint8_t>(20, 50), 0);
  // Depth at the bottom row: the ray (1, 0, -1) in normalised terms meets z = -1 at x = 1.
  EXPECT_NEAR(rasteriser.depth().at<float>(100, 50), 1.0f, 1e-4f);
}

TEST(Rasteriser, TheNearerSurfaceOwnsThePixelInTheObjectIdBuffer) {
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

}  // namespace
}  // namespace safecell

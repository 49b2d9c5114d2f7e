#include "safecell/camera/default_cameras.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace safecell {
namespace {

TEST(DefaultCameras, FourCamerasInTheTopCorners) {
  const std::vector<PinholeCamera> cameras = default_cameras();
  ASSERT_EQ(cameras.size(), 4u);
  const Eigen::Vector3d expected[] = {
      {1.95, 1.95, 2.9}, {-1.95, 1.95, 2.9}, {-1.95, -1.95, 2.9}, {1.95, -1.95, 2.9}};
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    const PinholeCamera& camera = cameras[i];
    EXPECT_EQ(camera.name(), "cam" + std::to_string(i));
    EXPECT_LT((camera.position_m() - expected[i]).norm(), 1e-12) << camera.name();
    EXPECT_EQ(camera.intrinsics().width_px, 704);
    EXPECT_EQ(camera.intrinsics().height_px, 576);
    // 75 degrees across 704 px: fx = 352 / tan(37.5 deg) = 458.7335...
    EXPECT_NEAR(camera.intrinsics().fx_px, 352.0 / std::tan(37.5 * std::numbers::pi / 180.0), 1e-9);
    for (std::size_t j = 0; j < i; ++j) {
      EXPECT_GT((camera.position_m() - cameras[j].position_m()).norm(), 1.0);
    }
  }
}

TEST(DefaultCameras, EachSeesTheRobotBaseAndTheSpaceAboveIt) {
  for (const PinholeCamera& camera : default_cameras()) {
    for (const Eigen::Vector3d& point_m :
         {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(0, 0, 0.8)}) {
      const auto pixel = camera.project(point_m);
      ASSERT_TRUE(pixel.has_value()) << camera.name() << " " << point_m.transpose();
      EXPECT_TRUE(camera.in_image(*pixel)) << camera.name() << " " << pixel->transpose();
    }
    // The aim point is the image centre; the base lies below it in the image, 2 m above it.
    const Eigen::Vector2d aim = camera.project({0, 0, 0.8}).value();
    EXPECT_LT((aim - Eigen::Vector2d(351.5, 287.5)).norm(), 1e-9) << camera.name();
    EXPECT_GT(camera.project({0, 0, 0}).value().y(), aim.y());
    EXPECT_LT(camera.project({0, 0, 2}).value().y(), aim.y());
    // The opposite top corner of the cell is out of view.
    const Eigen::Vector3d opposite(-camera.position_m().x(), -camera.position_m().y(), 2.9);
    const auto far = camera.project(opposite);
    EXPECT_TRUE(!far || !camera.in_image(*far)) << camera.name();
  }
}

}  // namespace
}  // namespace safecell

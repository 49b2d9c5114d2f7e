// Model error is applied to the simulated world by exactly the amounts asked, and never to the
// model.

#include "safecell/validation/model_error.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "model_fixture.hpp"

namespace safecell {
namespace {

TEST(ModelError, NoErrorLeavesTheWorldAsTheModel) {
  const CellModel cell = test::coarse_default_cell();
  const CellModel world = world_with_error(cell, ModelError{}, 3);
  for (std::size_t c = 0; c < cell.cameras.size(); ++c) {
    EXPECT_TRUE(world.cameras[c].cell_to_camera().isApprox(cell.cameras[c].cell_to_camera()));
  }
}

TEST(ModelError, CamerasAndRobotChangeByTheBoundsAsked) {
  const CellModel cell = test::coarse_default_cell();
  const CellModel world = world_with_error(cell, kDocumentedTolerances, 3);
  for (std::size_t c = 0; c < cell.cameras.size(); ++c) {
    const PinholeCamera& model = cell.cameras[c];
    const PinholeCamera& real = world.cameras[c];
    const Eigen::AngleAxisd turn(real.camera_to_cell().linear() *
                                 model.camera_to_cell().linear().transpose());
    EXPECT_NEAR(turn.angle() * 180.0 / std::numbers::pi, 0.5, 1e-9) << "camera " << c;
    EXPECT_NEAR((real.position_m() - model.position_m()).norm(), 0.01, 1e-9) << "camera " << c;
    EXPECT_NEAR(std::abs(real.intrinsics().fx_px / model.intrinsics().fx_px - 1.0), 0.01, 1e-12);
    EXPECT_DOUBLE_EQ(real.intrinsics().distortion.k1, -0.02);
  }
  // Every collision shape is 5 mm larger: the radii of the capsules and cylinders.
  const auto radius = [](const PlacedShape& shape) {
    if (const auto* capsule = std::get_if<Capsule>(&shape.shape)) return capsule->radius_m;
    if (const auto* cylinder = std::get_if<Cylinder>(&shape.shape)) return cylinder->radius_m;
    if (const auto* sphere = std::get_if<Sphere>(&shape.shape)) return sphere->radius_m;
    return -1.0;
  };
  int checked = 0;
  for (std::size_t link = 0; link < cell.robot->links.size(); ++link) {
    for (std::size_t s = 0; s < cell.robot->links[link].collision.size(); ++s) {
      const double before = radius(cell.robot->links[link].collision[s]);
      if (before < 0.0) continue;
      EXPECT_NEAR(radius(world.robot->links[link].collision[s]) - before, 0.005, 1e-12);
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

TEST(ModelError, AbsurdOrImpossibleErrorsAreRefused) {
  const CellModel cell = test::coarse_default_cell();
  ModelError error;
  error.camera_rotation_deg = 11.0;
  EXPECT_THROW((void)world_with_error(cell, error, 1), std::invalid_argument);
  error = ModelError{};
  error.robot_growth_m = -0.001;
  EXPECT_THROW((void)world_with_error(cell, error, 1), std::invalid_argument);
  error = ModelError{};
  error.lens_k1 = -0.3;  // folds the 75 deg image over before its corners
  EXPECT_THROW((void)world_with_error(cell, error, 1), std::invalid_argument);
}

}  // namespace
}  // namespace safecell

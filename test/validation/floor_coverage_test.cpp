// Blind spots: a partition that hides a floor region from two of the four cameras makes it blind
// at a camera threshold of 3; the region is reported, and with the blind spots forbidden the
// tables make every cell whose robot reaches a person standing there a static obstacle cell.

#include "safecell/validation/floor_coverage.hpp"

#include <gtest/gtest.h>

#include "model_fixture.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/lut_build/model_luts.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// The default cell with a ceiling beam along x (y = 1.3 m, 2.45 m up): it stands in the way of
// cam0 and cam1 looking at the floor on the far side (around y = -1.4 m), which the robot reaches
// without coming near the beam. (A partition on the floor would stand between the robot and the
// region it hides, so its own cells would hold the blind spots' too.) Whole cells: the static
// obstacle cells, which this test reads, come from the whole cells' envelopes either way, and the
// silhouettes of the default cell's sub-cells would take a minute a build.
CellModel beam_cell(int camera_threshold) {
  CellConfig config = default_cell();
  config.envelope_max_move_m.reset();
  config.obstacles.push_back({"beam", {3.6, 0.3, 0.3}, {0.0, 1.3, 2.45}, 0.0, {}});
  config.camera_threshold = camera_threshold;
  return load_cell_model(config);
}

bool blind_near(const FloorCoverage& coverage, const Eigen::Vector2d& point, double within_m) {
  for (int row = 0; row < coverage.rows; ++row) {
    for (int column = 0; column < coverage.columns; ++column) {
      if (coverage.blind(column, row) &&
          (coverage.position_m(column, row) - point).norm() <= within_m) {
        return true;
      }
    }
  }
  return false;
}

TEST(FloorCoverage, TheDefaultCellHasNoBlindSpot) {
  const CellModel cell = test::coarse_default_cell();
  CoverageOptions options;
  options.step_m = 0.25;
  const FloorCoverage coverage = floor_coverage(cell, make_grid(cell.config), options);
  EXPECT_EQ(coverage.reach_blind_positions(), 0U);
  EXPECT_GT(coverage.reach_positions(), 50U);
  // Nobody stands inside the workbench.
  int no_room = 0;
  for (const int seeing : coverage.cameras_seeing) no_room += seeing < 0 ? 1 : 0;
  EXPECT_GT(no_room, 0);
}

TEST(FloorCoverage, ABeamHidingARegionFromTwoCamerasMakesItBlindAndForbidden) {
  const CellModel cell = beam_cell(3);
  const CspaceGrid grid = make_grid(cell.config);
  CoverageOptions options;
  options.step_m = 0.2;
  const FloorCoverage coverage = floor_coverage(cell, grid, options);
  const Eigen::Vector2d behind(0.0, -1.4);
  EXPECT_TRUE(blind_near(coverage, behind, 0.2)) << "the floor in the beam's shadows";
  EXPECT_FALSE(blind_near(coverage, {0.0, 1.0}, 0.3)) << "the floor under the beam";
  EXPECT_GT(coverage.reach_blind_positions(), 0U);
  // With the threshold at 2 the same region is seen enough (by cam0 and cam3).
  EXPECT_FALSE(blind_near(floor_coverage(beam_cell(2), grid, options), behind, 0.2));

  // Tables with and without the blind spots forbidden: every configuration whose robot touches a
  // person standing in a blind spot is a static obstacle cell with them - and not all without
  // them (the negative control of this test).
  const LutSet forbidding = build_model_luts(with_blind_spots_forbidden(cell, coverage), grid);
  const LutSet allowing = build_model_luts(cell, grid);
  std::vector<PlacedShape> people;
  for (int row = 0; row < coverage.rows; ++row) {
    for (int column = 0; column < coverage.columns; ++column) {
      if (!coverage.blind(column, row)) continue;
      PlacedShape person{Cylinder{0.3, 2.0}, Eigen::Isometry3d::Identity()};
      person.pose.translation() << coverage.position_m(column, row), 1.0;
      people.push_back(person);
    }
  }
  const GroundTruth truth(people);
  test::PropertyRun run(400);
  int touching = 0, static_with = 0, static_without = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    std::vector<double> q(grid.joint_count());
    for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
      q[j] = std::uniform_real_distribution<double>(grid.joint(j).lo_rad,
                                                    grid.joint(j).hi_rad)(run.rng());
    }
    q[0] = std::uniform_real_distribution<double>(-2.2, -0.9)(run.rng());  // towards -y
    if (!truth.collides(collision_shapes_at(*cell.robot, q))) continue;
    ++touching;
    const CellIndex at = test::cell_of(grid, q);
    static_with += forbidding.static_cells.test(at) ? 1 : 0;
    static_without += allowing.static_cells.test(at) ? 1 : 0;
    EXPECT_TRUE(forbidding.static_cells.test(at)) << "q[0] " << q[0] << " q[1] " << q[1];
  }
  EXPECT_EQ(static_with, touching);
  if (run.full_length()) {  // a replay of one draw rarely reaches a blind spot
    EXPECT_GT(touching, 20) << "the sample must reach into the blind spots";
    EXPECT_LT(static_without, touching) << "without the blind spots forbidden they are free";
  }
}

TEST(FloorCoverage, AbsurdOptionsAreRefused) {
  const CellModel cell = test::coarse_default_cell();
  const CspaceGrid grid = make_grid(cell.config);
  CoverageOptions options;
  options.step_m = 0.0;
  EXPECT_THROW((void)floor_coverage(cell, grid, options), std::invalid_argument);
  options = CoverageOptions{};
  options.body_heights_m = {5.0};
  EXPECT_THROW((void)floor_coverage(cell, grid, options), std::invalid_argument);
}

}  // namespace
}  // namespace safecell

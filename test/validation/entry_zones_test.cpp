// Entries: the tables make every configuration whose robot comes within the separation distance
// of an entry's opening a static obstacle cell. The ground truth is FCL's distance from the
// robot to the opening itself (a sheet in the wall's plane), not the zone boxes the tables are
// built from; the negative control is the same cell with its entries left out.

#include "safecell/cell/entry_zones.hpp"

#include <gtest/gtest.h>

#include "model_fixture.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/lut_build/model_luts.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// The entry's opening: a sheet 1 mm thick in the wall's plane, floor to ceiling.
PlacedShape opening_of(const CellConfig& cell, const EntryConfig& entry) {
  const Eigen::Vector2d a = entry_floor_point(cell, entry, 0.0, 0.0);
  const Eigen::Vector2d b = entry_floor_point(cell, entry, 1.0, 0.0);
  const Eigen::Vector2d extent = (b - a).cwiseAbs() + Eigen::Vector2d::Constant(0.001);
  PlacedShape sheet{Box{Eigen::Vector3d(extent.x(), extent.y(), cell.size_m[2])},
                    Eigen::Isometry3d::Identity()};
  sheet.pose.translation() << (a + b) / 2.0, cell.size_m[2] / 2.0;
  return sheet;
}

TEST(EntryZones, SeparationDistanceIsIso13855s) {
  SeparationDistanceConfig separation;
  EXPECT_NEAR(separation_distance_m(separation), 1.6 * (0.1 + 0.3) + 0.2, 1e-12);
  separation.approach_speed_m_s = 2.0;
  separation.intrusion_m = 0.0;
  EXPECT_NEAR(separation_distance_m(separation), 0.8, 1e-12);
}

TEST(EntryZones, OneBoxPerEntryReachingSIntoTheCellAndSPastTheOpening) {
  CellConfig cell = default_cell();
  ASSERT_TRUE(cell.entries.has_value());
  cell.entries->push_back({"gate", CellWall::kPlusY, {1.5, 1.9}, {}});
  const std::vector<PlacedShape> zones = entry_zone_volumes(cell);
  ASSERT_EQ(zones.size(), 2U);
  const double s = separation_distance_m(cell.entry_separation);
  const auto& door = std::get<Box>(zones[0].shape).size_m;
  EXPECT_NEAR(door.x(), s, 1e-12);
  // The door spans y -1.2 .. -0.2; its box -1.2 - s .. -0.2 + s, clipped at the -y wall.
  EXPECT_NEAR(door.y(), -0.2 + s + 2.0, 1e-12);
  EXPECT_NEAR(zones[0].pose.translation().x(), -2.0 + s / 2.0, 1e-12);
  EXPECT_NEAR(zones[0].pose.translation().y(), (-2.0 + -0.2 + s) / 2.0, 1e-12);
  // The gate's box is clipped at the +x wall.
  const auto& gate = std::get<Box>(zones[1].shape).size_m;
  EXPECT_NEAR(gate.x(), 2.0 - (1.5 - s), 1e-12);
  EXPECT_NEAR(gate.y(), s, 1e-12);
  EXPECT_NEAR(zones[1].pose.translation().y(), 2.0 - s / 2.0, 1e-12);
  // The other two walls: a box S deep inside the +x wall, and inside the -y wall.
  cell.entries = {{"hatch", CellWall::kPlusX, {0.0, 0.5}, {}},
                  {"gap", CellWall::kMinusY, {-0.5, 0.5}, {}}};
  const std::vector<PlacedShape> more = entry_zone_volumes(cell);
  ASSERT_EQ(more.size(), 2U);
  EXPECT_NEAR(more[0].pose.translation().x(), 2.0 - s / 2.0, 1e-12);
  EXPECT_NEAR(more[0].pose.translation().y(), 0.25, 1e-12);
  EXPECT_NEAR(std::get<Box>(more[0].shape).size_m.y(), 0.5 + 2.0 * s, 1e-12);
  EXPECT_NEAR(more[1].pose.translation().y(), -2.0 + s / 2.0, 1e-12);
  EXPECT_NEAR(std::get<Box>(more[1].shape).size_m.x(), 1.0 + 2.0 * s, 1e-12);
  EXPECT_NEAR(more[1].pose.translation().z(), 1.5, 1e-12);
  EXPECT_NEAR(std::get<Box>(more[1].shape).size_m.z(), 3.0, 1e-12);
  cell.entries.reset();
  EXPECT_TRUE(entry_zone_volumes(cell).empty());
}

TEST(EntryZones, EntryFloorPointsLieOnTheWallsNormal) {
  const CellConfig cell = default_cell();
  const EntryConfig& door = cell.entries->front();
  EXPECT_TRUE(entry_floor_point(cell, door, 0.5, 0.3).isApprox(Eigen::Vector2d(-1.7, -0.7)));
  EXPECT_TRUE(entry_floor_point(cell, door, 0.0, -0.6).isApprox(Eigen::Vector2d(-2.6, -1.2)));
  const EntryConfig gate{"gate", CellWall::kPlusY, {-1.0, 1.0}, {}};
  EXPECT_TRUE(entry_floor_point(cell, gate, 1.0, 0.5).isApprox(Eigen::Vector2d(1.0, 1.5)));
}

TEST(EntryZones, EveryConfigurationWithinSOfTheDoorIsAStaticObstacleCell) {
  const CellModel cell = test::coarse_default_cell();
  ASSERT_TRUE(cell.config.entries.has_value());
  const CspaceGrid grid = make_grid(cell.config);
  const double s = separation_distance_m(cell.config.entry_separation);
  const LutSet forbidding = build_model_luts(with_entry_zones_forbidden(cell), grid);
  CellModel without = cell;
  without.config.entries.reset();
  const LutSet allowing = build_model_luts(with_entry_zones_forbidden(without), grid);
  const GroundTruth door({opening_of(cell.config, cell.config.entries->front())});
  // About 3.7 % of the draws come within s of the door: 2400 give about 89 (1200 gave 30 or
  // fewer about once in 80 runs, seed 63).
  test::PropertyRun run(2400);
  int near = 0, static_with = 0, static_without = 0, far_free = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    std::vector<double> q(grid.joint_count());
    for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
      q[j] = std::uniform_real_distribution<double>(grid.joint(j).lo_rad,
                                                    grid.joint(j).hi_rad)(run.rng());
    }
    q[0] = std::uniform_real_distribution<double>(grid.joint(0).lo_rad, -2.2)(run.rng());
    const CellIndex at = test::cell_of(grid, q);
    const double distance = door.min_distance_m(collision_shapes_at(*cell.robot, q));
    if (distance >= s) {
      far_free += forbidding.static_cells.test(at) ? 0 : 1;
      continue;
    }
    ++near;
    static_with += forbidding.static_cells.test(at) ? 1 : 0;
    static_without += allowing.static_cells.test(at) ? 1 : 0;
    EXPECT_TRUE(forbidding.static_cells.test(at))
        << "q = [" << q[0] << ", " << q[1] << ", " << q[2] << ", " << q[3] << ", " << q[4] << ", "
        << q[5] << "], " << distance << " m from the door";
  }
  EXPECT_EQ(static_with, near);
  if (run.full_length()) {
    EXPECT_GT(near, 30) << "the sample must reach towards the door";
    EXPECT_GT(far_free, 0) << "the zone must not forbid everything";
    EXPECT_LT(static_without, near / 2) << "without entries named the door's side is free";
  }
}

}  // namespace
}  // namespace safecell

// The vote per robot part (robot_parts.hpp) against the paper's vote over the whole robot, on
// scenes built from the model and the cameras, not from the tables under test:
// - two cameras that each see a small obstacle at a different part of the arm in a cell make the
//   cell critical for the whole-robot vote (the phantom) and not for the vote per part;
// - a point on the forearm's surface, seen by every camera that sees it at all, makes the cell
//   critical for both votes (a real collision is never lost).

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "model_fixture.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"
#include "safecell/geometry/tessellate.hpp"
#include "safecell/robot/kinematics.hpp"

namespace safecell {
namespace {

constexpr std::size_t kUpperArm = 1;
constexpr std::size_t kForearm = 2;

// One feature cell per camera, or none.
using Pixels = std::vector<std::optional<FeatureCell>>;

std::vector<CameraObservation> observations_of(const LutSet& luts, const Pixels& pixels) {
  std::vector<CameraObservation> observations;
  for (const auto& pixel : pixels) {
    CameraObservation observation{true, FeatureMask(luts.columns, luts.rows)};
    if (pixel) observation.blocked.set(pixel->column, pixel->row);
    observations.push_back(std::move(observation));
  }
  return observations;
}

std::string describe(const Pixels& pixels) {
  std::string text;
  for (std::size_t c = 0; c < pixels.size(); ++c) {
    if (!pixels[c]) continue;
    text += " camera " + std::to_string(c) + " at (" + std::to_string(pixels[c]->column) + ", " +
            std::to_string(pixels[c]->row) + ")";
  }
  return text;
}

class RobotPartVote : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    segments_ = new test::CoarseTables(PartSplit::kArmSegments);
    whole_ = new test::CoarseTables(PartSplit::kWholeRobot);
  }
  static void TearDownTestSuite() {
    delete segments_;
    delete whole_;
  }

  // Critical for the tables' vote, at threshold 2, the robot parked in `robot_cell`.
  static bool critical(const test::CoarseTables& tables, const Pixels& pixels, CellIndex cell,
                       CellIndex robot_cell) {
    FusionSettings settings;
    settings.camera_threshold = 2;
    settings.removal = RobotRemoval::kPlain;
    ForbiddenMapFusion fusion(tables.luts, tables.silhouettes, settings);
    fusion.fuse(observations_of(tables.luts, pixels), robot_cell);
    return fusion.critical().test(cell);
  }

  static test::CoarseTables* segments_;
  static test::CoarseTables* whole_;
};

test::CoarseTables* RobotPartVote::segments_ = nullptr;
test::CoarseTables* RobotPartVote::whole_ = nullptr;

TEST_F(RobotPartVote, ObstaclesAtDifferentPartsAreNoCollision) {
  const test::CoarseTables& tables = *segments_;
  ASSERT_EQ(tables.luts.parts.size(), 3U);
  const std::size_t cameras = tables.cell.cameras.size();
  const CellIndex robot_cell = 0;
  std::vector<FeatureMask> robot(cameras, FeatureMask(tables.cell.feature_grid));
  tables.silhouettes.add_silhouettes(robot_cell, robot);
  // A feature cell of camera `camera` inside part `inside`'s silhouette of the cell and outside
  // the other parts' and the parked robot's.
  const auto pixel_only_in = [&](const std::vector<std::vector<FeatureMask>>& parts,
                                 std::size_t inside, std::size_t camera) {
    const FeatureMask& mask = parts[inside][camera];
    for (int row = 0; row < mask.rows(); ++row) {
      for (int column = 0; column < mask.columns(); ++column) {
        if (!mask.test(column, row) || robot[camera].test(column, row)) continue;
        bool elsewhere = false;
        for (std::size_t part = 0; part < parts.size(); ++part) {
          elsewhere = elsewhere || (part != inside && parts[part][camera].test(column, row));
        }
        if (!elsewhere) return std::optional<FeatureCell>(FeatureCell{column, row});
      }
    }
    return std::optional<FeatureCell>();
  };
  int scenes = 0;
  for (CellIndex cell = 1; cell < tables.grid.cell_count() && scenes < 5; cell += 37) {
    if (tables.luts.static_cells.test(cell)) continue;
    std::vector<std::vector<FeatureMask>> parts(
        3, std::vector<FeatureMask>(cameras, FeatureMask(tables.cell.feature_grid)));
    for (std::size_t part = 0; part < 3; ++part) {
      tables.silhouettes.add_part_silhouettes(cell, part, parts[part].data());
    }
    for (std::size_t a = 0; a < cameras; ++a) {
      for (std::size_t b = 0; b < cameras; ++b) {
        if (a == b) continue;
        Pixels pixels(cameras);
        pixels[a] = pixel_only_in(parts, kUpperArm, a);
        pixels[b] = pixel_only_in(parts, kForearm, b);
        if (!pixels[a] || !pixels[b]) continue;
        SCOPED_TRACE("cell " + std::to_string(cell) + ":" + describe(pixels));
        EXPECT_TRUE(critical(*whole_, pixels, cell, robot_cell))
            << "the whole-robot vote counts two cameras";
        EXPECT_FALSE(critical(tables, pixels, cell, robot_cell))
            << "each part is seen by one camera only";
        ++scenes;
        a = b = cameras;  // one scene per cell
      }
    }
  }
  EXPECT_EQ(scenes, 5) << "too few cells where two cameras see different parts apart";
}

TEST_F(RobotPartVote, APointOnTheForearmIsCriticalForBothVotes) {
  const test::CoarseTables& tables = *segments_;
  const RobotModel& robot = *tables.cell.robot;
  const FeatureGrid& features = tables.cell.feature_grid;
  int scenes = 0;
  for (CellIndex cell = 3; cell < tables.grid.cell_count() && scenes < 5; cell += 53) {
    if (tables.luts.static_cells.test(cell)) continue;
    const auto centre = tables.grid.cell_centre(tables.grid.coords_of(cell).value()).value();
    const std::vector<double> q(centre.rad, centre.rad + tables.grid.joint_count());
    const auto shapes =
        collision_shapes_at(robot, q, Eigen::Isometry3d::Identity(), BodyRange{3, robot.dof() + 1});
    ASSERT_FALSE(shapes.empty());
    const Eigen::Vector3d point = tessellate(shapes.front()).vertices.front();
    // The robot parked at the other end of C-space; cameras that see the point behind its parked
    // silhouette are left out (robot removal drops what is there).
    const CellIndex robot_cell =
        cell < tables.grid.cell_count() / 2 ? tables.grid.cell_count() - 1 : 0;
    std::vector<FeatureMask> parked(tables.cell.cameras.size(), FeatureMask(features));
    tables.silhouettes.add_silhouettes(robot_cell, parked);
    // Where each camera sees the point, independently of the tables: the calibrated projection.
    Pixels pixels(tables.cell.cameras.size());
    int seen = 0;
    for (std::size_t c = 0; c < pixels.size(); ++c) {
      const auto image = tables.cell.cameras[c].project(point);
      if (!image) continue;
      pixels[c] = features.cell_of(*image);
      if (pixels[c] && parked[c].test(pixels[c]->column, pixels[c]->row)) pixels[c].reset();
      seen += pixels[c] ? 1 : 0;
    }
    if (seen < 2) continue;
    SCOPED_TRACE("cell " + std::to_string(cell) + ":" + describe(pixels));
    EXPECT_TRUE(critical(tables, pixels, cell, robot_cell));
    EXPECT_TRUE(critical(*whole_, pixels, cell, robot_cell));
    ++scenes;
  }
  EXPECT_EQ(scenes, 5);
}

}  // namespace
}  // namespace safecell

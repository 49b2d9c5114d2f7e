// The vote per robot part (robot_parts.hpp) against the paper's vote over the whole robot, on
// scenes built from the model and the cameras, not from the tables under test:
// - two cameras that each see a small obstacle at a different part of the arm in a cell make the
//   cell critical for the whole-robot vote (the phantom) and not for the vote per part;
// - a point on the forearm's surface, seen by every camera that sees it at all, makes the cell
//   critical for both votes (a real collision is never lost);
// - such a point hidden behind the parked robot from some cameras and seen by the others makes
//   the cell critical at a threshold of all those cameras with hidden votes, and not without
//   them (the paper's vote, which leaves what the robot hides to the other cameras, misses it).

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

// Each camera's blocked mask: its pixel, and the parked robot's pixels when given.
std::vector<CameraObservation> observations_of(const LutSet& luts, const Pixels& pixels,
                                               const std::vector<FeatureMask>* parked = nullptr) {
  std::vector<CameraObservation> observations;
  for (std::size_t c = 0; c < pixels.size(); ++c) {
    CameraObservation observation{true, FeatureMask(luts.columns, luts.rows)};
    if (pixels[c]) observation.blocked.set(pixels[c]->column, pixels[c]->row);
    if (parked != nullptr) observation.blocked |= (*parked)[c];
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

  // Critical for the tables' vote, the robot parked in `robot_cell`.
  static bool critical(const test::CoarseTables& tables,
                       const std::vector<CameraObservation>& observations, CellIndex cell,
                       CellIndex robot_cell, int threshold = 2, bool hidden_votes = false) {
    FusionSettings settings;
    settings.camera_threshold = threshold;
    settings.removal = RobotRemoval::kPlain;
    settings.hidden_votes = hidden_votes;
    ForbiddenMapFusion fusion(tables.luts, tables.silhouettes, settings);
    fusion.fuse(observations, robot_cell);
    return fusion.critical().test(cell);
  }
  static bool critical(const test::CoarseTables& tables, const Pixels& pixels, CellIndex cell,
                       CellIndex robot_cell) {
    return critical(tables, observations_of(tables.luts, pixels), cell, robot_cell);
  }

  // Where the cameras see a point of the forearm's surface with the robot at the centre of
  // `cell` and parked in `robot_cell`: by the calibrated projection, independently of the
  // tables. A camera whose pixel lies in the parked robot's silhouette has it hidden.
  struct ForearmPoint {
    Pixels seen;
    Pixels hidden;
    int seen_count = 0;
    int hidden_count = 0;
  };
  static ForearmPoint forearm_point(const test::CoarseTables& tables, CellIndex cell,
                                    const std::vector<FeatureMask>& parked) {
    const RobotModel& robot = *tables.cell.robot;
    const auto centre = tables.grid.cell_centre(tables.grid.coords_of(cell).value()).value();
    const std::vector<double> q(centre.rad, centre.rad + tables.grid.joint_count());
    const auto shapes =
        collision_shapes_at(robot, q, Eigen::Isometry3d::Identity(), BodyRange{3, robot.dof() + 1});
    EXPECT_FALSE(shapes.empty());
    ForearmPoint point{Pixels(parked.size()), Pixels(parked.size())};
    if (shapes.empty()) return point;
    const Eigen::Vector3d at = tessellate(shapes.front()).vertices.front();
    for (std::size_t c = 0; c < parked.size(); ++c) {
      const auto image = tables.cell.cameras[c].project(at);
      if (!image) continue;
      const auto pixel = tables.cell.feature_grid.cell_of(*image);
      if (!pixel) continue;
      const bool behind_robot = parked[c].test(pixel->column, pixel->row);
      (behind_robot ? point.hidden : point.seen)[c] = pixel;
      ++(behind_robot ? point.hidden_count : point.seen_count);
    }
    return point;
  }
  static std::vector<FeatureMask> parked_robot(const test::CoarseTables& tables,
                                               CellIndex robot_cell) {
    std::vector<FeatureMask> parked(tables.cell.cameras.size(),
                                    FeatureMask(tables.cell.feature_grid));
    tables.silhouettes.add_silhouettes(robot_cell, parked);
    return parked;
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
  int scenes = 0;
  for (CellIndex cell = 3; cell < tables.grid.cell_count() && scenes < 5; cell += 53) {
    if (tables.luts.static_cells.test(cell)) continue;
    // The robot parked at the other end of C-space; cameras that see the point behind its parked
    // silhouette are left out (robot removal drops what is there).
    const CellIndex robot_cell =
        cell < tables.grid.cell_count() / 2 ? tables.grid.cell_count() - 1 : 0;
    const ForearmPoint point = forearm_point(tables, cell, parked_robot(tables, robot_cell));
    if (point.seen_count < 2) continue;
    SCOPED_TRACE("cell " + std::to_string(cell) + ":" + describe(point.seen));
    EXPECT_TRUE(critical(tables, point.seen, cell, robot_cell));
    EXPECT_TRUE(critical(*whole_, point.seen, cell, robot_cell));
    ++scenes;
  }
  EXPECT_EQ(scenes, 5);
}

TEST_F(RobotPartVote, APointHiddenByTheParkedArmIsCriticalWithHiddenVotes) {
  const test::CoarseTables& tables = *segments_;
  const CellIndex cells = tables.grid.cell_count();
  int scenes = 0;
  for (CellIndex cell = 5; cell < cells && scenes < 5; cell += 41) {
    if (tables.luts.static_cells.test(cell)) continue;
    for (const CellIndex robot_cell : {cells - 1 - cell, (cell + cells / 3) % cells,
                                       (cell + 2 * cells / 3) % cells, (cell + 7) % cells}) {
      // The real frame shows the parked robot: its pixels are blocked in every camera.
      const std::vector<FeatureMask> parked = parked_robot(tables, robot_cell);
      const ForearmPoint point = forearm_point(tables, cell, parked);
      const int cameras = point.seen_count + point.hidden_count;
      if (point.seen_count < 1 || point.hidden_count < 1 || cameras < 3) continue;
      SCOPED_TRACE("cell " + std::to_string(cell) + ", robot parked in " +
                   std::to_string(robot_cell) + ": seen by" + describe(point.seen) +
                   ", hidden from" + describe(point.hidden));
      const auto observations = observations_of(tables.luts, point.seen, &parked);
      EXPECT_TRUE(critical(tables, observations, cell, robot_cell, cameras, true))
          << "every camera that could see the point votes";
      EXPECT_FALSE(critical(tables, observations, cell, robot_cell, cameras, false))
          << "without hidden votes only " << point.seen_count << " cameras see the point";
      ++scenes;
      break;
    }
  }
  EXPECT_EQ(scenes, 5) << "too few cells where the parked arm hides the forearm from a camera";
}

}  // namespace
}  // namespace safecell

// The fast fusion, the paper's baseline and a dense oracle straight from each robot part's
// silhouettes agree on random blocked masks, unknown cameras, robot cells, thresholds, both kinds
// of robot removal, with and without hidden votes, and every way of cutting the robot into parts.

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>

#include "model_fixture.hpp"
#include "safecell/fusion/baseline_fusion.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"
#include "safecell/lut_build/model_luts.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

FeatureMask random_blocked(std::mt19937_64& rng, int columns, int rows) {
  FeatureMask mask(columns, rows);
  const int blobs = std::uniform_int_distribution<int>(0, 4)(rng);
  for (int b = 0; b < blobs; ++b) {
    const int c0 = std::uniform_int_distribution<int>(0, columns - 1)(rng);
    const int r0 = std::uniform_int_distribution<int>(0, rows - 1)(rng);
    const int w = std::uniform_int_distribution<int>(0, 12)(rng);
    const int h = std::uniform_int_distribution<int>(0, 16)(rng);
    mask.set_rect(FeatureRect{static_cast<std::uint16_t>(c0), static_cast<std::uint16_t>(r0),
                              static_cast<std::uint16_t>(std::min(columns - 1, c0 + w)),
                              static_cast<std::uint16_t>(std::min(rows - 1, r0 + h))});
  }
  const int noise = std::uniform_int_distribution<int>(0, 10)(rng);
  for (int k = 0; k < noise; ++k) {
    mask.set(std::uniform_int_distribution<int>(0, columns - 1)(rng),
             std::uniform_int_distribution<int>(0, rows - 1)(rng));
  }
  return mask;
}

// The mask as its rectangles, columns and rows inclusive: enough to rebuild a failing scene.
std::string rectangles_of(const FeatureMask& mask) {
  std::string text;
  for (const FeatureRect& rect : mask.rectangles()) {
    text += " [" + std::to_string(rect.col0) + ".." + std::to_string(rect.col1) + " x " +
            std::to_string(rect.row0) + ".." + std::to_string(rect.row1) + "]";
  }
  return text.empty() ? " (none)" : text;
}

CellSet dense_oracle(const LutSet& luts, const ModelSilhouettes& silhouettes,
                     const std::vector<CameraObservation>& observations, CellIndex robot_cell,
                     const FusionSettings& settings) {
  const std::size_t cameras = observations.size();
  std::vector<FeatureMask> robot(cameras, FeatureMask(luts.columns, luts.rows));
  std::vector<FeatureMask> obstacles(cameras, FeatureMask(luts.columns, luts.rows));
  std::vector<FeatureMask> dropped(cameras, FeatureMask(luts.columns, luts.rows));
  remove_robot_from_views(observations, {silhouettes, nullptr, robot_cell, {}}, settings,
                          {robot, obstacles, dropped});
  // The pixels that vote as hidden, from the masks: blocked, inside the robot, not obstacles.
  std::vector<FeatureMask> hidden(cameras, FeatureMask(luts.columns, luts.rows));
  for (std::size_t camera = 0; camera < cameras; ++camera) {
    if (!observations[camera].known || !settings.hidden_votes) continue;
    hidden[camera] = observations[camera].blocked;
    hidden[camera] &= robot[camera];
    hidden[camera].subtract(obstacles[camera]);
  }
  const std::uint32_t cells = luts.static_cells.cell_count();
  CellSet forbidden = luts.static_cells;
  std::vector<FeatureMask> part_silhouettes(cameras, FeatureMask(luts.columns, luts.rows));
  for (CellIndex cell = 0; cell < cells; ++cell) {
    for (std::size_t part = 0; part < silhouettes.parts().size(); ++part) {
      for (FeatureMask& mask : part_silhouettes) mask.clear();
      silhouettes.add_part_silhouettes(cell, part, part_silhouettes.data());
      int seeing = 0;
      int voting = 0;
      for (std::size_t camera = 0; camera < cameras; ++camera) {
        const FeatureMask& silhouette = part_silhouettes[camera];
        const bool known = observations[camera].known;
        const bool sees = known ? silhouette.intersects(obstacles[camera]) : silhouette.any();
        // A camera hides the cell when the robot's blocked pixels it dropped meet the part's
        // silhouette (the masks' own test, independent of the tables).
        const bool hides = known && settings.hidden_votes && silhouette.intersects(hidden[camera]);
        seeing += sees ? 1 : 0;
        voting += sees || hides ? 1 : 0;
      }
      if (seeing >= 1 && voting >= settings.camera_threshold) forbidden.set(cell);
    }
  }
  return forbidden;
}

// Every part's tables of every camera of the set.
template <typename Edit>
void edit_parts(LutSet& luts, Edit edit) {
  for (auto& camera : luts.cameras) {
    for (auto& part : camera.parts) edit(part);
  }
}

void expect_fusions_agree(PartSplit split) {
  SCOPED_TRACE(std::string("robot parts: ") + to_string(split));
  const test::CoarseTables tables(split);
  const CspaceGrid& grid = tables.grid;
  const LutSet& luts = tables.luts;
  const ModelSilhouettes& silhouettes = tables.silhouettes;
  ASSERT_EQ(luts.parts.size(), robot_parts(*tables.cell.robot, split).size());
  ASSERT_FALSE(luts.cameras[0].parts[0].differences[kLeftNeighbour].empty());
  ASSERT_FALSE(luts.cameras[0].parts[0].differences[kUpperNeighbour].empty());
  // The same tables with the differences to one neighbour only, and with none (fusion then adds
  // whole entries).
  std::vector<LutSet> fewer_differences(3, luts);
  edit_parts(fewer_differences[0],
             [](PartLuts& part) { part.differences[kUpperNeighbour].clear(); });
  edit_parts(fewer_differences[1],
             [](PartLuts& part) { part.differences[kLeftNeighbour].clear(); });
  edit_parts(fewer_differences[2], [](PartLuts& part) {
    for (auto& neighbour : part.differences) neighbour.clear();
  });
  test::PropertyRun run(split == PartSplit::kArmSegments ? 24 : 12);
  std::uniform_int_distribution<CellIndex> any_cell(0, grid.cell_count() - 1);
  int nonempty = 0;
  int covered = 0;  // parts skipped because every cell they could make critical already was
  for (int i = 0; i < run.iterations(); ++i) {
    FusionSettings settings;
    settings.camera_threshold = 1 + i % 4;
    settings.removal = i % 2 == 0 ? RobotRemoval::kOcclusionAware : RobotRemoval::kPlain;
    settings.hidden_votes = (i / 4) % 2 == 0;
    std::vector<CameraObservation> observations(luts.cameras.size());
    for (auto& observation : observations) {
      observation.known = std::bernoulli_distribution(0.85)(run.rng());
      observation.blocked = random_blocked(run.rng(), luts.columns, luts.rows);
    }
    const CellIndex robot_cell = any_cell(run.rng());
    // The failing input, not only the seed.
    std::string scene = "robot cell " + std::to_string(robot_cell) + ", threshold " +
                        std::to_string(settings.camera_threshold) + ", removal " +
                        to_string(settings.removal) +
                        (settings.hidden_votes ? ", hidden votes" : ", no hidden votes");
    for (std::size_t c = 0; c < observations.size(); ++c) {
      scene += "; camera " + std::to_string(c) +
               (observations[c].known ? " blocked" + rectangles_of(observations[c].blocked)
                                      : std::string(" unknown"));
    }
    SCOPED_TRACE(scene);
    ForbiddenMapFusion fast(luts, silhouettes, settings);
    BaselineFusion baseline(luts, silhouettes, settings);
    const CellSet& fused = fast.fuse(observations, robot_cell);
    const CellSet oracle = dense_oracle(luts, silhouettes, observations, robot_cell, settings);
    ASSERT_EQ(fused, oracle) << "iteration " << i;
    for (std::size_t set = 0; set < fewer_differences.size(); ++set) {
      ForbiddenMapFusion with_fewer(fewer_differences[set], silhouettes, settings);
      ASSERT_EQ(with_fewer.fuse(observations, robot_cell), oracle)
          << "iteration " << i << ", differences of set " << set;
    }
    ASSERT_EQ(baseline.fuse(observations, robot_cell), oracle) << "iteration " << i;
    EXPECT_EQ(fast.counts().forbidden_cells, fused.count());
    nonempty += fused.count() > luts.static_cells.count() ? 1 : 0;
    for (std::size_t part = 0; part < luts.parts.size(); ++part) {
      EXPECT_FALSE(fast.counts().part_covered[part] && fast.counts().part_critical[part]);
      covered += fast.counts().part_covered[part] ? 1 : 0;
    }
    // The map given up for a cycle (the separation stopped the robot), then made in two halves
    // by the same engine: nothing of the skipped cycle may reach the next one.
    const CellSet& all = fast.forbid_all();
    EXPECT_EQ(all.count(), grid.cell_count());
    EXPECT_FALSE(fast.critical().any());
    EXPECT_EQ(fast.counts().critical_cells, 0U);
    for (std::size_t part = 0; part < luts.parts.size(); ++part) {
      EXPECT_FALSE(fast.counts().part_voted[part]);
      EXPECT_FALSE(fast.suspicious(part, 0).any());
    }
    fast.remove_robot(observations, robot_cell);
    ASSERT_EQ(fast.vote(observations), oracle) << "iteration " << i << ", in two halves";
  }
  if (run.full_length()) {
    EXPECT_GT(nonempty, run.iterations() / 3) << "the random scenes forbid too little to test";
    // The whole robot is one part: nothing to skip.
    if (split != PartSplit::kWholeRobot) {
      EXPECT_GT(covered, 0) << "no scene let a part be skipped";
    }
  }
}

TEST(FusionEquivalence, FastEqualsBaselineEqualsDenseOracleForArmSegments) {
  expect_fusions_agree(PartSplit::kArmSegments);
}

TEST(FusionEquivalence, FastEqualsBaselineEqualsDenseOracleForEveryLink) {
  expect_fusions_agree(PartSplit::kPerLink);
}

TEST(FusionEquivalence, FastEqualsBaselineEqualsDenseOracleForLinksAndWrist) {
  expect_fusions_agree(PartSplit::kLinksAndWrist);
}

TEST(FusionEquivalence, FastEqualsBaselineEqualsDenseOracleForTheWholeRobot) {
  expect_fusions_agree(PartSplit::kWholeRobot);
}

TEST(FusionEquivalence, ACameraStopsEarlyOnceItsSetHoldsEverythingItSees) {
  // One part: with everything blocked, the parts voted on before the arm would make every cell
  // critical and the arm would be skipped as covered, its cameras never filling.
  const test::CoarseTables tables(PartSplit::kWholeRobot);
  const LutSet& luts = tables.luts;
  FusionSettings settings;
  settings.camera_threshold = 1;
  std::vector<CameraObservation> observations(luts.cameras.size());
  for (auto& observation : observations) {
    observation.known = true;
    observation.blocked = FeatureMask(luts.columns, luts.rows);
    observation.blocked.set_rect(FeatureRect{0, 0, static_cast<std::uint16_t>(luts.columns - 1),
                                             static_cast<std::uint16_t>(luts.rows - 1)});
  }
  observations[1].blocked.clear();
  ForbiddenMapFusion fast(luts, tables.silhouettes, settings);
  BaselineFusion baseline(luts, tables.silhouettes, settings);
  // Occlusion-aware removal keeps the robot's pixels that border obstacles, so with everything
  // blocked camera 0 can see all its cells, but whether it does depends on the robot's cell.
  int stopped_early = 0;
  for (CellIndex robot_cell = 0; robot_cell < luts.static_cells.cell_count() && stopped_early < 3;
       robot_cell += 7) {
    const CellSet& fused = fast.fuse(observations, robot_cell);
    ASSERT_EQ(fused, baseline.fuse(observations, robot_cell)) << "robot cell " << robot_cell;
    const std::size_t cameras = luts.cameras.size();
    for (std::size_t part = 0; part < luts.parts.size(); ++part) {
      EXPECT_FALSE(fast.counts().saturated[part * cameras + 1]);
      EXPECT_FALSE(fast.suspicious(part, 1).any());
    }
    const std::size_t whole = 0;  // the one part
    if (!fast.counts().saturated[whole * cameras]) continue;
    ++stopped_early;
    EXPECT_EQ(fast.suspicious(whole, 0), fast.observable(whole, 0)) << "robot cell " << robot_cell;
    EXPECT_EQ(fused, dense_oracle(luts, tables.silhouettes, observations, robot_cell, settings));
  }
  EXPECT_EQ(stopped_early, 3) << "camera 0 never held every cell it sees";
}

TEST(FusionEquivalence, UnknownCameraMarksEverythingItCanSee) {
  const test::CoarseTables tables;
  const CspaceGrid& grid = tables.grid;
  const LutSet& luts = tables.luts;
  const ModelSilhouettes& silhouettes = tables.silhouettes;
  FusionSettings settings;
  settings.camera_threshold = 1;
  ForbiddenMapFusion fusion(luts, silhouettes, settings);
  std::vector<CameraObservation> observations(luts.cameras.size());
  for (auto& observation : observations) {
    observation.known = true;
    observation.blocked = FeatureMask(luts.columns, luts.rows);
  }
  EXPECT_EQ(fusion.fuse(observations, 0), luts.static_cells);  // nothing seen: static only
  observations[1].known = false;
  CellSet expected = fusion.observable(1);
  expected |= luts.static_cells;
  EXPECT_EQ(fusion.fuse(observations, 0), expected);
  EXPECT_GT(fusion.observable(1).count(), grid.cell_count() / 2);
}

TEST(FusionEquivalence, AVoteNeedsThisCyclesRobotRemoval) {
  const test::CoarseTables tables;
  const LutSet& luts = tables.luts;
  ForbiddenMapFusion fusion(luts, tables.silhouettes, FusionSettings{});
  std::vector<CameraObservation> observations(luts.cameras.size());
  for (auto& observation : observations) {
    observation.known = true;
    observation.blocked = FeatureMask(luts.columns, luts.rows);
  }
  EXPECT_THROW((void)fusion.vote(observations), std::logic_error) << "before any removal";
  fusion.remove_robot(observations, 0);
  EXPECT_EQ(fusion.vote(observations), luts.static_cells);
  EXPECT_THROW((void)fusion.vote(observations), std::logic_error) << "a second vote on it";
  const std::vector<CameraObservation> copy = observations;
  fusion.remove_robot(observations, 0);
  EXPECT_THROW((void)fusion.vote(copy), std::logic_error) << "a vote on other observations";
  fusion.remove_robot(observations, 0);
  (void)fusion.forbid_all();
  EXPECT_THROW((void)fusion.vote(observations), std::logic_error) << "after forbid_all";
  EXPECT_THROW(fusion.remove_robot(observations, luts.static_cells.cell_count()),
               std::out_of_range);
  EXPECT_THROW((void)fusion.vote(observations), std::logic_error) << "after a refused removal";
}

TEST(FusionEquivalence, BadInputsAreRefused) {
  const test::CoarseTables tables;
  const CspaceGrid& grid = tables.grid;
  const LutSet& luts = tables.luts;
  const ModelSilhouettes& silhouettes = tables.silhouettes;
  FusionSettings settings;
  settings.camera_threshold = 5;
  EXPECT_THROW(ForbiddenMapFusion(luts, silhouettes, settings), std::invalid_argument);
  settings.camera_threshold = 0;
  EXPECT_THROW(ForbiddenMapFusion(luts, silhouettes, settings), std::invalid_argument);
  settings.camera_threshold = 2;
  LutSet misfit = luts;
  PartLuts& part = misfit.cameras[1].parts[0];
  part.differences[kLeftNeighbour][0] = part.pixel_blocks[0];  // 32 x 32
  EXPECT_THROW(ForbiddenMapFusion(misfit, silhouettes, settings), std::invalid_argument);
  misfit = luts;
  PartLuts& other = misfit.cameras[2].parts[1];
  other.differences[kUpperNeighbour].push_back(other.pixel_to_cells);
  EXPECT_THROW(ForbiddenMapFusion(misfit, silhouettes, settings), std::invalid_argument);
  misfit = luts;
  misfit.cameras[3].parts.pop_back();  // tables for fewer parts than the set names
  EXPECT_THROW(ForbiddenMapFusion(misfit, silhouettes, settings), std::invalid_argument);
  ForbiddenMapFusion fusion(luts, silhouettes, settings);
  std::vector<CameraObservation> three(3, CameraObservation{true, FeatureMask(64, 64)});
  EXPECT_THROW(fusion.fuse(three, 0), std::invalid_argument);
  std::vector<CameraObservation> small(4, CameraObservation{true, FeatureMask(32, 32)});
  EXPECT_THROW(fusion.fuse(small, 0), std::invalid_argument);
  std::vector<CameraObservation> good(4, CameraObservation{true, FeatureMask(64, 64)});
  EXPECT_THROW(fusion.fuse(good, grid.cell_count()), std::out_of_range);
}

}  // namespace
}  // namespace safecell

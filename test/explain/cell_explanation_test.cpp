// Stop explanations against the fusion they explain and against the robot parts' silhouettes:
// - a cell is explained as critical exactly when the fusion made it critical, as static exactly
//   when it is static and not critical, and as not forbidden otherwise;
// - each camera's feature cells are exactly its obstacle pixels inside the part's silhouette of
//   the cell (LUT-1 from the model, not the LUT-2 the explanation reads);
// - explained with another cycle's views (the negative control), the agreement fails.

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "model_fixture.hpp"
#include "safecell/explain/cell_explanation.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

std::vector<CameraObservation> random_views(std::mt19937_64& rng, const LutSet& luts) {
  std::vector<CameraObservation> observations(luts.cameras.size());
  for (auto& observation : observations) {
    observation.known = std::bernoulli_distribution(0.9)(rng);
    observation.blocked = FeatureMask(luts.columns, luts.rows);
    const int blobs = std::uniform_int_distribution<int>(1, 3)(rng);
    for (int b = 0; b < blobs; ++b) {
      const int c0 = std::uniform_int_distribution<int>(0, luts.columns - 4)(rng);
      const int r0 = std::uniform_int_distribution<int>(0, luts.rows - 6)(rng);
      observation.blocked.set_rect(
          FeatureRect{static_cast<std::uint16_t>(c0), static_cast<std::uint16_t>(r0),
                      static_cast<std::uint16_t>(c0 + 3), static_cast<std::uint16_t>(r0 + 5)});
    }
  }
  return observations;
}

std::string scene_text(const std::vector<CameraObservation>& observations, CellIndex robot_cell) {
  std::string text = "robot cell " + std::to_string(robot_cell);
  for (std::size_t c = 0; c < observations.size(); ++c) {
    text += "; camera " + std::to_string(c);
    if (!observations[c].known) {
      text += " unknown";
      continue;
    }
    for (const FeatureRect& rect : observations[c].blocked.rectangles()) {
      text += " [" + std::to_string(rect.col0) + ".." + std::to_string(rect.col1) + " x " +
              std::to_string(rect.row0) + ".." + std::to_string(rect.row1) + "]";
    }
  }
  return text;
}

// Whether the explanation agrees with the fusion's map and with the parts' silhouettes; the
// first disagreement otherwise.
std::string disagreement(const test::CoarseTables& tables, const ForbiddenMapFusion& fusion,
                         const CellExplanation& explanation, CellIndex cell) {
  const bool critical = fusion.critical().test(cell);
  const bool is_static = tables.luts.static_cells.test(cell);
  const ForbiddenBecause expected = critical    ? ForbiddenBecause::kCritical
                                    : is_static ? ForbiddenBecause::kStatic
                                                : ForbiddenBecause::kNotForbidden;
  if (explanation.because != expected) {
    return std::string("explained as ") + to_string(explanation.because) + ", the fusion says " +
           to_string(expected);
  }
  const std::size_t cameras = fusion.camera_count();
  for (const PartVote& vote : explanation.parts) {
    std::vector<FeatureMask> silhouettes(cameras,
                                         FeatureMask(tables.luts.columns, tables.luts.rows));
    tables.silhouettes.add_part_silhouettes(cell, vote.part, silhouettes.data());
    for (const CameraVote& camera : vote.cameras) {
      if (camera.unknown) continue;
      FeatureMask expected_cells = fusion.obstacles(camera.camera);
      expected_cells &= silhouettes[camera.camera];
      FeatureMask explained(tables.luts.columns, tables.luts.rows);
      for (const FeatureCell& at : camera.obstacle_cells) explained.set(at.column, at.row);
      if (!(explained == expected_cells)) {
        return "part " + std::to_string(vote.part) + ", camera " + std::to_string(camera.camera) +
               ": feature cells differ from its obstacles inside the part's silhouette";
      }
    }
  }
  return {};
}

void expect_agreement(const FusionSettings& settings) {
  const test::CoarseTables tables;
  const LutSet& luts = tables.luts;
  ForbiddenMapFusion fusion(luts, tables.silhouettes, settings);
  FusedViewsHistory history(4);
  test::PropertyRun run(12);
  std::uniform_int_distribution<CellIndex> any_cell(0, tables.grid.cell_count() - 1);
  int critical_cells = 0;
  int static_cells = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    const auto observations = random_views(run.rng(), luts);
    const CellIndex robot_cell = any_cell(run.rng());
    SCOPED_TRACE(scene_text(observations, robot_cell));
    fusion.fuse(observations, robot_cell);
    const auto version = static_cast<std::uint64_t>(i + 1);
    history.record(version, fusion, observations);
    // Critical cells, static cells and a few others.
    std::vector<CellIndex> cells;
    for (CellIndex cell = fusion.critical().next_set(0);
         cell < tables.grid.cell_count() && cells.size() < 6;
         cell = fusion.critical().next_set(cell + 1 + any_cell(run.rng()) % 97)) {
      cells.push_back(cell);
    }
    for (int k = 0; k < 6; ++k) cells.push_back(any_cell(run.rng()));
    // Static cells from random places (random cells alone may meet none: the coarse grid has
    // few), so that every seed tests the static explanation.
    for (int k = 0; k < 6; ++k) {
      CellIndex cell = luts.static_cells.next_set(any_cell(run.rng()));
      if (cell >= tables.grid.cell_count()) cell = luts.static_cells.next_set(0);
      if (cell < tables.grid.cell_count()) cells.push_back(cell);
    }
    for (const CellIndex cell : cells) {
      const CellExplanation explanation = explain_cell(fusion, history.find(version), cell);
      EXPECT_EQ(explanation.map_version, version);
      const std::string wrong = disagreement(tables, fusion, explanation, cell);
      EXPECT_TRUE(wrong.empty()) << "cell " << cell << ": " << wrong;
      critical_cells += explanation.because == ForbiddenBecause::kCritical ? 1 : 0;
      static_cells += explanation.because == ForbiddenBecause::kStatic ? 1 : 0;
      if (explanation.because == ForbiddenBecause::kCritical) {
        const std::string text = describe(explanation, fusion);
        EXPECT_NE(text.find("critical"), std::string::npos) << text;
        EXPECT_NE(text.find("camera '"), std::string::npos) << text;
      }
    }
  }
  if (run.full_length()) {
    EXPECT_GT(critical_cells, run.iterations()) << "too few critical cells to test";
    EXPECT_GT(static_cells, 0) << "no static cell among the samples";
  }
}

TEST(CellExplanation, AgreesWithTheFusionAndTheSilhouettes) {
  FusionSettings settings;
  settings.camera_threshold = 2;
  settings.removal = RobotRemoval::kPlain;
  expect_agreement(settings);
}

TEST(CellExplanation, AgreesWithTheFusionAtThreshold3WithHiddenVotes) {
  FusionSettings settings;
  settings.camera_threshold = 3;
  settings.hidden_votes = true;
  expect_agreement(settings);
}

TEST(CellExplanation, TheViewsOfAnotherCycleDisagree) {
  // The negative control: the agreement above can fail. A critical cell explained with the views
  // of an empty cycle is not critical, and the check says so.
  const test::CoarseTables tables;
  const LutSet& luts = tables.luts;
  FusionSettings settings;
  settings.camera_threshold = 2;
  ForbiddenMapFusion fusion(luts, tables.silhouettes, settings);
  FusedViewsHistory history(4);
  std::vector<CameraObservation> empty(
      luts.cameras.size(), CameraObservation{true, FeatureMask(luts.columns, luts.rows)});
  fusion.fuse(empty, 0);
  history.record(1, fusion, empty);
  std::mt19937_64 rng(3);
  std::vector<CameraObservation> busy;
  do {
    busy = random_views(rng, luts);
    fusion.fuse(busy, 0);
  } while (fusion.critical().count() == 0);
  history.record(2, fusion, busy);
  const CellIndex cell = fusion.critical().next_set(0);
  EXPECT_TRUE(
      disagreement(tables, fusion, explain_cell(fusion, history.find(2), cell), cell).empty());
  const CellExplanation stale = explain_cell(fusion, history.find(1), cell);
  EXPECT_EQ(stale.because, luts.static_cells.test(cell) ? ForbiddenBecause::kStatic
                                                        : ForbiddenBecause::kNotForbidden);
  EXPECT_FALSE(disagreement(tables, fusion, stale, cell).empty());
}

TEST(CellExplanation, UnknownMapsAndWholeForbiddenMapsAreSaidSo) {
  const test::CoarseTables tables;
  FusionSettings settings;
  ForbiddenMapFusion fusion(tables.luts, tables.silhouettes, settings);
  FusedViewsHistory history(2);
  history.record_all_forbidden(7, "robot pose unknown: no joints");
  const CellExplanation whole = explain_cell(fusion, history.find(7), 5);
  EXPECT_EQ(whole.because, ForbiddenBecause::kAllForbidden);
  EXPECT_NE(describe(whole, fusion).find("robot pose unknown"), std::string::npos);
  EXPECT_EQ(explain_cell(fusion, history.find(8), 5).because, ForbiddenBecause::kMapUnknown);
  EXPECT_THROW((void)explain_cell(fusion, history.find(7), tables.grid.cell_count()),
               std::out_of_range);
}

}  // namespace
}  // namespace safecell

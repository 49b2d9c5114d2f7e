#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

#include "model_fixture.hpp"
#include "safecell/envelope/ball_projection.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// Every camera's silhouette of one part of a cell, from its balls computed directly (not from
// the head's masks per prefix, nor from the tail's balls made once per line and moved along it).
std::vector<FeatureMask> direct_silhouettes(const CellModel& cell, const ModelSilhouettes& model,
                                            CellIndex index, const RobotPart& part) {
  std::vector<Ball> balls;
  model.envelope().balls_of_bodies(model.envelope().grid().coords_of(index).value(),
                                   part.first_body, part.end_body, balls);
  std::vector<FeatureMask> masks;
  for (const auto& camera : cell.cameras) {
    masks.emplace_back(cell.feature_grid);
    add_ball_rects(BallProjection(camera, cell.feature_grid), balls, masks.back());
  }
  return masks;
}

// Two models of the default cell (paddings 2 and 5 cm: other balls on the same grid) asked in
// turn, on one thread, for random parts of random cells, most of them on a few lines of joint-0
// cells: each answer is the cell's own silhouette, never a line another model, part or line left
// behind. Control: the next cell along joint 0 has another silhouette in most calls, so an answer
// one cell off the line would be caught.
TEST(ModelSilhouettes, LinesMadeOnceGiveEachCellItsOwnSilhouetteInAnyOrder) {
  test::PropertyRun run(300);
  const CellModel cell = load_cell_model(default_cell());
  const CspaceGrid grid = make_grid(cell.config);
  ModelLutOptions wider;
  wider.padding_m = 0.05;
  const ModelSilhouettes narrow(cell, grid, ModelLutOptions{});
  const ModelSilhouettes wide(cell, grid, wider);
  const std::array<const ModelSilhouettes*, 2> models{&narrow, &wide};
  ASSERT_LT(narrow.envelope().tail_body(), narrow.envelope().body_count())
      << "the default cell's robot must have a tail, or no line is made";
  const std::uint32_t line_length = grid.cells_along(0);
  std::vector<CellIndex> lines;
  lines.reserve(3);
  for (int line = 0; line < 3; ++line) {
    lines.push_back(static_cast<CellIndex>(run.rng()() % (grid.cell_count() / line_length)) *
                    line_length);
  }
  int control_caught = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    const std::size_t which = run.rng()() % models.size();
    const ModelSilhouettes& model = *models.at(which);
    const std::size_t part = run.rng()() % model.parts().size();
    const auto along = static_cast<CellIndex>(run.rng()() % (line_length - 1));
    const CellIndex index = i % 4 == 3 ? static_cast<CellIndex>(run.rng()() % grid.cell_count())
                                       : lines[run.rng()() % lines.size()] + along;
    std::vector<FeatureMask> masks(cell.cameras.size(), FeatureMask(cell.feature_grid));
    model.add_part_silhouettes(index, part, masks.data());
    ASSERT_EQ(masks, direct_silhouettes(cell, model, index, model.parts()[part]))
        << "call " << i << ": model " << which << ", cell " << index << ", part " << part;
    const bool last_on_line = grid.coords_of(index).value().along[0] + 1 == line_length;
    if (!last_on_line) {
      control_caught +=
          masks != direct_silhouettes(cell, model, index + 1, model.parts()[part]) ? 1 : 0;
    }
  }
  if (run.full_length()) {
    EXPECT_GT(control_caught, run.iterations() / 2) << "control: one cell off must be caught";
  }
}

}  // namespace
}  // namespace safecell

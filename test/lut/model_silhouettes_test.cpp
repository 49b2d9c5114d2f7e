#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <random>
#include <vector>

#include "model_fixture.hpp"
#include "safecell/cell/cell_error.hpp"
#include "safecell/envelope/ball_projection.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/test/property.hpp"
#include "silhouette_check.hpp"

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
  // Whole cells: direct_silhouettes takes the cell's own envelope.
  CellConfig config = default_cell();
  config.envelope_max_move_m.reset();
  const CellModel cell = load_cell_model(config);
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

// The coarse default cell with its cells cut into 2 sub-cells per discretised joint (3 of them:
// 8 sub-cells a cell), and the same cell drawn from whole cells.
struct SubCellModels {
  static CellModel with_max_move(std::optional<double> max_move_m) {
    CellConfig config = test::coarse_default_config();
    config.envelope_max_move_m = max_move_m;
    return load_cell_model(config);
  }
  explicit SubCellModels(std::uint32_t per_joint = 2) : parts(per_joint) {}
  std::uint32_t parts;
  CellModel cell = with_max_move(test::coarse_default_config().m_max_m / parts);
  CellModel whole_cell = with_max_move(std::nullopt);
  CspaceGrid grid = make_grid(cell.config);
  CspaceGrid sub_grid = grid.subdivided(parts).value();
  ModelSilhouettes sub_cells{cell, grid, ModelLutOptions{}};
  ModelSilhouettes whole_cells{whole_cell, grid, ModelLutOptions{}};
  // Whole cells of the subdivided grid: each is one sub-cell.
  ModelSilhouettes on_sub_grid{whole_cell, sub_grid, ModelLutOptions{}};

  // The sub-cells of a cell of `grid`, as cells of `sub_grid`.
  [[nodiscard]] std::vector<CellIndex> sub_cells_of(CellIndex index) const {
    const GridCoords coords = grid.coords_of(index).value();
    std::vector<CellIndex> found;
    for (CellIndex sub = 0; sub < sub_grid.cell_count(); ++sub) {
      const GridCoords sub_coords = sub_grid.coords_of(sub).value();
      bool inside = true;
      for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
        const std::uint32_t cut = grid.joint(j).discretised ? parts : 1;
        inside = inside && sub_coords.along[j] / cut == coords.along[j];
      }
      if (inside) found.push_back(sub);
    }
    return found;
  }
};

TEST(ModelSilhouettes, EnvelopeMaxMoveSetsTheSubCellsPerJoint) {
  EXPECT_EQ(SubCellModels::with_max_move(std::nullopt).envelope_subdivision, 1u);
  EXPECT_EQ(SubCellModels::with_max_move(0.4).envelope_subdivision, 1u);
  EXPECT_EQ(SubCellModels::with_max_move(1.0).envelope_subdivision, 1u);
  EXPECT_EQ(SubCellModels::with_max_move(0.2).envelope_subdivision, 2u);
  EXPECT_EQ(SubCellModels::with_max_move(0.15).envelope_subdivision, 3u);
  EXPECT_EQ(SubCellModels::with_max_move(0.1).envelope_subdivision, 4u);
  EXPECT_EQ(SubCellModels::with_max_move(0.01).envelope_subdivision, 4u);
  EXPECT_THROW(SubCellModels::with_max_move(-0.2), CellError);
}

// A cell's silhouette is the union of its sub-cells' own (whole cells of the subdivided grid),
// for random parts of random cells asked in random order (the lines a thread keeps). A part is
// drawn from the sub-cells of the joints that move it only (model_silhouettes.cpp); the union
// here is over all 8. Control: the first sub-cell alone differs from the union for most parts
// that a discretised joint moves.
TEST(ModelSilhouettes, ACellsSilhouetteIsTheUnionOfItsSubCells) {
  const SubCellModels models;
  ASSERT_EQ(models.sub_cells.subdivision(), 2u);
  ASSERT_EQ(models.sub_grid.cell_count(), models.grid.cell_count() * 8);
  test::PropertyRun run(40);
  const std::size_t cameras = models.cell.cameras.size();
  int moved = 0;
  int first_alone_differs = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    const auto index = static_cast<CellIndex>(run.rng()() % models.grid.cell_count());
    const std::size_t part = run.rng()() % models.sub_cells.parts().size();
    std::vector<FeatureMask> masks(cameras, FeatureMask(models.cell.feature_grid));
    models.sub_cells.add_part_silhouettes(index, part, masks.data());
    std::vector<FeatureMask> united(cameras, FeatureMask(models.cell.feature_grid));
    const std::vector<CellIndex> subs = models.sub_cells_of(index);
    ASSERT_EQ(subs.size(), 8u);
    for (const CellIndex sub : subs)
      models.on_sub_grid.add_part_silhouettes(sub, part, united.data());
    ASSERT_EQ(masks, united) << "cell " << index << ", part " << part;
    if (models.sub_cells.parts()[part].end_body > 1) {  // joint 0 (discretised) moves it
      std::vector<FeatureMask> first(cameras, FeatureMask(models.cell.feature_grid));
      models.on_sub_grid.add_part_silhouettes(subs.front(), part, first.data());
      ++moved;
      first_alone_differs += first != united ? 1 : 0;
    }
  }
  if (run.full_length()) {
    EXPECT_GT(first_alone_differs, moved / 2) << "control: one sub-cell for all must be caught";
  }
}

// The silhouettes of a part are the same in cells that differ only along joints that do not
// move it (body b moves with joints 0..b-1): the model-mode build draws each part's first joints'
// cells only and repeats them (repeat_cells). Every part of links-and-wrist, with sub-cells.
// Control: a cell that differs along the last joint that moves the part has other silhouettes
// in most calls.
TEST(ModelSilhouettes, APartsSilhouettesRepeatAlongTheJointsThatDoNotMoveIt) {
  const SubCellModels models;
  const ModelSilhouettes silhouettes(models.cell, models.grid,
                                     test::options_with(PartSplit::kLinksAndWrist));
  ASSERT_EQ(silhouettes.parts().size(), 5u);
  const CspaceGrid& grid = models.grid;
  test::PropertyRun run(60);
  const std::size_t cameras = models.cell.cameras.size();
  int controls = 0;
  int control_caught = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    const auto index = static_cast<CellIndex>(run.rng()() % grid.cell_count());
    const std::size_t part = run.rng()() % silhouettes.parts().size();
    const std::size_t moving_joints = silhouettes.parts()[part].end_body - 1;
    const GridCoords coords = grid.coords_of(index).value();
    GridCoords elsewhere = coords;
    for (std::uint32_t joint = 0; joint < grid.joint_count(); ++joint) {
      if (joint >= moving_joints) {
        elsewhere.along[joint] = static_cast<std::uint32_t>(run.rng()() % grid.cells_along(joint));
      }
    }
    const CellIndex other = grid.index_of(elsewhere).value();
    std::vector<FeatureMask> masks(cameras, FeatureMask(models.cell.feature_grid));
    std::vector<FeatureMask> others(cameras, FeatureMask(models.cell.feature_grid));
    silhouettes.add_part_silhouettes(index, part, masks.data());
    silhouettes.add_part_silhouettes(other, part, others.data());
    ASSERT_EQ(masks, others) << "part " << silhouettes.parts()[part].name << ", cells " << index
                             << " and " << other;
    if (moving_joints == 0) continue;
    const auto last =
        static_cast<std::uint32_t>(std::min<std::size_t>(moving_joints, grid.joint_count()) - 1);
    if (grid.cells_along(last) < 2) continue;
    GridCoords moved = coords;
    moved.along[last] = (coords.along[last] + 1) % grid.cells_along(last);
    std::vector<FeatureMask> moved_masks(cameras, FeatureMask(models.cell.feature_grid));
    silhouettes.add_part_silhouettes(grid.index_of(moved).value(), part, moved_masks.data());
    ++controls;
    control_caught += moved_masks != masks ? 1 : 0;
  }
  if (run.full_length()) {
    EXPECT_GT(control_caught, controls / 2) << "control: a moving joint's cell must count";
  }
}

// Robot removal draws whole cells whatever the cell file says (CellDrawing::kWholeCells): the
// same silhouettes as a cell without sub-cells. Control: the tables' drawing of the same cell
// differs from them.
TEST(ModelSilhouettes, RemovalDrawsWholeCellsOfACellWithSubCells) {
  const SubCellModels models;
  const ModelSilhouettes removal(models.cell, models.grid, ModelLutOptions{},
                                 CellDrawing::kWholeCells);
  EXPECT_EQ(removal.subdivision(), 1u);
  test::PropertyRun run(40);
  const std::size_t cameras = models.cell.cameras.size();
  int tables_differ = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    const auto index = static_cast<CellIndex>(run.rng()() % models.grid.cell_count());
    std::vector<FeatureMask> drawn(cameras, FeatureMask(models.cell.feature_grid));
    std::vector<FeatureMask> whole(cameras, FeatureMask(models.cell.feature_grid));
    std::vector<FeatureMask> tables(cameras, FeatureMask(models.cell.feature_grid));
    removal.add_silhouettes(index, drawn);
    models.whole_cells.add_silhouettes(index, whole);
    models.sub_cells.add_silhouettes(index, tables);
    ASSERT_EQ(drawn, whole) << "cell " << index;
    tables_differ += tables != whole ? 1 : 0;
  }
  EXPECT_GT(tables_differ, run.iterations() / 2) << "control: the tables draw sub-cells";
}

// Control for the check below: a silhouette drawn from one sub-cell only.
class FirstSubCellOnly final : public RobotSilhouettes {
 public:
  explicit FirstSubCellOnly(const SubCellModels& models) : models_(models) {}
  [[nodiscard]] std::size_t camera_count() const override {
    return models_.on_sub_grid.camera_count();
  }
  void add_silhouette(CellIndex cell, std::size_t camera, FeatureMask& mask) const override {
    models_.on_sub_grid.add_silhouette(models_.sub_cells_of(cell).front(), camera, mask);
  }

 private:
  const SubCellModels& models_;
};

// The sub-cells hold the rendered robot (the renderer's own meshes, not the balls) anywhere in
// the cell, and their silhouettes are measurably tighter than the whole cell's. (Not a subset of
// it to the feature cell: a sub-cell's ball, placed half a sub-cell from the cell's centre and
// grown by the sub-cell's chord, can reach out of the cell's ball by a sliver, of order r h^3.)
// Control: the corner sub-cell of 4 per joint misses rendered pixels of configurations elsewhere
// in the cell.
TEST(ModelSilhouettes, SubCellSilhouettesHoldTheRenderedRobotAndAreTighter) {
  const SubCellModels models;
  test::expect_silhouettes_hold_rendered_robot(models.cell, models.grid, models.sub_cells, 30);
  const SubCellModels quarters(4);
  EXPECT_GT(
      test::uncovered_robot_pixels(quarters.cell, quarters.grid, FirstSubCellOnly(quarters), 30)
          .count,
      0u)
      << "control: a silhouette of one sub-cell must miss the robot elsewhere in the cell";
  test::PropertyRun run(200);
  std::size_t sub_count = 0;
  std::size_t whole_count = 0;
  const std::size_t cameras = models.cell.cameras.size();
  for (int i = 0; i < run.iterations(); ++i) {
    const auto index = static_cast<CellIndex>(run.rng()() % models.grid.cell_count());
    std::vector<FeatureMask> sub(cameras, FeatureMask(models.cell.feature_grid));
    std::vector<FeatureMask> whole(cameras, FeatureMask(models.cell.feature_grid));
    models.sub_cells.add_silhouettes(index, sub);
    models.whole_cells.add_silhouettes(index, whole);
    for (std::size_t camera = 0; camera < cameras; ++camera) {
      sub_count += sub[camera].count();
      whole_count += whole[camera].count();
    }
  }
  EXPECT_LT(static_cast<double>(sub_count), 0.9 * static_cast<double>(whole_count))
      << sub_count << " feature cells from sub-cells, " << whole_count << " from whole cells";
}

}  // namespace
}  // namespace safecell

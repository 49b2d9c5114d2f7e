#include "safecell/explain/cell_explanation.hpp"

#include <stdexcept>

namespace safecell {
namespace {

// Whether the LUT-2 entry of `pixel` holds `cell`.
bool entry_holds(const PixelToCellsTable& table, std::size_t pixel, CellIndex cell) {
  bool holds = false;
  table.for_each_cell_run(pixel, [&](CellIndex first, std::uint32_t length) {
    holds = holds || (cell >= first && cell - first < length);
  });
  return holds;
}

// The feature cells of `pixels` whose entry holds `cell`.
std::vector<FeatureCell> cells_marking(const PixelToCellsTable& table, const FeatureMask& pixels,
                                       CellIndex cell) {
  std::vector<FeatureCell> marking;
  pixels.for_each_set([&](int column, int row) {
    const std::size_t pixel =
        static_cast<std::size_t>(row) * static_cast<std::size_t>(pixels.columns()) +
        static_cast<std::size_t>(column);
    if (entry_holds(table, pixel, cell)) marking.push_back(FeatureCell{column, row});
  });
  return marking;
}

std::string feature_cells_text(const std::vector<FeatureCell>& cells, std::size_t at_most) {
  std::string text;
  for (std::size_t k = 0; k < cells.size() && k < at_most; ++k) {
    text += " (" + std::to_string(cells[k].column) + "," + std::to_string(cells[k].row) + ")";
  }
  if (cells.size() > at_most) text += " +" + std::to_string(cells.size() - at_most) + " more";
  return text;
}

}  // namespace

const char* to_string(ForbiddenBecause because) {
  switch (because) {
    case ForbiddenBecause::kCritical:
      return "critical";
    case ForbiddenBecause::kStatic:
      return "static";
    case ForbiddenBecause::kAllForbidden:
      return "all forbidden";
    case ForbiddenBecause::kNotForbidden:
      return "not forbidden";
    case ForbiddenBecause::kMapUnknown:
      return "map unknown";
  }
  return "unknown";
}

CellExplanation explain_cell(const ForbiddenMapFusion& fusion, const FusedViews* views,
                             CellIndex cell) {
  const LutSet& luts = fusion.luts();
  if (cell >= luts.static_cells.cell_count()) {
    throw std::out_of_range("cell " + std::to_string(cell) + " outside the grid");
  }
  CellExplanation explanation;
  explanation.cell = cell;
  if (views == nullptr) return explanation;  // kMapUnknown
  explanation.map_version = views->map_version;
  if (!views->all_forbidden.empty()) {
    explanation.because = ForbiddenBecause::kAllForbidden;
    explanation.all_forbidden = views->all_forbidden;
    return explanation;
  }
  const std::size_t cameras = fusion.camera_count();
  if (views->known.size() != cameras || views->obstacles.size() != cameras ||
      views->hidden.size() != cameras) {
    throw std::invalid_argument("views of " + std::to_string(views->known.size()) +
                                " cameras, the fusion has " + std::to_string(cameras));
  }
  const FusionSettings& settings = fusion.settings();
  bool critical = false;
  for (std::size_t part = 0; part < fusion.part_count(); ++part) {
    PartVote vote;
    vote.part = part;
    for (std::size_t camera = 0; camera < cameras; ++camera) {
      CameraVote camera_vote;
      camera_vote.camera = camera;
      if (!views->known[camera]) {
        if (!fusion.observable(part, camera).test(cell)) continue;
        camera_vote.unknown = true;
      } else {
        const PixelToCellsTable& table = luts.cameras[camera].parts[part].pixel_to_cells;
        camera_vote.obstacle_cells = cells_marking(table, views->obstacles[camera], cell);
        if (settings.hidden_votes) {
          camera_vote.hidden_cells = cells_marking(table, views->hidden[camera], cell);
        }
        if (camera_vote.obstacle_cells.empty() && camera_vote.hidden_cells.empty()) continue;
      }
      vote.seeing += camera_vote.unknown || !camera_vote.obstacle_cells.empty() ? 1 : 0;
      vote.cameras.push_back(std::move(camera_vote));
    }
    if (vote.cameras.empty()) continue;
    // The fusion's rule (forbidden_map_fusion.hpp); without hidden votes every voter sees.
    vote.critical =
        vote.seeing >= 1 && static_cast<int>(vote.cameras.size()) >= settings.camera_threshold;
    critical = critical || vote.critical;
    explanation.parts.push_back(std::move(vote));
  }
  const bool is_static = luts.static_cells.test(cell);
  if (critical) {
    explanation.because = ForbiddenBecause::kCritical;
    explanation.also_static = is_static;
  } else {
    explanation.because = is_static ? ForbiddenBecause::kStatic : ForbiddenBecause::kNotForbidden;
  }
  return explanation;
}

std::string describe(const CellExplanation& explanation, const ForbiddenMapFusion& fusion,
                     std::size_t cells_per_camera) {
  const LutSet& luts = fusion.luts();
  std::string text = "cell " + std::to_string(explanation.cell) + " of map " +
                     std::to_string(explanation.map_version) + ": ";
  switch (explanation.because) {
    case ForbiddenBecause::kMapUnknown:
      return text + "the map is no longer kept; no explanation";
    case ForbiddenBecause::kAllForbidden:
      return text + "the whole map was forbidden (" + explanation.all_forbidden + ")";
    case ForbiddenBecause::kStatic:
      return text + "static (an obstacle of the cell file or a blind spot)";
    case ForbiddenBecause::kNotForbidden:
      return text + "not forbidden in that map";
    case ForbiddenBecause::kCritical:
      break;
  }
  text += "critical";
  if (explanation.also_static) text += " and static";
  for (const PartVote& vote : explanation.parts) {
    if (!vote.critical) continue;
    text += "; " + luts.parts.at(vote.part).name + " seen by";
    for (const CameraVote& camera : vote.cameras) {
      text += " camera '" + luts.cameras.at(camera.camera).camera + "'";
      if (camera.unknown) {
        text += " (view unknown)";
        continue;
      }
      if (!camera.obstacle_cells.empty()) {
        text += " at" + feature_cells_text(camera.obstacle_cells, cells_per_camera);
      }
      if (!camera.hidden_cells.empty()) {
        text += " hidden at" + feature_cells_text(camera.hidden_cells, cells_per_camera);
      }
    }
  }
  return text;
}

}  // namespace safecell

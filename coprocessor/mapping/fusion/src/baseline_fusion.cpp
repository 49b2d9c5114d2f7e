#include "safecell/fusion/baseline_fusion.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace safecell {

BaselineFusion::BaselineFusion(const LutSet& luts, const RobotSilhouettes& silhouettes,
                               const FusionSettings& settings)
    : luts_(luts), silhouettes_(silhouettes), settings_(settings) {
  if (silhouettes.camera_count() != luts.cameras.size() || luts.cameras.size() > 254) {
    throw std::invalid_argument("baseline fusion: camera counts of tables and silhouettes differ");
  }
  if (settings.camera_threshold < 1 ||
      static_cast<std::size_t>(settings.camera_threshold) > luts.cameras.size()) {
    throw std::invalid_argument("camera threshold " + std::to_string(settings.camera_threshold) +
                                " outside 1.." + std::to_string(luts.cameras.size()));
  }
  const std::uint32_t cells = luts.static_cells.cell_count();
  for (std::size_t part = 0; part < luts.parts.size(); ++part) {
    for (const auto& camera : luts.cameras) {
      const CellSet seen = observable_cells(camera.parts.at(part).pixel_to_cells);
      std::vector<CellIndex> list;
      for (CellIndex cell = seen.next_set(0); cell < cells; cell = seen.next_set(cell + 1)) {
        list.push_back(cell);
      }
      observable_.push_back(std::move(list));
    }
  }
  for (std::size_t camera = 0; camera < luts.cameras.size(); ++camera) {
    robot_.emplace_back(luts.columns, luts.rows);
    obstacles_.emplace_back(luts.columns, luts.rows);
    hidden_.emplace_back(luts.columns, luts.rows);
  }
  counters_.assign(cells, 0);
  stamps_.assign(cells, 0);
  forbidden_ = CellSet(cells);
  pixel_cells_ = CellSet(cells);
  seen_ = CellSet(cells);
}

void BaselineFusion::count_cell(CellIndex cell, std::uint8_t camera_stamp) {
  if (stamps_[cell] == camera_stamp) return;
  stamps_[cell] = camera_stamp;
  ++counters_[cell];
}

void BaselineFusion::count_pixels(const FeatureMask& pixels, const PixelToCellsTable& table,
                                  std::uint8_t camera_stamp, bool seen) {
  pixels.for_each_set([&](int column, int row) {
    const std::size_t pixel =
        static_cast<std::size_t>(row) * static_cast<std::size_t>(pixels.columns()) +
        static_cast<std::size_t>(column);
    // The pixel's cells each once, as the paper's list holds them: its runs may overlap, so they
    // are gathered first.
    pixel_cells_.clear();
    table.add_cells(pixel, pixel_cells_);
    if (seen) seen_ |= pixel_cells_;
    const std::vector<std::uint64_t>& words = pixel_cells_.words();
    for (std::size_t word = 0; word < words.size(); ++word) {
      for (std::uint64_t bits = words[word]; bits != 0; bits &= bits - 1) {
        count_cell(
            static_cast<CellIndex>(word * 64 + static_cast<std::size_t>(std::countr_zero(bits))),
            camera_stamp);
      }
    }
  });
}

const CellSet& BaselineFusion::fuse(const std::vector<CameraObservation>& observations,
                                    CellIndex robot_cell) {
  if (observations.size() != luts_.cameras.size()) {
    throw std::invalid_argument("baseline fusion: wrong number of camera observations");
  }
  if (robot_cell >= counters_.size()) throw std::out_of_range("robot cell outside the grid");
  remove_robot_from_views(observations, {silhouettes_, nullptr, robot_cell, {}}, settings_,
                          {robot_, obstacles_, hidden_});
  forbidden_ = luts_.static_cells;
  const auto threshold = static_cast<std::uint8_t>(settings_.camera_threshold);
  const std::size_t cameras = observations.size();
  for (std::size_t part = 0; part < luts_.parts.size(); ++part) {
    std::fill(counters_.begin(), counters_.end(), 0);
    std::fill(stamps_.begin(), stamps_.end(), 0);
    seen_.clear();
    for (std::size_t camera = 0; camera < cameras; ++camera) {
      const auto stamp = static_cast<std::uint8_t>(camera + 1);
      if (!observations[camera].known) {
        for (const CellIndex cell : observable_[part * cameras + camera]) {
          count_cell(cell, stamp);
          seen_.set(cell);
        }
        continue;
      }
      const PixelToCellsTable& table = luts_.cameras[camera].parts[part].pixel_to_cells;
      count_pixels(obstacles_[camera], table, stamp, true);
      // Hidden pixels count the camera too (none without hidden votes); they see nothing.
      count_pixels(hidden_[camera], table, stamp, false);
    }
    for (CellIndex cell = 0; cell < counters_.size(); ++cell) {
      // Without hidden votes every counted cell was seen.
      if (counters_[cell] >= threshold && seen_.test(cell)) forbidden_.set(cell);
    }
  }
  return forbidden_;
}

}  // namespace safecell

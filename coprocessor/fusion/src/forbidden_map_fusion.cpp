#include "safecell/fusion/forbidden_map_fusion.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

#include "safecell/compute/word_loops.hpp"

namespace safecell {

void count_at_least(const std::vector<std::span<const std::uint64_t>>& sets, int threshold,
                    std::vector<std::vector<std::uint64_t>>& scratch,
                    std::vector<std::uint64_t>& result) {
  if (threshold < 1) throw std::invalid_argument("camera threshold must be >= 1");
  const std::size_t levels = static_cast<std::size_t>(threshold);
  const std::size_t words = result.size();
  if (scratch.size() < levels) throw std::invalid_argument("count_at_least: too little scratch");
  for (std::size_t k = 0; k < levels; ++k) {
    if (scratch[k].size() != words) throw std::invalid_argument("count_at_least: scratch size");
    std::fill(scratch[k].begin(), scratch[k].end(), 0);
  }
  for (const auto set : sets) {
    if (set.size() != words) throw std::invalid_argument("count_at_least: sets of other sizes");
    const std::uint64_t* incoming = set.data();
    // Highest level first, so that each set adds at most one to a cell's count.
    for (std::size_t k = levels; k-- > 1;) {
      or_and_words(scratch[k].data(), scratch[k - 1].data(), incoming, words);
    }
    or_words(scratch[0].data(), incoming, words);
  }
  std::copy(scratch[levels - 1].begin(), scratch[levels - 1].end(), result.begin());
}

CellSet observable_cells(const PixelToCellsTable& table) {
  CellSet cells(table.cell_count());
  for (std::size_t pixel = 0; pixel < table.pixel_count(); ++pixel) table.add_cells(pixel, cells);
  return cells;
}

void remove_robot_from_views(const std::vector<CameraObservation>& observations,
                             const RobotAtExposure& where, const FusionSettings& settings,
                             std::vector<FeatureMask>& robot, std::vector<FeatureMask>& obstacles) {
  // Every camera's silhouette in one call (the robot's balls or envelope are placed once), even
  // those whose view is unknown: cheaper than asking camera by camera.
  for (FeatureMask& mask : robot) mask.clear();
  if (settings.removal == RobotRemoval::kOcclusionAware && where.at_configuration != nullptr &&
      !where.q.empty()) {
    where.at_configuration->add_silhouettes(where.q, robot);
  } else {
    where.cell_silhouettes.add_silhouettes(where.cell, robot);
  }
  for (std::size_t camera = 0; camera < observations.size(); ++camera) {
    if (!observations[camera].known) {
      obstacles[camera].clear();
      continue;
    }
    remove_robot(observations[camera].blocked, robot[camera], settings.removal, obstacles[camera],
                 settings.occlusion_reach);
  }
}

ForbiddenMapFusion::ForbiddenMapFusion(const LutSet& luts, const RobotSilhouettes& silhouettes,
                                       const FusionSettings& settings,
                                       const ConfigurationSilhouettes* at_configuration)
    : luts_(luts),
      silhouettes_(silhouettes),
      at_configuration_(at_configuration),
      settings_(settings) {
  if (silhouettes.camera_count() != luts.cameras.size()) {
    throw std::invalid_argument("robot silhouettes for " +
                                std::to_string(silhouettes.camera_count()) +
                                " cameras, tables for " + std::to_string(luts.cameras.size()));
  }
  if (settings.camera_threshold < 1 ||
      static_cast<std::size_t>(settings.camera_threshold) > luts.cameras.size()) {
    throw std::invalid_argument("camera threshold " + std::to_string(settings.camera_threshold) +
                                " outside 1.." + std::to_string(luts.cameras.size()) +
                                " (the number of cameras)");
  }
  if (at_configuration != nullptr && at_configuration->camera_count() != luts.cameras.size()) {
    throw std::invalid_argument("robot silhouettes at the configuration for " +
                                std::to_string(at_configuration->camera_count()) +
                                " cameras, tables for " + std::to_string(luts.cameras.size()));
  }
  if (settings.occlusion_reach < 0) {
    throw std::invalid_argument("occlusion reach must be >= 0 feature cells, got " +
                                std::to_string(settings.occlusion_reach));
  }
  const std::uint32_t cells = luts.static_cells.cell_count();
  for (const auto& camera : luts.cameras) {
    if (camera.pixel_to_cells.cell_count() != cells) {
      throw std::invalid_argument("LUT-2 of camera '" + camera.camera + "' is of another grid");
    }
    for (const auto& neighbour : camera.differences) {
      if (neighbour.size() > camera.pixel_blocks.size() + 1) {
        throw std::invalid_argument("LUT-2 of camera '" + camera.camera +
                                    "' has differences for levels it lacks");
      }
      for (std::size_t level = 0; level < neighbour.size(); ++level) {
        const PixelToCellsTable& entries = camera.entries_of_level(level);
        const PixelToCellsTable& differences = neighbour[level];
        if (differences.cell_count() != cells || differences.columns() != entries.columns() ||
            differences.rows() != entries.rows()) {
          throw std::invalid_argument("LUT-2 differences of camera '" + camera.camera +
                                      "' at level " + std::to_string(level) +
                                      " do not fit its entries");
        }
      }
    }
    suspicious_lines_.emplace_back(camera.pixel_to_cells.axes(), cells);
    observable_lines_.emplace_back(camera.pixel_to_cells.axes(), cells);
    for (std::size_t pixel = 0; pixel < camera.pixel_to_cells.pixel_count(); ++pixel) {
      camera.pixel_to_cells.add_cells(pixel, observable_lines_.back());
    }
    observable_.emplace_back(cells);
    observable_lines_.back().pack_into(observable_.back());  // folds it, too
    robot_.emplace_back(luts.columns, luts.rows);
    obstacles_.emplace_back(luts.columns, luts.rows);
    remaining_.emplace_back(luts.columns, luts.rows);
  }
  camera_lines_.reserve(luts.cameras.size());
  const std::size_t words = observable_lines_.front().lines().size();
  at_least_.assign(static_cast<std::size_t>(settings.camera_threshold),
                   std::vector<std::uint64_t>(words, 0));
  critical_lines_.assign(words, 0);
  critical_ = CellSet(cells);
  forbidden_ = CellSet(cells);
  counts_.obstacle_pixels.assign(luts.cameras.size(), 0);
  counts_.saturated.assign(luts.cameras.size(), false);
}

CellSet ForbiddenMapFusion::suspicious(std::size_t camera) const {
  CellSet cells(critical_.cell_count());
  suspicious_lines_.at(camera).pack_lines(suspicious_lines_.at(camera).lines(), cells);
  return cells;
}

void ForbiddenMapFusion::check(const std::vector<CameraObservation>& observations) const {
  if (observations.size() != luts_.cameras.size()) {
    throw std::invalid_argument(std::to_string(observations.size()) + " camera observations for " +
                                std::to_string(luts_.cameras.size()) + " cameras");
  }
  for (std::size_t camera = 0; camera < observations.size(); ++camera) {
    const auto& blocked = observations[camera].blocked;
    if (observations[camera].known &&
        (blocked.columns() != luts_.columns || blocked.rows() != luts_.rows)) {
      throw std::invalid_argument("camera '" + luts_.cameras[camera].camera +
                                  "': blocked mask of " + std::to_string(blocked.columns()) +
                                  " x " + std::to_string(blocked.rows()) +
                                  " cells, the tables have " + std::to_string(luts_.columns) +
                                  " x " + std::to_string(luts_.rows));
    }
  }
}

bool ForbiddenMapFusion::back_project(std::size_t camera) {
  CellLines& suspicious = suspicious_lines_[camera];
  suspicious.clear();
  const CameraLuts& tables = luts_.cameras[camera];
  FeatureMask& remaining = remaining_[camera];
  remaining = obstacles_[camera];
  // Once the set holds every cell the camera can see, no pixel can add to it. Testing that costs
  // about two passes over the set (fold and compare), so it is done each time twice as many lines
  // have been written (tried on the benchmark scenes: checking 4 or 16 times as often costs more
  // than it saves, half as often gains nothing).
  std::size_t lines_since_check = 0;
  const auto add = [&](const PixelToCellsTable& table, std::size_t entry) {
    lines_since_check += table.add_cells(entry, suspicious);
    if (lines_since_check < 2 * suspicious.line_count()) return false;
    lines_since_check = 0;
    return suspicious.contains(observable_lines_[camera]);
  };
  const FeatureMask& obstacles = obstacles_[camera];
  // An entry whose left or upper neighbour (of its level) is all obstacles adds only its
  // difference to it, the shorter where both are: the neighbour's cells are in the set already -
  // it came earlier in this level's row order, or lay inside a coarser block added before (blocks
  // are aligned, so it is wholly in one or not).
  const auto table_for = [&tables](std::size_t level, std::size_t entry, bool left_is_in,
                                   bool upper_is_in) -> const PixelToCellsTable& {
    const PixelToCellsTable* cheapest = &tables.entries_of_level(level);
    const bool is_in[kNeighbourCount] = {left_is_in, upper_is_in};
    for (std::size_t n = 0; n < kNeighbourCount; ++n) {
      if (!is_in[n] || level >= tables.differences[n].size()) continue;
      const PixelToCellsTable& difference = tables.differences[n][level];
      if (difference.entry_bytes(entry) < cheapest->entry_bytes(entry)) cheapest = &difference;
    }
    return *cheapest;
  };
  // Whole blocks first, the coarsest level first: a block's cells are the union of its pixels'.
  for (std::size_t level = tables.pixel_blocks.size(); level >= 1; --level) {
    const int size = 1 << level;
    const auto block_rect = [size](int x, int y) {
      return FeatureRect{static_cast<std::uint16_t>(x * size), static_cast<std::uint16_t>(y * size),
                         static_cast<std::uint16_t>(x * size + size - 1),
                         static_cast<std::uint16_t>(y * size + size - 1)};
    };
    const auto columns = static_cast<std::size_t>(tables.entries_of_level(level).columns());
    const bool saturated = remaining.for_each_full_block(size, [&](int x, int y) {
      const std::size_t entry = static_cast<std::size_t>(y) * columns + static_cast<std::size_t>(x);
      if (add(table_for(level, entry, x > 0 && obstacles.all_in_rect(block_rect(x - 1, y)),
                        y > 0 && obstacles.all_in_rect(block_rect(x, y - 1))),
              entry)) {
        return true;
      }
      remaining.reset_rect(block_rect(x, y));
      return false;
    });
    if (saturated) return true;
  }
  for (int row = 0; row < remaining.rows(); ++row) {
    const std::uint64_t* words = remaining.row_words(row);
    for (int word = 0; word < remaining.words_per_row(); ++word) {
      for (std::uint64_t bits = words[word]; bits != 0; bits &= bits - 1) {
        const int column = word * 64 + std::countr_zero(bits);
        const std::size_t entry =
            static_cast<std::size_t>(row) * static_cast<std::size_t>(luts_.columns) +
            static_cast<std::size_t>(column);
        if (add(table_for(0, entry, column > 0 && obstacles.test(column - 1, row),
                          row > 0 && obstacles.test(column, row - 1)),
                entry)) {
          return true;
        }
      }
    }
  }
  return false;
}

const CellSet& ForbiddenMapFusion::fuse(const std::vector<CameraObservation>& observations,
                                        CellIndex robot_cell, std::span<const double> q) {
  check(observations);
  if (robot_cell >= critical_.cell_count()) {
    throw std::out_of_range("robot cell " + std::to_string(robot_cell) + " outside the grid");
  }
  remove_robot_from_views(observations, {silhouettes_, at_configuration_, robot_cell, q}, settings_,
                          robot_, obstacles_);
  camera_lines_.clear();
  for (std::size_t camera = 0; camera < observations.size(); ++camera) {
    if (!observations[camera].known) {
      suspicious_lines_[camera].clear();
      counts_.obstacle_pixels[camera] = 0;
      counts_.saturated[camera] = false;
      camera_lines_.push_back(observable_lines_[camera].lines());
      continue;
    }
    counts_.saturated[camera] = back_project(camera);
    suspicious_lines_[camera].fold();
    counts_.obstacle_pixels[camera] = obstacles_[camera].count();
    camera_lines_.push_back(suspicious_lines_[camera].lines());
  }
  // Counted in the line layout, so that only the result is packed.
  count_at_least(camera_lines_, settings_.camera_threshold, at_least_, critical_lines_);
  observable_lines_.front().pack_lines(critical_lines_, critical_);
  forbidden_.words() = critical_.words();
  forbidden_ |= luts_.static_cells;
  counts_.critical_cells = critical_.count();
  counts_.forbidden_cells = forbidden_.count();
  return forbidden_;
}

}  // namespace safecell

#include "safecell/fusion/forbidden_map_fusion.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

#include "safecell/compute/word_loops.hpp"

namespace safecell {

bool or_at_least(const std::vector<std::span<const std::uint64_t>>& sets, int threshold,
                 std::span<const std::uint64_t> mask,
                 std::vector<std::vector<std::uint64_t>>& scratch, std::span<std::uint64_t> into,
                 std::size_t block_words) {
  if (threshold < 1) throw std::invalid_argument("camera threshold must be >= 1");
  if (block_words == 0) throw std::invalid_argument("or_at_least: a block of no words");
  const std::size_t levels = static_cast<std::size_t>(threshold);
  const std::size_t words = into.size();
  if (scratch.size() < levels) throw std::invalid_argument("or_at_least: too little scratch");
  for (const auto set : sets) {
    if (set.size() != words) throw std::invalid_argument("or_at_least: sets of other sizes");
  }
  if (!mask.empty() && mask.size() != words) {
    throw std::invalid_argument("or_at_least: a mask of another size");
  }
  for (std::size_t k = 0; k < levels; ++k) scratch[k].resize(block_words);
  bool any = false;
  for (std::size_t first = 0; first < words; first += block_words) {
    const std::size_t length = std::min(block_words, words - first);
    for (std::size_t k = 0; k < levels; ++k) std::fill_n(scratch[k].begin(), length, 0);
    for (const auto set : sets) {
      const std::uint64_t* incoming = set.data() + first;
      // Highest level first, so that each set adds at most one to a cell's count.
      for (std::size_t k = levels; k-- > 1;) {
        or_and_words(scratch[k].data(), scratch[k - 1].data(), incoming, length);
      }
      or_words(scratch[0].data(), incoming, length);
    }
    std::uint64_t* counted = scratch[levels - 1].data();
    if (!mask.empty()) and_words(counted, mask.data() + first, length);
    any = or_words_any(into.data() + first, counted, length) || any;
  }
  return any;
}

CellSet observable_cells(const PixelToCellsTable& table) {
  CellSet cells(table.cell_count());
  for (std::size_t pixel = 0; pixel < table.pixel_count(); ++pixel) table.add_cells(pixel, cells);
  return cells;
}

void remove_robot_from_views(const std::vector<CameraObservation>& observations,
                             const RobotAtExposure& where, const FusionSettings& settings,
                             const ViewsWithoutRobot& views) {
  // Every camera's silhouette in one call (the robot's balls or envelope are placed once), even
  // those whose view is unknown: cheaper than asking camera by camera.
  for (FeatureMask& mask : views.robot) mask.clear();
  if (settings.removal == RobotRemoval::kOcclusionAware && where.at_configuration != nullptr &&
      !where.q.empty()) {
    where.at_configuration->add_silhouettes(where.q, views.robot);
  } else {
    where.cell_silhouettes.add_silhouettes(where.cell, views.robot);
  }
  for (std::size_t camera = 0; camera < observations.size(); ++camera) {
    FeatureMask& obstacles = views.obstacles[camera];
    FeatureMask& hidden = views.hidden[camera];
    if (!observations[camera].known) {
      obstacles.clear();
      hidden.clear();
      continue;
    }
    const FeatureMask& blocked = observations[camera].blocked;
    remove_robot(blocked, views.robot[camera], settings.removal, obstacles,
                 settings.occlusion_reach);
    if (!settings.hidden_votes) {
      hidden.clear();
      continue;
    }
    hidden = blocked;  // same size after the first cycle: no allocation
    hidden &= views.robot[camera];
    hidden.subtract(obstacles);
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
  if (luts.parts.empty()) throw std::invalid_argument("the tables name no robot part");
  const std::uint32_t cells = luts.static_cells.cell_count();
  const std::size_t cameras = luts.cameras.size();
  observable_.resize(luts.parts.size() * cameras);
  for (std::size_t part = 0; part < luts.parts.size(); ++part) {
    for (std::size_t camera = 0; camera < cameras; ++camera) {
      const std::string& name = luts.cameras[camera].camera;
      if (luts.cameras[camera].parts.size() != luts.parts.size()) {
        throw std::invalid_argument("camera '" + name + "' has LUT-2 for " +
                                    std::to_string(luts.cameras[camera].parts.size()) +
                                    " robot parts, the set names " +
                                    std::to_string(luts.parts.size()));
      }
      const PartLuts& tables = luts.cameras[camera].parts[part];
      const std::string where = "LUT-2 of camera '" + name + "', part '" + luts.parts[part].name;
      if (tables.pixel_to_cells.cell_count() != cells ||
          tables.pixel_to_cells.columns() != luts.columns ||
          tables.pixel_to_cells.rows() != luts.rows) {
        throw std::invalid_argument(where + "' is of another grid");
      }
      for (const auto& neighbour : tables.differences) {
        if (neighbour.size() > tables.pixel_blocks.size() + 1) {
          throw std::invalid_argument(where + "' has differences for levels it lacks");
        }
        for (std::size_t level = 0; level < neighbour.size(); ++level) {
          const PixelToCellsTable& entries = tables.entries_of_level(level);
          const PixelToCellsTable& differences = neighbour[level];
          if (differences.cell_count() != cells || differences.columns() != entries.columns() ||
              differences.rows() != entries.rows()) {
            throw std::invalid_argument(where + "': differences at level " + std::to_string(level) +
                                        " do not fit its entries");
          }
        }
      }
      suspicious_lines_.emplace_back(tables.pixel_to_cells.axes(), cells);
      observable_lines_.emplace_back(tables.pixel_to_cells.axes(), cells);
      // What the camera sees of the part: the union of the coarsest level's entries, which is
      // the union of all pixels' (a block holds its pixels' cells) at a fraction of the work.
      const PixelToCellsTable& coarsest = tables.entries_of_level(tables.pixel_blocks.size());
      for (std::size_t entry = 0; entry < coarsest.pixel_count(); ++entry) {
        coarsest.add_cells(entry, observable_lines_.back());
      }
      FeatureMask reach(luts.columns, luts.rows);
      for (std::size_t pixel = 0; pixel < tables.pixel_to_cells.pixel_count(); ++pixel) {
        if (tables.pixel_to_cells.entry_bytes(pixel) == 0) continue;
        reach.set(static_cast<int>(pixel % static_cast<std::size_t>(luts.columns)),
                  static_cast<int>(pixel / static_cast<std::size_t>(luts.columns)));
      }
      reach_.push_back(std::move(reach));
      CellSet& seen = observable_[slot(part, camera)];
      seen = CellSet(cells);
      observable_lines_.back().pack_into(seen);  // folds it, too
    }
  }
  for (std::size_t camera = 0; camera < cameras; ++camera) {
    observable_any_part_.emplace_back(cells);
    for (std::size_t part = 0; part < luts.parts.size(); ++part) {
      observable_any_part_.back() |= observable_[slot(part, camera)];
    }
    robot_.emplace_back(luts.columns, luts.rows);
    obstacles_.emplace_back(luts.columns, luts.rows);
    hidden_.emplace_back(luts.columns, luts.rows);
    remaining_.emplace_back(luts.columns, luts.rows);
    if (settings.hidden_votes) voting_lines_.push_back(observable_lines_.front());
  }
  camera_lines_.reserve(cameras);
  seeing_.assign(cameras, false);
  hiding_.assign(cameras, false);
  voting_.assign(cameras, false);
  const std::size_t words = observable_lines_.front().lines().size();
  seen_lines_.assign(words, 0);
  at_least_.assign(static_cast<std::size_t>(settings.camera_threshold),
                   std::vector<std::uint64_t>(kAtLeastBlockWords, 0));
  critical_lines_ = observable_lines_.front();
  critical_lines_.clear();
  vote_sets_.assign(cameras, nullptr);
  suspect_sets_.assign(cameras, nullptr);
  for (std::size_t part = 0; part < luts.parts.size(); ++part) {
    camera_lines_.clear();
    for (std::size_t camera = 0; camera < cameras; ++camera) {
      camera_lines_.push_back(observable_lines_[slot(part, camera)].lines());
    }
    votable_lines_.emplace_back(words, 0);
    or_at_least(camera_lines_, settings.camera_threshold, {}, at_least_, votable_lines_.back());
  }
  camera_lines_.clear();
  critical_ = CellSet(cells);
  forbidden_ = CellSet(cells);
  counts_.obstacle_pixels.assign(cameras, 0);
  counts_.hidden_pixels.assign(cameras, 0);
  counts_.saturated.assign(luts.parts.size() * cameras, false);
  counts_.part_voted.assign(luts.parts.size(), false);
  counts_.part_critical.assign(luts.parts.size(), false);
  counts_.part_covered.assign(luts.parts.size(), false);
}

CellSet ForbiddenMapFusion::suspicious(std::size_t part, std::size_t camera) const {
  const CellLines& lines = suspicious_lines_.at(slot(part, camera));
  CellSet cells(critical_.cell_count());
  // After forbid_all the lines are the last vote's; no part was voted on since.
  if (!counts_.part_voted.at(part)) return cells;
  if (lines.folded()) {
    lines.pack_lines(lines.lines(), cells);
    return cells;
  }
  CellLines whole = lines;  // voted on at a lower level: folded here, for explanations only
  whole.pack_into(cells);
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

ForbiddenMapFusion::VoterCounts ForbiddenMapFusion::find_voters(
    const std::vector<CameraObservation>& observations, std::size_t part) {
  VoterCounts counts;
  for (std::size_t camera = 0; camera < observations.size(); ++camera) {
    const FeatureMask& reach = reach_[slot(part, camera)];
    const bool unknown = !observations[camera].known;
    seeing_[camera] = unknown || obstacles_[camera].intersects(reach);
    hiding_[camera] = !unknown && settings_.hidden_votes && hidden_[camera].intersects(reach);
    voting_[camera] = seeing_[camera] || hiding_[camera];
    counts.seeing += seeing_[camera] ? 1U : 0U;
    counts.voting += voting_[camera] ? 1U : 0U;
  }
  return counts;
}

bool ForbiddenMapFusion::back_project(std::size_t part, std::size_t camera,
                                      const FeatureMask& pixels, const FeatureMask& present,
                                      CellLines& into) {
  CellLines& suspicious = into;
  const PartLuts& tables = luts_.cameras[camera].parts[part];
  CellLines& observable = observable_lines_[slot(part, camera)];
  FeatureMask& remaining = remaining_[camera];
  remaining = pixels;
  // Once the set holds every cell the camera can see, no pixel can add to it. Testing that costs
  // about two passes over the set (fold and compare), so it is done each time twice as many lines
  // have been written (tried on the benchmark scenes: checking 4 or 16 times as often costs more
  // than it saves, half as often gains nothing).
  std::size_t lines_since_check = 0;
  const auto add = [&](const PixelToCellsTable& table, std::size_t entry) {
    lines_since_check += table.add_cells(entry, suspicious);
    if (lines_since_check < 2 * suspicious.line_count()) return false;
    lines_since_check = 0;
    return suspicious.contains(observable);
  };
  const FeatureMask& obstacles = present;
  // An entry whose left or upper neighbour (of its level) is all present adds only its
  // difference to it, the shorter where both are: every pixel of the neighbour has its cells in
  // the set by the end of the call (it was there before, or is added in this call, as part of
  // some block or alone), so the union comes out whole whatever the order.
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
  remove_robot(observations, robot_cell, q);
  return vote(observations);
}

void ForbiddenMapFusion::remove_robot(const std::vector<CameraObservation>& observations,
                                      CellIndex robot_cell, std::span<const double> q) {
  removed_from_ = nullptr;
  check(observations);
  if (robot_cell >= critical_.cell_count()) {
    throw std::out_of_range("robot cell " + std::to_string(robot_cell) + " outside the grid");
  }
  remove_robot_from_views(observations, {silhouettes_, at_configuration_, robot_cell, q}, settings_,
                          {robot_, obstacles_, hidden_});
  for (std::size_t camera = 0; camera < observations.size(); ++camera) {
    const bool known = observations[camera].known;
    counts_.obstacle_pixels[camera] = known ? obstacles_[camera].count() : std::size_t{0};
    counts_.hidden_pixels[camera] = known ? hidden_[camera].count() : std::size_t{0};
  }
  removed_from_ = &observations;
}

const CellSet& ForbiddenMapFusion::forbid_all() {
  removed_from_ = nullptr;
  std::fill(counts_.saturated.begin(), counts_.saturated.end(), false);
  std::fill(counts_.part_voted.begin(), counts_.part_voted.end(), false);
  std::fill(counts_.part_critical.begin(), counts_.part_critical.end(), false);
  std::fill(counts_.part_covered.begin(), counts_.part_covered.end(), false);
  critical_.clear();
  forbidden_.fill();
  counts_.critical_cells = 0;
  counts_.forbidden_cells = forbidden_.count();
  return forbidden_;
}

const CellSet& ForbiddenMapFusion::vote(const std::vector<CameraObservation>& observations) {
  // The obstacles must be this cycle's, of these observations: a vote on others would be a silent
  // wrong map.
  if (removed_from_ != &observations) {
    throw std::logic_error("fusion vote without robot removal from these observations this cycle");
  }
  removed_from_ = nullptr;
  check(observations);  // the same object, but its masks may have changed since
  critical_lines_.clear();
  const auto threshold = static_cast<std::size_t>(settings_.camera_threshold);
  const bool hidden_votes = settings_.hidden_votes;
  bool any_critical = false;
  for (std::size_t part = 0; part < luts_.parts.size(); ++part) {
    const VoterCounts voters = find_voters(observations, part);
    counts_.part_voted[part] = voters.seeing >= 1 && voters.voting >= threshold;
    counts_.part_critical[part] = false;
    if (counts_.part_voted[part] && any_critical) critical_lines_.fold();
    counts_.part_covered[part] =
        counts_.part_voted[part] && any_critical &&
        !any_missing(critical_lines_.lines().data(), votable_lines_[part].data(),
                     critical_lines_.lines().size());
    const bool voted = counts_.part_voted[part] && !counts_.part_covered[part];
    std::fill(vote_sets_.begin(), vote_sets_.end(), nullptr);
    std::fill(suspect_sets_.begin(), suspect_sets_.end(), nullptr);
    for (std::size_t camera = 0; camera < observations.size(); ++camera) {
      const std::size_t at = slot(part, camera);
      CellLines& suspicious = suspicious_lines_[at];
      suspicious.clear();
      counts_.saturated[at] = false;
      if (!voted || !voting_[camera]) continue;
      if (!observations[camera].known) {
        vote_sets_[camera] = suspect_sets_[camera] = &observable_lines_[at];
        continue;
      }
      if (seeing_[camera]) {
        counts_.saturated[at] =
            back_project(part, camera, obstacles_[camera], obstacles_[camera], suspicious);
      }
      suspect_sets_[camera] = &suspicious;
      if (!hiding_[camera] || counts_.saturated[at]) {
        vote_sets_[camera] = &suspicious;
        continue;
      }
      // Suspicious or hidden: what the camera sees, then what its robot pixels may hide (all
      // its blocked pixels are then in the set).
      CellLines& voting = voting_lines_[camera];
      voting = suspicious;
      back_project(part, camera, hidden_[camera], observations[camera].blocked, voting);
      vote_sets_[camera] = &voting;
    }
    if (!voted) continue;
    // The vote is counted at the highest level any set was written at: the same bits as in the
    // full grid (folding copies lines along the axes above, and counting works bit by bit), for
    // a part moved by the first joints a fraction of the work; the result is folded once, with
    // the other parts', before the map is packed.
    std::uint32_t level = 1;
    for (std::size_t camera = 0; camera < observations.size(); ++camera) {
      for (const CellLines* set : {vote_sets_[camera], suspect_sets_[camera]}) {
        if (set != nullptr) level = std::max(level, set->written_through());
      }
    }
    // With hidden votes some camera must see an obstacle through the part: the cells are masked
    // with what the cameras suspect. Where every camera votes with what it suspects, that mask
    // holds every cell one camera votes for, so it would change nothing and is not made.
    bool some_vote_hidden = false;
    for (std::size_t camera = 0; camera < observations.size(); ++camera) {
      some_vote_hidden = some_vote_hidden || vote_sets_[camera] != suspect_sets_[camera];
    }
    camera_lines_.clear();
    std::span<std::uint64_t> seen;
    if (hidden_votes && some_vote_hidden) {
      seen = std::span<std::uint64_t>(seen_lines_).first(critical_lines_.level_lines(level).size());
      std::fill(seen.begin(), seen.end(), 0);
    }
    for (std::size_t camera = 0; camera < observations.size(); ++camera) {
      if (vote_sets_[camera] == nullptr) continue;
      vote_sets_[camera]->fold_to(level);
      suspect_sets_[camera]->fold_to(level);
      camera_lines_.push_back(vote_sets_[camera]->level_lines(level));
      if (!seen.empty()) {
        or_words(seen.data(), suspect_sets_[camera]->level_lines(level).data(), seen.size());
      }
    }
    counts_.part_critical[part] =
        or_at_least(camera_lines_, settings_.camera_threshold, seen, at_least_,
                    critical_lines_.level_lines_to_add_to(level));
    any_critical = any_critical || counts_.part_critical[part];
  }
  critical_lines_.pack_into(critical_);
  counts_.critical_cells = critical_.count();
  counts_.forbidden_cells = forbidden_.assign_union(critical_, luts_.static_cells);
  return forbidden_;
}

}  // namespace safecell

#include "safecell/fusion/robot_removal.hpp"

#include <stdexcept>
#include <utility>

namespace safecell {
namespace {

// One 8-neighbour dilation step of `from`, limited to `within` and to cells not yet in `into`:
// the new cells are written to `grown` and added to `into`. Returns whether there were any.
bool grow_within(const FeatureMask& from, const FeatureMask& within, FeatureMask& into,
                 FeatureMask& grown) {
  bool grew = false;
  const int words = from.words_per_row();
  for (int row = 0; row < from.rows(); ++row) {
    for (int word = 0; word < words; ++word) {
      std::uint64_t reach = 0;
      for (int source_row = row - 1; source_row <= row + 1; ++source_row) {
        if (source_row < 0 || source_row >= from.rows()) continue;
        const std::uint64_t* source = from.row_words(source_row);
        const std::uint64_t centre = source[word];
        // Bits move one column left and right; the neighbouring words feed the edge bits.
        const std::uint64_t from_left = word > 0 ? source[word - 1] >> 63 : 0;
        const std::uint64_t from_right = word + 1 < words ? source[word + 1] << 63 : 0;
        reach |= centre | (centre << 1) | from_left | (centre >> 1) | from_right;
      }
      const std::uint64_t added = reach & within.row_words(row)[word] & ~into.row_words(row)[word];
      grown.row_words(row)[word] = added;
      grew = grew || added != 0;
    }
  }
  into |= grown;
  return grew;
}

}  // namespace

const char* to_string(RobotRemoval removal) {
  switch (removal) {
    case RobotRemoval::kOcclusionAware:
      return "occlusion-aware";
    case RobotRemoval::kPlain:
      return "plain";
  }
  return "unknown";
}

void remove_robot(const FeatureMask& blocked, const FeatureMask& silhouette, RobotRemoval removal,
                  FeatureMask& obstacles, int reach) {
  if (blocked.columns() != silhouette.columns() || blocked.rows() != silhouette.rows()) {
    throw std::invalid_argument("robot removal: blocked mask and silhouette differ in size");
  }
  if (reach < 0) throw std::invalid_argument("occlusion reach must be >= 0 feature cells");
  obstacles = blocked;
  obstacles.subtract(silhouette);
  if (removal == RobotRemoval::kPlain || !obstacles.any()) return;
  // Grow the outside blobs into the blocked part of the silhouette, one step per cell of reach.
  // Scratch masks per thread: after the first call of a size this allocates nothing.
  thread_local FeatureMask hidden;
  thread_local FeatureMask frontier;
  thread_local FeatureMask grown;
  hidden = blocked;
  hidden &= silhouette;
  frontier = obstacles;
  grown = obstacles;
  for (int step = 0; step < reach; ++step) {
    if (!grow_within(frontier, hidden, obstacles, grown)) break;
    std::swap(frontier, grown);
  }
}

}  // namespace safecell

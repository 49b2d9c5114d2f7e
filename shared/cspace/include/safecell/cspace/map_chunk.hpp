#pragma once
// Forbidden maps and their changes cut into chunks that each fit one link frame.
//
// A chunk covers the cells [first_cell, end_cell) and carries a run list (run_coding.hpp):
//   keyframe chunk  the range is cleared, then its runs (set runs only) are set;
//   delta chunk     its runs set or clear cells; cells of the range outside every run keep their
//                   value in the base map.
// The chunks of one keyframe or delta cover the whole grid, in order, without overlap, so a
// receiver knows it has them all. Chunks are applied to a working copy, never to the map in use;
// the copy becomes the map only when every chunk arrived and the map hash matches (map_hash.hpp).
// Real-time safe: no allocation; caller storage only.

#include <cstddef>
#include <cstdint>

#include "safecell/base/status.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/cspace/run_coding.hpp"

namespace safecell {

enum class MapChunkKind : std::uint8_t { kKeyframe, kDelta };

struct MapChunkView {
  MapChunkKind kind = MapChunkKind::kKeyframe;
  CellIndex first_cell = 0;
  CellIndex end_cell = 0;
  const std::uint8_t* runs = nullptr;
  std::size_t runs_size = 0;
};

// Writes the next keyframe chunk of `target` from cell `from` into out[0..capacity) (capacity >=
// kMaxRunRecordBytes, checked): as many set runs as fit. Returns the chunk's end cell, where the
// next chunk starts; cell_count when the map is done. out_size receives the bytes written.
CellIndex encode_keyframe_chunk(const std::uint64_t* target, CellIndex cell_count, CellIndex from,
                                std::uint8_t* out, std::size_t capacity, std::size_t& out_size);

// The same for the delta base -> target: runs where target differs from base, with target's value.
CellIndex encode_delta_chunk(const std::uint64_t* base, const std::uint64_t* target,
                             CellIndex cell_count, CellIndex from, std::uint8_t* out,
                             std::size_t capacity, std::size_t& out_size);

// The cells an applied chunk may have changed: [begin, end), empty when begin == end.
struct CellSpan {
  CellIndex begin = 0;
  CellIndex end = 0;
};

// Checks one chunk whole without applying it: kOutOfRange for a range outside the grid or
// reversed, kInvalidArgument for a malformed run list, a run outside the range or, in a keyframe,
// a clear run. `changed`, when given, receives the span the chunk may change (as below).
Status check_map_chunk(const MapChunkView& chunk, CellIndex cell_count,
                       CellSpan* changed = nullptr);

// Applies one chunk to `words` (a map of cell_count cells). The chunk is checked whole before any
// bit changes: a range outside the grid or reversed, a malformed run list, a run outside the
// range or, in a keyframe, a clear run, are refused (kOutOfRange / kInvalidArgument) with `words`
// untouched. `changed`, when given, receives the span the chunk may have changed (a keyframe
// chunk: its whole range; a delta chunk: from its first run to its last).
Status apply_map_chunk(const MapChunkView& chunk, std::uint64_t* words, CellIndex cell_count,
                       CellSpan* changed = nullptr);

}  // namespace safecell

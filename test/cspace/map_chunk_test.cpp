// Keyframes and deltas cut into chunks: apply(diff(a, b), a) == b against a dense bitmap on random
// maps and frame sizes, and chunks that are torn, foreign or malformed leave the map untouched.

#include "safecell/cspace/map_chunk.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "safecell/cspace/cell_bits.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

using Words = std::vector<std::uint64_t>;

struct Chunk {
  MapChunkKind kind;
  CellIndex first_cell;
  CellIndex end_cell;
  std::vector<std::uint8_t> runs;
  MapChunkView view() const { return {kind, first_cell, end_cell, runs.data(), runs.size()}; }
};

// Every chunk of the keyframe of `target` (base == nullptr) or of the delta base -> target.
std::vector<Chunk> chunks_of(const Words* base, const Words& target, CellIndex cells,
                             std::size_t capacity) {
  std::vector<Chunk> chunks;
  CellIndex from = 0;
  do {
    Chunk chunk{base ? MapChunkKind::kDelta : MapChunkKind::kKeyframe, from, 0,
                std::vector<std::uint8_t>(capacity)};
    std::size_t size = 0;
    chunk.end_cell =
        base ? encode_delta_chunk(base->data(), target.data(), cells, from, chunk.runs.data(),
                                  capacity, size)
             : encode_keyframe_chunk(target.data(), cells, from, chunk.runs.data(), capacity, size);
    chunk.runs.resize(size);
    EXPECT_GT(chunk.end_cell, from == cells ? from - 1 : from) << "a chunk makes progress";
    from = chunk.end_cell;
    chunks.push_back(std::move(chunk));
  } while (from < cells);
  return chunks;
}

// A random map with runs of random lengths (so both long runs and single cells occur).
Words random_map(CellIndex cells, std::mt19937_64& rng) {
  Words words(cell_bits::words_for(cells), 0);
  CellIndex at = 0;
  const auto mean_run = static_cast<CellIndex>(1 + rng() % 300);
  bool value = rng() % 2 == 0;
  while (at < cells) {
    const CellIndex end = std::min(cells, static_cast<CellIndex>(at + 1 + rng() % (2 * mean_run)));
    if (value) cell_bits::set_range(words.data(), at, end);
    at = end;
    value = !value;
  }
  return words;
}

std::string describe(CellIndex cells, std::size_t capacity, int iteration) {
  return "cells " + std::to_string(cells) + ", capacity " + std::to_string(capacity) +
         ", iteration " + std::to_string(iteration);
}

TEST(MapChunk, KeyframeAndDeltaRebuildTheTargetMap) {
  test::PropertyRun run(200);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto cells = static_cast<CellIndex>(1 + run.rng()() % 20000);
    const std::size_t capacity = kMaxRunRecordBytes + run.rng()() % 1400;
    const Words a = random_map(cells, run.rng());
    Words b = a;  // b: a changed in a few places, as consecutive maps are
    for (int change = static_cast<int>(run.rng()() % 6); change > 0; --change) {
      const auto begin = static_cast<CellIndex>(run.rng()() % cells);
      const auto end = static_cast<CellIndex>(begin + 1 + run.rng()() % (cells - begin));
      if (run.rng()() % 2 == 0) {
        cell_bits::set_range(b.data(), begin, end);
      } else {
        cell_bits::clear_range(b.data(), begin, end);
      }
    }
    const std::string input = describe(cells, capacity, i);
    // Keyframe of b onto garbage; delta a -> b onto a.
    Words rebuilt(b.size(), 0);
    for (std::size_t w = 0; w < rebuilt.size(); ++w) rebuilt[w] = run.rng()() & a[w];
    CellIndex covered = 0;
    for (const Chunk& chunk : chunks_of(nullptr, b, cells, capacity)) {
      ASSERT_EQ(chunk.first_cell, covered) << input;
      ASSERT_EQ(apply_map_chunk(chunk.view(), rebuilt.data(), cells), Status::kOk) << input;
      covered = chunk.end_cell;
    }
    ASSERT_EQ(covered, cells) << input;
    ASSERT_EQ(rebuilt, b) << "keyframe, " << input;
    Words delta_applied = a;
    for (const Chunk& chunk : chunks_of(&a, b, cells, capacity)) {
      ASSERT_EQ(apply_map_chunk(chunk.view(), delta_applied.data(), cells), Status::kOk) << input;
    }
    ASSERT_EQ(delta_applied, b) << "delta, " << input;
  }
}

TEST(MapChunk, ANoChangeDeltaIsOneEmptyChunkOverTheGrid) {
  const Words a(2, 0x00FF00FF00FF00FFull);
  const std::vector<Chunk> chunks = chunks_of(&a, a, 128, 64);
  ASSERT_EQ(chunks.size(), 1u);
  EXPECT_EQ(chunks[0].first_cell, 0u);
  EXPECT_EQ(chunks[0].end_cell, 128u);
  EXPECT_TRUE(chunks[0].runs.empty());
}

TEST(MapChunk, ALostChunkLeavesItsRangeAtTheBase) {
  // The negative control of the receiver's "every chunk arrived" rule: skipping one chunk of a
  // delta leaves a map that differs from the target (so the hash check will refuse it).
  std::mt19937_64 rng(5);
  const CellIndex cells = 50000;
  const Words a = random_map(cells, rng);
  const Words b = random_map(cells, rng);
  const std::vector<Chunk> chunks = chunks_of(&a, b, cells, 64);
  ASSERT_GT(chunks.size(), 2u);
  Words torn = a;
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    if (c != 1) {
      ASSERT_EQ(apply_map_chunk(chunks[c].view(), torn.data(), cells), Status::kOk);
    }
  }
  EXPECT_NE(torn, b);
}

TEST(MapChunk, HostileChunksLeaveTheMapUntouched) {
  const CellIndex cells = 1000;
  Words map(cell_bits::words_for(cells), 0);
  cell_bits::set_range(map.data(), 100, 300);
  const Words before = map;
  const std::vector<std::uint8_t> good = {0x00, 0x03};            // set one cell at the range start
  const std::vector<std::uint8_t> clear = {0x00, 0x02};           // clear one cell
  const std::vector<std::uint8_t> tail_bad = {0x00, 0x03, 0x05};  // a truncated second record
  const auto apply = [&](MapChunkKind kind, CellIndex first, CellIndex end,
                         const std::vector<std::uint8_t>& runs) {
    return apply_map_chunk({kind, first, end, runs.data(), runs.size()}, map.data(), cells);
  };
  EXPECT_EQ(apply(MapChunkKind::kDelta, 0, 1001, good), Status::kOutOfRange);  // past the grid
  EXPECT_EQ(apply(MapChunkKind::kDelta, 10, 5, good), Status::kOutOfRange);    // reversed
  EXPECT_EQ(apply(MapChunkKind::kDelta, 999, 1000, {0x01, 0x03}), Status::kOutOfRange);
  EXPECT_EQ(apply(MapChunkKind::kKeyframe, 0, 1000, clear), Status::kInvalidArgument);
  EXPECT_EQ(apply(MapChunkKind::kKeyframe, 0, 1000, tail_bad), Status::kInvalidArgument);
  EXPECT_EQ(apply_map_chunk({MapChunkKind::kDelta, 0, 10, nullptr, 4}, map.data(), cells),
            Status::kInvalidArgument);
  EXPECT_EQ(map, before) << "a refused chunk changed the map";
  // The same chunk, well formed, does apply.
  EXPECT_EQ(apply(MapChunkKind::kKeyframe, 0, 1000, good), Status::kOk);
  EXPECT_EQ(cell_bits::count(map.data(), 0, cells), 1u);
}

}  // namespace
}  // namespace safecell

// The map hash: test vectors from an independent transcription of its definition
// (test/cspace/map_hash_reference.py), and the block-wise update equal to a full recomputation.

#include "safecell/cspace/map_hash.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "safecell/cspace/cell_bits.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

using Words = std::vector<std::uint64_t>;

TEST(MapHash, TestVectors) {
  Words one(1, 0);
  EXPECT_EQ(map_hash(one.data(), 1), 0xC0EE9E8082515CB5ull);

  Words hundred(cell_bits::words_for(100), 0);
  cell_bits::set(hundred.data(), 0);
  cell_bits::set_range(hundred.data(), 5, 10);
  cell_bits::set(hundred.data(), 99);
  EXPECT_EQ(map_hash(hundred.data(), 100), 0xF1FB76E20CE07441ull);

  Words three_blocks(cell_bits::words_for(10000), 0);
  cell_bits::set_range(three_blocks.data(), 4090, 4200);
  cell_bits::set(three_blocks.data(), 9999);
  EXPECT_EQ(map_hash(three_blocks.data(), 10000), 0xB8E65574F96A367Cull);

  Words partial(cell_bits::words_for(1000), 0);
  cell_bits::set_range(partial.data(), 500, 525);
  EXPECT_EQ(map_hash(partial.data(), 1000), 0xC49A16A9262C7690ull);

  Words full(cell_bits::words_for(4096), 0);
  cell_bits::set_range(full.data(), 0, 4096);
  EXPECT_EQ(map_hash(full.data(), 4096), 0x9330255D048C73D4ull);
}

// Block hashes are combined by XOR; each is keyed by its block's index, so equal blocks neither
// cancel nor trade places unnoticed.
TEST(MapHash, EqualBlocksNeitherCancelNorSwap) {
  constexpr CellIndex kCells = 2048;
  Words empty(cell_bits::words_for(kCells), 0);
  Words first = empty;
  cell_bits::set_range(first.data(), 10, 20);
  Words second = empty;
  cell_bits::set_range(second.data(), 512 + 10, 512 + 20);
  Words both = first;
  cell_bits::set_range(both.data(), 512 + 10, 512 + 20);
  EXPECT_NE(map_hash(first.data(), kCells), map_hash(second.data(), kCells));
  EXPECT_NE(map_hash(both.data(), kCells), map_hash(empty.data(), kCells));
}

TEST(MapHash, OneCellOrTheCellCountChangesIt) {
  Words map(cell_bits::words_for(9000), 0);
  const std::uint64_t empty = map_hash(map.data(), 9000);
  EXPECT_NE(map_hash(map.data(), 8999), empty);
  for (CellIndex cell : {0u, 63u, 64u, 4095u, 4096u, 8999u}) {
    cell_bits::set(map.data(), cell);
    EXPECT_NE(map_hash(map.data(), 9000), empty) << "cell " << cell;
    cell_bits::clear(map.data(), cell);
  }
}

TEST(MapHash, RefreshingTheTouchedBlocksEqualsAFullRecomputation) {
  test::PropertyRun run(100);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto cells = static_cast<CellIndex>(1 + run.rng()() % 40000);
    Words map(cell_bits::words_for(cells), 0);
    std::vector<std::uint64_t> blocks(map_hash_blocks(cells));
    MapBlockHashes hashes(blocks.data(), cells);
    hashes.refresh_all(map.data());
    for (int change = 0; change < 10; ++change) {
      const auto begin = static_cast<CellIndex>(run.rng()() % cells);
      const auto end =
          static_cast<CellIndex>(begin + 1 + run.rng()() % std::min(cells - begin, 9000u));
      cell_bits::set_range(map.data(), begin, end);
      hashes.refresh(map.data(), begin, end);
      ASSERT_EQ(hashes.map_hash(), map_hash(map.data(), cells))
          << "cells " << cells << ", set [" << begin << ", " << end << "), iteration " << i;
    }
  }
}

// The chunk's hash binds the camera counts (vectors from map_hash_reference.py); binding twice
// takes it off again, which is how the receiver checks it.
TEST(MapHash, TheCameraCountsAreBoundIntoTheChunksHash) {
  const Words one(1, 0);
  const std::uint64_t hash = map_hash(one.data(), 1);
  EXPECT_EQ(map_hash_with_cameras(hash, 4, 4), 0x01E6F9CAAC04CAD1ull);
  EXPECT_EQ(map_hash_with_cameras(hash, 3, 4), 0xBFFB77FEF6B1808Dull);
  EXPECT_EQ(map_hash_with_cameras(hash, 0, 0), 0xA37D4B9C84974469ull);
  EXPECT_EQ(map_hash_with_cameras(map_hash_with_cameras(hash, 3, 4), 3, 4), hash);
}

// And the speed reduction on top (same vectors' script); none binds nothing, so an update
// without the field hashes as before it.
TEST(MapHash, TheSpeedReductionIsBoundIntoTheChunksHash) {
  const Words one(1, 0);
  const std::uint64_t cameras = map_hash_with_cameras(map_hash(one.data(), 1), 4, 4);
  EXPECT_EQ(map_hash_with_speed_reduction(cameras, 500), 0xE8A34DDF05D6F805ull);
  EXPECT_EQ(map_hash_with_speed_reduction(cameras, 1000), 0x4C2E4499C32DE3B9ull);
  EXPECT_EQ(map_hash_with_speed_reduction(cameras, 0), cameras);
  EXPECT_EQ(map_hash_with_speed_reduction(map_hash_with_speed_reduction(cameras, 750), 750),
            cameras);
  EXPECT_NE(map_hash_with_speed_reduction(cameras, 750), map_hash_with_speed_reduction(cameras, 0));
}

}  // namespace
}  // namespace safecell

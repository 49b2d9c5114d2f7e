// The controller's map store, dense and compressed, against the dense reference (MapAssembler,
// which keeps every bit): the same chunks give the same outcomes and the same maps; with a pool
// too small for the map, the compressed store holds a superset (only forbidden cells added,
// counted), never less.

#include "safecell/controller/map_store.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "safecell/controller/host/map_store_memory.hpp"
#include "safecell/cspace/map_assembler.hpp"
#include "safecell/test/map_updates.hpp"
#include "safecell/test/property.hpp"
#include "store_receiver.hpp"

namespace safecell {
namespace {

using test::random_map;
using test::SentChunk;
using test::update_of;
using test::Words;

using test::DenseReceiver;

// Every forbidden cell of `inner` is forbidden in `outer`.
bool covers(const Words& outer, const Words& inner) {
  for (std::size_t w = 0; w < inner.size(); ++w) {
    if ((inner[w] & ~outer[w]) != 0) return false;
  }
  return true;
}

// A map with long free and forbidden stretches (whole blocks of each kind) and a few ragged
// stretches (mixed blocks), as a forbidden map of a real cell looks.
Words blocky_map(CellIndex cells, std::mt19937_64& rng) {
  Words words(cell_bits::words_for(cells), 0);
  for (CellIndex at = 0; at < cells;) {
    const CellIndex long_run = 1 + static_cast<CellIndex>(rng() % 6000);
    const CellIndex end =
        std::min(cells, at + (rng() % 4 == 0 ? 1 + static_cast<CellIndex>(rng() % 60) : long_run));
    if (rng() % 2 == 0) cell_bits::set_range(words.data(), at, end);
    at = end;
  }
  return words;
}

// A changed copy: a few stretches set or cleared.
Words changed(const Words& map, CellIndex cells, std::mt19937_64& rng) {
  Words next = map;
  const int stretches = 1 + static_cast<int>(rng() % 4);
  for (int s = 0; s < stretches; ++s) {
    const auto begin = static_cast<CellIndex>(rng() % cells);
    const auto end =
        static_cast<CellIndex>(begin + 1 + rng() % std::min<CellIndex>(cells - begin, 3000));
    if (rng() % 2 == 0) {
      cell_bits::set_range(next.data(), begin, end);
    } else {
      cell_bits::clear_range(next.data(), begin, end);
    }
  }
  return next;
}

TEST(MapStore, StartsWithNoMapAndEverythingForbidden) {
  for (const MapStoreLayout& layout :
       {MapStoreLayout::of(5000), MapStoreLayout::compressed(5000, 8)}) {
    const StoreReceiver receiver(layout);
    EXPECT_EQ(receiver.store().version(), 0u);
    EXPECT_EQ(cell_bits::count(receiver.held().data(), 0, 5000), 5000u);
    EXPECT_EQ(receiver.store().pool_blocks_used(), 0u);
  }
}

TEST(MapStore, LayoutIsSizedFromTheGridAndTheForm) {
  const MapStoreLayout compressed = MapStoreLayout::compressed(186480, 200);
  EXPECT_EQ(compressed.blocks, 365u);  // 186480 / 512 rounded up
  EXPECT_FALSE(compressed.dense);
  EXPECT_EQ(compressed.bytes(), 365u * 28 + 200u * 68);
  // The default: two sides of whole blocks and a bit per block, 128 bytes a block in all.
  const MapStoreLayout dense = MapStoreLayout::of(186480);
  EXPECT_TRUE(dense.dense);
  EXPECT_EQ(dense.pool_blocks, 0u);
  EXPECT_EQ(dense.bytes(), 2u * 365 * 64 + 6 * 8);
  // The 6 cm grid: 32,156 blocks, 4.12 MB dense against 5.27 MB for a pool of two maps.
  EXPECT_EQ(MapStoreLayout::of(16'463'480).bytes(), 2u * 32156 * 64 + 503 * 8);
  EXPECT_EQ(MapStoreLayout::compressed(16'463'480, 2 * 32156).bytes(), 32156u * (28 + 2 * 68));
}

// Offers `chunk` as the controller's link does: accept(), then work() in slices of small random
// budgets until the chunk has an outcome, and sometimes the upkeep after it too. Each slice stays
// within its budget (the last step may overdraw it by less than kWorkPerRun + kWorkPerBlock), and
// the held map stays `before` until the slice that returns kApplied.
MapOffer offer_in_slices(StoreReceiver& receiver, MapStore& store, const SentChunk& chunk,
                         std::mt19937_64& rng, const Words& before) {
  const std::uint64_t held_version = store.version();
  MapOffer offer = store.accept(chunk.header, chunk.runs.data(), chunk.runs.size(), 1);
  const bool upkeep_too = rng() % 2 == 0;
  while (offer.outcome == MapOutcome::kWorking || (upkeep_too && store.busy())) {
    const auto budget = static_cast<std::uint32_t>(1 + rng() % 24);
    std::uint32_t left = budget;
    const std::uint64_t done = store.work_done();
    const MapOffer slice = store.work(left);
    EXPECT_LT(store.work_done() - done, std::uint64_t{budget} + kWorkPerRun + kWorkPerBlock);
    if (offer.outcome == MapOutcome::kWorking) offer = slice;
    if (offer.outcome == MapOutcome::kWorking) {
      EXPECT_EQ(store.version(), held_version);
      EXPECT_EQ(receiver.held(), before);
    }
  }
  return offer;
}

// The same stream of chunks, with faults, to the store and to the dense reference: equal outcomes
// and equal maps after every chunk, while the pool has room. `sliced`: the store works in slices.
// `dense`: the store's dense form, else the compressed form with a pool of two maps.
void matches_the_dense_reference(bool sliced, bool dense_form) {
  test::PropertyRun run(sliced ? 20 : 40);
  for (int i = 0; i < run.iterations(); ++i) {
    auto& rng = run.rng();
    const auto cells = static_cast<CellIndex>(1 + rng() % 60000);
    const std::size_t capacity = kMaxRunRecordBytes + rng() % 400;
    StoreReceiver store(dense_form
                            ? MapStoreLayout::of(cells)
                            : MapStoreLayout::compressed(cells, store_blocks_for(cells) * 2));
    DenseReceiver dense(cells);
    Words sent = blocky_map(cells, rng);
    std::uint64_t acknowledged = 0;
    std::ostringstream input;
    input << (dense_form ? "dense" : "compressed") << ", cells " << cells << ", capacity "
          << capacity << "; updates:";
    for (std::uint64_t version = 1; version < 12; ++version) {
      const bool keyframe = acknowledged == 0 || rng() % 5 == 0;
      const Words next = keyframe ? blocky_map(cells, rng) : changed(sent, cells, rng);
      std::vector<SentChunk> chunks =
          update_of(keyframe ? nullptr : &sent, acknowledged, next, version, cells, capacity);
      // One fault in about half the updates.
      const int fault = static_cast<int>(rng() % 10);
      const std::size_t at = rng() % chunks.size();
      if (fault == 0 && chunks.size() > 1) chunks.erase(chunks.begin() + static_cast<long>(at));
      if (fault == 1) chunks.insert(chunks.begin() + static_cast<long>(at), chunks[at]);
      if (fault == 2 && at + 1 < chunks.size()) std::swap(chunks[at], chunks[at + 1]);
      if (fault == 3) chunks[at].header.map_hash ^= 1;
      if (fault == 4 && !keyframe) {
        for (auto& chunk : chunks) ++chunk.header.base_version;
      }
      input << " v" << version << (keyframe ? " key" : " delta") << " fault " << fault << " at "
            << at << ";";
      for (const SentChunk& chunk : chunks) {
        const Words before = dense.held();
        const MapOffer expected = dense.offer(chunk);
        const MapOffer got = sliced ? offer_in_slices(store, store.host_store(), chunk, rng, before)
                                    : store.offer(chunk);
        ASSERT_EQ(got.outcome, expected.outcome) << input.str();
        ASSERT_EQ(got.refusal, expected.refusal) << input.str();
        ASSERT_EQ(store.store().version(), dense.version()) << input.str();
      }
      ASSERT_EQ(store.held(), dense.held()) << input.str();
      ASSERT_EQ(store.store().degraded_blocks(), 0u) << input.str();
      if (dense.version() == version) {
        sent = next;
        acknowledged = version;
      }
    }
  }
}

TEST(MapStore, MatchesTheDenseReferenceUnderFaults) { matches_the_dense_reference(false, true); }
TEST(MapStore, WorkInSlicesMatchesTheDenseReferenceAndNeverShowsHalfAnUpdate) {
  matches_the_dense_reference(true, true);
}
TEST(MapStore, CompressedMatchesTheDenseReferenceUnderFaults) {
  matches_the_dense_reference(false, false);
}
TEST(MapStore, CompressedWorkInSlicesMatchesTheDenseReferenceAndNeverShowsHalfAnUpdate) {
  matches_the_dense_reference(true, false);
}

TEST(MapStore, AnUpdateShowsOnlyWhenWholeAndVerified) {
  constexpr CellIndex kCells = 30000;
  std::mt19937_64 rng(5);
  StoreReceiver store(kCells, 64);
  const Words first = blocky_map(kCells, rng);
  ASSERT_EQ(store.offer_all(update_of(nullptr, 0, first, 1, kCells, 64)).outcome,
            MapOutcome::kApplied);
  const Words second = random_map(kCells, rng);
  auto chunks = update_of(&first, 1, second, 2, kCells, 24);
  ASSERT_GT(chunks.size(), 2u);
  for (std::size_t c = 0; c + 1 < chunks.size(); ++c) {
    EXPECT_EQ(store.offer(chunks[c]).outcome, MapOutcome::kPending);
    EXPECT_EQ(store.held(), first) << "chunk " << c << " of " << chunks.size();
  }
  // The last chunk with a wrong hash: the whole update is refused, the first map stays.
  SentChunk last = chunks.back();
  last.header.map_hash ^= 0x100;
  for (auto& chunk : chunks) chunk.header.map_hash ^= 0x100;
  StoreReceiver other(kCells, 64);
  ASSERT_EQ(other.offer_all(update_of(nullptr, 0, first, 1, kCells, 64)).outcome,
            MapOutcome::kApplied);
  const MapOffer refused = other.offer_all(chunks);
  EXPECT_EQ(refused.outcome, MapOutcome::kRefused);
  EXPECT_EQ(refused.refusal, MapRefusal::kHashMismatch);
  EXPECT_EQ(other.held(), first);
  EXPECT_EQ(other.store().version(), 1u);
  // And the original last chunk completes the first store's update.
  EXPECT_EQ(store.offer(update_of(&first, 1, second, 2, kCells, 24).back()).outcome,
            MapOutcome::kApplied);
  EXPECT_EQ(store.held(), second);
}

TEST(MapStore, KnowsTheOldestCaptureTimeOfItsUpdate) {
  constexpr CellIndex kCells = 20000;
  std::mt19937_64 rng(9);
  StoreReceiver store(kCells, 64);
  const auto chunks = update_of(nullptr, 0, random_map(kCells, rng), 1, kCells, 40);
  ASSERT_GT(chunks.size(), 2u);
  std::uint64_t capture = 5000;
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    (void)store.offer(chunks[c], c == 1 ? 4000 : capture + c);
  }
  EXPECT_EQ(store.store().version(), 1u);
  EXPECT_EQ(store.store().capture_ns(), 4000u);
}

// A pool smaller than the map needs: the blocks that do not fit are held forbidden, counted, and
// the map only gains forbidden cells; deltas onto them are refused so the link asks for a
// keyframe, and keyframes still verify.
TEST(MapStore, APoolThatOverflowsOnlyAddsForbiddenCells) {
  test::PropertyRun run(30);
  for (int i = 0; i < run.iterations(); ++i) {
    auto& rng = run.rng();
    const auto cells = static_cast<CellIndex>(4000 + rng() % 60000);
    const auto pool = static_cast<std::uint32_t>(rng() % 12);
    StoreReceiver store(cells, pool);
    DenseReceiver dense(cells);
    std::ostringstream input;
    input << "cells " << cells << ", pool " << pool << ";";
    Words sent = random_map(cells, rng, 900);
    std::uint64_t acknowledged = 0;
    bool saw_degraded = false;
    for (std::uint64_t version = 1; version < 10; ++version) {
      const bool keyframe = acknowledged == 0 || rng() % 3 == 0;
      const Words next = keyframe ? random_map(cells, rng, 900) : changed(sent, cells, rng);
      const auto chunks =
          update_of(keyframe ? nullptr : &sent, acknowledged, next, version, cells, 300);
      const MapOffer got = store.offer_all(chunks);
      input << " v" << version << (keyframe ? " key" : " delta");
      if (keyframe) {
        ASSERT_EQ(got.outcome, MapOutcome::kApplied) << input.str();
      } else if (got.outcome == MapOutcome::kRefused) {
        ASSERT_EQ(got.refusal, MapRefusal::kBaseInexact) << input.str();
        ASSERT_EQ(store.store().version(), acknowledged) << input.str();
        ASSERT_TRUE(covers(store.held(), sent)) << input.str();
        continue;
      }
      ASSERT_EQ(got.outcome, MapOutcome::kApplied) << input.str();
      ASSERT_TRUE(covers(store.held(), next)) << input.str() << ": a forbidden cell was lost";
      saw_degraded = saw_degraded || store.store().degraded_blocks() > 0;
      if (store.store().degraded_blocks() == 0) {
        ASSERT_EQ(store.held(), next) << input.str();
      }
      ASSERT_LE(store.store().pool_blocks_used(), pool) << input.str();
      sent = next;
      acknowledged = version;
    }
    if (pool < 4) {
      ASSERT_TRUE(saw_degraded) << input.str() << ": the pool never overflowed";
    }
  }
}

// The degraded blocks are exactly the counted ones, and they read as forbidden.
TEST(MapStore, CountsItsDegradedBlocks) {
  constexpr CellIndex kCells = 64 * 512;
  Words map(cell_bits::words_for(kCells), 0);
  for (CellIndex block = 0; block < 10; ++block) cell_bits::set(map.data(), block * 1024 + 7);
  StoreReceiver store(kCells, 4);
  ASSERT_EQ(store.offer_all(update_of(nullptr, 0, map, 1, kCells, 200)).outcome,
            MapOutcome::kApplied);
  EXPECT_EQ(store.store().pool_blocks_used(), 4u);
  EXPECT_EQ(store.store().degraded_blocks(), 6u);
  EXPECT_EQ(store.store().pool_overflows(), 6u);
  // 4 blocks exact (one cell each), 6 blocks of 512 all forbidden.
  EXPECT_EQ(cell_bits::count(store.held().data(), 0, kCells), 4u + 6u * 512u);
  EXPECT_TRUE(covers(store.held(), map));
}

}  // namespace
}  // namespace safecell

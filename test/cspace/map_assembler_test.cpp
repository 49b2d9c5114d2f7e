// The receiving end of map updates: whole updates replace the held map, torn, stale, foreign or
// corrupt ones never do (checked against the sender's dense maps).

#include "safecell/cspace/map_assembler.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/map_hash.hpp"
#include "safecell/test/map_updates.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

using test::random_map;
using test::SentChunk;
using test::update_of;
using test::Words;

using Receiver = test::DenseReceiver;

TEST(MapAssembler, StartsWithNoMapAndEverythingForbidden) {
  Receiver receiver(1000);
  EXPECT_EQ(receiver.assembler().version(), 0u);
  EXPECT_EQ(cell_bits::count(receiver.assembler().map(), 0, 1000), 1000u);
}

TEST(MapAssembler, KeyframeThenDeltasRebuildTheSendersMaps) {
  test::PropertyRun run(60);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto cells = static_cast<CellIndex>(1 + run.rng()() % 30000);
    const std::size_t capacity = kMaxRunRecordBytes + run.rng()() % 600;
    Receiver receiver(cells);
    Words sent = random_map(cells, run.rng());
    const std::string input =
        "cells " + std::to_string(cells) + ", capacity " + std::to_string(capacity);
    auto result = receiver.offer_all(update_of(nullptr, 0, sent, 1, cells, capacity));
    ASSERT_EQ(result.outcome, MapAssembler::Outcome::kApplied) << input;
    ASSERT_EQ(receiver.held(), sent) << input;
    for (std::uint64_t version = 2; version < 6; ++version) {
      Words next = sent;
      const auto begin = static_cast<CellIndex>(run.rng()() % cells);
      const auto end = static_cast<CellIndex>(begin + 1 + run.rng()() % (cells - begin));
      if (run.rng()() % 2 == 0) {
        cell_bits::set_range(next.data(), begin, end);
      } else {
        cell_bits::clear_range(next.data(), begin, end);
      }
      result = receiver.offer_all(update_of(&sent, version - 1, next, version, cells, capacity));
      ASSERT_EQ(result.outcome, MapAssembler::Outcome::kApplied) << input << ", v" << version;
      ASSERT_EQ(receiver.held(), next) << input << ", v" << version;
      ASSERT_EQ(receiver.assembler().version(), version);
      sent = next;
    }
  }
}

class MapAssemblerFaults : public ::testing::Test {
 protected:
  static constexpr CellIndex kCells = 40000;
  MapAssemblerFaults() : rng_(17), a_(random_map(kCells, rng_)), b_(random_map(kCells, rng_)) {
    EXPECT_EQ(receiver_.offer_all(update_of(nullptr, 0, a_, 1, kCells, 200)).outcome,
              MapAssembler::Outcome::kApplied);
  }
  void expect_held_a() {
    EXPECT_EQ(receiver_.held(), a_);
    EXPECT_EQ(receiver_.assembler().version(), 1u);
  }
  std::mt19937_64 rng_;
  Words a_, b_;
  Receiver receiver_{kCells};
};

TEST_F(MapAssemblerFaults, ATornUpdateIsRefusedOnceAndNeverApplied) {
  std::vector<SentChunk> delta = update_of(&a_, 1, b_, 2, kCells, 64);
  ASSERT_GT(delta.size(), 3u);
  delta.erase(delta.begin() + 1);  // lost
  EXPECT_EQ(receiver_.offer(delta[0]).outcome, MapAssembler::Outcome::kPending);
  const auto torn = receiver_.offer(delta[1]);
  EXPECT_EQ(torn.outcome, MapAssembler::Outcome::kRefused);
  EXPECT_EQ(torn.refusal, MapRefusal::kTorn);
  for (std::size_t c = 2; c < delta.size(); ++c) {
    EXPECT_EQ(receiver_.offer(delta[c]).outcome, MapAssembler::Outcome::kIgnored);
  }
  expect_held_a();
  // The next delta, against the version the receiver still acknowledges, repairs it.
  EXPECT_EQ(receiver_.offer_all(update_of(&a_, 1, b_, 3, kCells, 64)).outcome,
            MapAssembler::Outcome::kApplied);
  EXPECT_EQ(receiver_.held(), b_);
}

TEST_F(MapAssemblerFaults, ADeltaOnAnotherBaseIsRefused) {
  const auto result = receiver_.offer_all(update_of(&b_, 7, a_, 8, kCells, 200));
  EXPECT_EQ(result.refusal, MapRefusal::kBaseMismatch);
  expect_held_a();
}

TEST_F(MapAssemblerFaults, AnOldVersionIsRefused) {
  const auto result = receiver_.offer_all(update_of(nullptr, 0, b_, 1, kCells, 200));
  EXPECT_EQ(result.refusal, MapRefusal::kStaleVersion);
  expect_held_a();
}

// The negative control of the hash check: a delta whose runs were changed after the sender hashed
// its map (a sender bug or a corruption the CRC missed) applies cleanly but must not be taken.
TEST_F(MapAssemblerFaults, AWrongResultIsAHashMismatch) {
  std::vector<SentChunk> delta = update_of(&a_, 1, b_, 2, kCells, 100000);
  ASSERT_EQ(delta.size(), 1u);
  ASSERT_GE(delta[0].runs.size(), 2u);
  delta[0].runs[1] ^= 0x02;  // one run two cells longer or shorter
  const auto result = receiver_.offer_all(delta);
  EXPECT_EQ(result.outcome, MapAssembler::Outcome::kRefused);
  EXPECT_TRUE(result.refusal == MapRefusal::kHashMismatch ||
              result.refusal == MapRefusal::kBadChunk)
      << to_string(result.refusal);
  expect_held_a();
}

TEST_F(MapAssemblerFaults, MalformedChunksAreRefused) {
  std::vector<SentChunk> delta = update_of(&a_, 1, b_, 2, kCells, 200);
  delta[0].runs.push_back(0x80);  // a truncated record
  EXPECT_EQ(receiver_.offer(delta[0]).refusal, MapRefusal::kBadChunk);
  std::vector<SentChunk> early = update_of(&a_, 1, b_, 3, kCells, 200);
  early.back().header.end_cell = kCells - 1;  // the last chunk stops short of the grid
  EXPECT_EQ(receiver_.offer_all(early).refusal, MapRefusal::kBadChunk);
  std::vector<SentChunk> past = update_of(&a_, 1, b_, 4, kCells, 200);
  past[0].header.end_cell = kCells + 1;
  EXPECT_EQ(receiver_.offer(past[0]).refusal, MapRefusal::kBadChunk);
  expect_held_a();
}

}  // namespace
}  // namespace safecell

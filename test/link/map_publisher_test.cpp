// The map publisher's choice of keyframe or delta, and its deltas on the version sent last,
// rebuilt by the controller's assembler: on a link that delivers in order nothing is refused,
// however late the acknowledgements; a loss is repaired from the version the controller names.

#include "safecell/link/map_publisher.hpp"

#include <gtest/gtest.h>

#include <deque>
#include <random>
#include <vector>

#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/map_assembler.hpp"
#include "safecell/cspace/map_hash.hpp"

namespace safecell {
namespace {

constexpr std::uint32_t kCells = 20000;

CellSet map_with(CellIndex begin, CellIndex end) {
  CellSet map(kCells);
  map.set_range(begin, end);
  return map;
}

MapChunkHeader header_of(const v1::MapChunk& chunk) {
  MapChunkHeader header;
  header.kind =
      chunk.kind() == v1::MAP_UPDATE_KIND_DELTA ? MapChunkKind::kDelta : MapChunkKind::kKeyframe;
  header.map_version = chunk.map_version();
  header.base_version = chunk.base_version();
  header.map_hash =
      map_hash_with_cameras(chunk.map_hash(), chunk.healthy_cameras(), chunk.camera_count());
  header.chunk_index = chunk.chunk_index();
  header.chunk_count = chunk.chunk_count();
  header.first_cell = chunk.first_cell();
  header.end_cell = chunk.end_cell();
  return header;
}

class Receiver {
 public:
  Receiver()
      : words_{std::vector<std::uint64_t>(cell_bits::words_for(kCells)),
               std::vector<std::uint64_t>(cell_bits::words_for(kCells))},
        hashes_{std::vector<std::uint64_t>(map_hash_blocks(kCells)),
                std::vector<std::uint64_t>(map_hash_blocks(kCells))},
        assembler_({{words_[0].data(), words_[1].data()}, {hashes_[0].data(), hashes_[1].data()}},
                   kCells) {}
  bool take(const MapUpdate& update) {
    MapAssembler::Offer offer;
    for (const auto& chunk : update.chunks) {
      const auto* runs = reinterpret_cast<const std::uint8_t*>(chunk.runs().data());
      offer = assembler_.offer(header_of(chunk), runs, chunk.runs().size());
    }
    return offer.outcome == MapAssembler::Outcome::kApplied;
  }
  std::uint64_t version() const { return assembler_.version(); }

 private:
  std::vector<std::uint64_t> words_[2];
  std::vector<std::uint64_t> hashes_[2];
  MapAssembler assembler_;
};

TEST(MapPublisher, StartsWithAKeyframeThenDeltasOnTheVersionSentLast) {
  MapPublisher publisher(kCells, {});
  Receiver receiver;
  const MapUpdate first = publisher.publish(map_with(10, 500), 4, 4);
  EXPECT_TRUE(first.keyframe);
  EXPECT_EQ(first.version, 1u);
  // Two more before any acknowledgement came back: both on their way at once.
  const MapUpdate second = publisher.publish(map_with(20, 510), 4, 4);
  const MapUpdate third = publisher.publish(map_with(30, 520), 4, 4);
  EXPECT_FALSE(second.keyframe);
  EXPECT_EQ(second.chunks.front().base_version(), 1u);
  EXPECT_EQ(third.chunks.front().base_version(), 2u);
  EXPECT_TRUE(receiver.take(first));
  EXPECT_TRUE(receiver.take(second));
  EXPECT_TRUE(receiver.take(third));
  EXPECT_EQ(receiver.version(), 3u);
}

// Updates delivered in order with random delays (up to three updates on their way) and
// acknowledgements random cycles late: the receiver refuses none, over several seeds. The control:
// the same run with one update swapped with the next (a reordering fault) is refused, so the
// count can fail.
TEST(MapPublisher, InOrderDeliveryRefusesNothingHoweverLateTheAcknowledgements) {
  for (const std::uint32_t seed : {1U, 2U, 3U, 4U, 5U}) {
    for (const bool reorder_once : {false, true}) {
      std::mt19937 rng(seed);
      MapPublisher publisher(kCells, {});
      Receiver receiver;
      std::deque<MapUpdate> on_the_way;
      std::deque<std::uint64_t> acks_on_the_way;
      int refused = 0;
      for (int cycle = 0; cycle < 300; ++cycle) {
        const auto begin = static_cast<CellIndex>(rng() % (kCells - 600));
        on_the_way.push_back(publisher.publish(map_with(begin, begin + 500), 4, 4));
        if (reorder_once && cycle == 150 && on_the_way.size() >= 2) {
          std::swap(on_the_way[on_the_way.size() - 2], on_the_way.back());
        }
        while (on_the_way.size() > rng() % 4) {
          if (!receiver.take(on_the_way.front())) {
            ++refused;
            publisher.request_repair(receiver.version());
          }
          on_the_way.pop_front();
          acks_on_the_way.push_back(receiver.version());
        }
        while (acks_on_the_way.size() > rng() % 5) {
          publisher.acknowledge(acks_on_the_way.front());
          acks_on_the_way.pop_front();
        }
      }
      if (reorder_once) {
        EXPECT_GT(refused, 0) << "seed " << seed << ": a reordering was not refused";
      } else {
        EXPECT_EQ(refused, 0) << "seed " << seed;
      }
      EXPECT_GE(receiver.version(), 290u) << "seed " << seed;
    }
  }
}

// A lost update: the next one (on the lost version) is refused, the controller names the version
// it holds, and the update after is a delta from it. The same request again (the refusal of the
// update that was already on its way) is answered by that repair and changes nothing.
TEST(MapPublisher, ALossIsRepairedFromTheVersionTheControllerHolds) {
  MapPublisher publisher(kCells, {});
  Receiver receiver;
  ASSERT_TRUE(receiver.take(publisher.publish(map_with(10, 500), 4, 4)));
  ASSERT_TRUE(receiver.take(publisher.publish(map_with(20, 510), 4, 4)));
  (void)publisher.publish(map_with(30, 520), 4, 4);  // version 3: lost
  EXPECT_FALSE(receiver.take(publisher.publish(map_with(40, 530), 4, 4)));
  publisher.request_repair(receiver.version());
  const MapUpdate fifth = publisher.publish(map_with(50, 540), 4, 4);
  EXPECT_FALSE(fifth.keyframe) << "version 2 is in the history: a delta repairs";
  EXPECT_EQ(fifth.chunks.front().base_version(), 2u);
  publisher.request_repair(2);  // a late second refusal of the same loss
  EXPECT_EQ(publisher.repeated_requests(), 1u);
  EXPECT_TRUE(receiver.take(fifth));
  const MapUpdate sixth = publisher.publish(map_with(60, 550), 4, 4);
  EXPECT_EQ(sixth.chunks.front().base_version(), 5u);
  EXPECT_TRUE(receiver.take(sixth));
  EXPECT_EQ(publisher.repairs(), 1u);
}

TEST(MapPublisher, KeyframesOnRequestAndWhenAcknowledgementsStop) {
  MapPublisherSettings settings;
  settings.keyframe_after_cycles = 3;
  MapPublisher publisher(kCells, settings);
  (void)publisher.publish(map_with(0, 10), 4, 4);
  publisher.acknowledge(1);
  EXPECT_FALSE(publisher.publish(map_with(0, 11), 4, 4).keyframe);
  publisher.request_repair(0);  // the controller holds no map
  EXPECT_TRUE(publisher.publish(map_with(0, 12), 4, 4).keyframe);
  // No acknowledgement for 3 cycles: the 4th update without one is a keyframe.
  EXPECT_FALSE(publisher.publish(map_with(0, 13), 4, 4).keyframe);
  EXPECT_TRUE(publisher.publish(map_with(0, 14), 4, 4).keyframe);
}

TEST(MapPublisher, ARepairFromAVersionOutOfTheHistoryIsAKeyframe) {
  MapPublisherSettings settings;
  settings.history = 2;
  MapPublisher publisher(kCells, settings);
  (void)publisher.publish(map_with(0, 10), 4, 4);
  publisher.acknowledge(1);
  (void)publisher.publish(map_with(0, 11), 4, 4);
  (void)publisher.publish(map_with(0, 12), 4, 4);  // version 1 leaves the history
  publisher.request_repair(1);
  EXPECT_TRUE(publisher.publish(map_with(0, 13), 4, 4).keyframe);
  publisher.request_repair(99);  // never sent: a keyframe too
  EXPECT_TRUE(publisher.publish(map_with(0, 14), 4, 4).keyframe);
  publisher.acknowledge(99);  // never sent: ignored
  EXPECT_EQ(publisher.acknowledged(), 1u);
}

TEST(MapPublisher, RefusesMeaninglessSettingsAndForeignMaps) {
  MapPublisherSettings settings;
  settings.runs_per_chunk_bytes = 4;
  EXPECT_THROW(MapPublisher(kCells, settings), std::invalid_argument);
  MapPublisher publisher(kCells, {});
  EXPECT_THROW((void)publisher.publish(CellSet(kCells + 1), 4, 4), std::invalid_argument);
}

}  // namespace
}  // namespace safecell

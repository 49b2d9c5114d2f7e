// The map publisher's choice of keyframe or delta, and its deltas against the acknowledged
// version, rebuilt by the controller's assembler.

#include "safecell/link/map_publisher.hpp"

#include <gtest/gtest.h>

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

TEST(MapPublisher, StartsWithAKeyframeThenDeltasAgainstTheAcknowledgedVersion) {
  MapPublisher publisher(kCells, {});
  Receiver receiver;
  const MapUpdate first = publisher.publish(map_with(10, 500), 4, 4);
  EXPECT_TRUE(first.keyframe);
  EXPECT_EQ(first.version, 1u);
  ASSERT_TRUE(receiver.take(first));
  publisher.acknowledge(receiver.version());
  const MapUpdate second = publisher.publish(map_with(20, 510), 4, 4);
  EXPECT_FALSE(second.keyframe);
  EXPECT_EQ(second.chunks.front().base_version(), 1u);
  ASSERT_TRUE(receiver.take(second));
  // Version 3 is lost; version 4 is still a delta against 2, the version the controller holds.
  publisher.acknowledge(receiver.version());
  (void)publisher.publish(map_with(30, 520), 4, 4);
  const MapUpdate fourth = publisher.publish(map_with(40, 530), 4, 4);
  EXPECT_FALSE(fourth.keyframe);
  EXPECT_EQ(fourth.chunks.front().base_version(), 2u);
  EXPECT_TRUE(receiver.take(fourth)) << "one lost update costs one cycle, not a resync";
  EXPECT_EQ(receiver.version(), 4u);
}

TEST(MapPublisher, KeyframesOnRequestAndWhenAcknowledgementsStop) {
  MapPublisherSettings settings;
  settings.keyframe_after_cycles = 3;
  MapPublisher publisher(kCells, settings);
  (void)publisher.publish(map_with(0, 10), 4, 4);
  publisher.acknowledge(1);
  EXPECT_FALSE(publisher.publish(map_with(0, 11), 4, 4).keyframe);
  publisher.request_keyframe();
  EXPECT_TRUE(publisher.publish(map_with(0, 12), 4, 4).keyframe);
  // No acknowledgement for 3 cycles: the 4th update without one is a keyframe.
  EXPECT_FALSE(publisher.publish(map_with(0, 13), 4, 4).keyframe);
  EXPECT_TRUE(publisher.publish(map_with(0, 14), 4, 4).keyframe);
}

TEST(MapPublisher, AnAcknowledgedVersionOutOfTheHistoryMeansAKeyframe) {
  MapPublisherSettings settings;
  settings.history = 2;
  MapPublisher publisher(kCells, settings);
  (void)publisher.publish(map_with(0, 10), 4, 4);
  publisher.acknowledge(1);
  (void)publisher.publish(map_with(0, 11), 4, 4);
  (void)publisher.publish(map_with(0, 12), 4, 4);  // version 1 leaves the history
  EXPECT_TRUE(publisher.publish(map_with(0, 13), 4, 4).keyframe);
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

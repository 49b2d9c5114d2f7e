#pragma once
// A MapStore with its memory that takes whole updates as a sender cuts them, for the controller
// tests; held() is its map as a dense bitmap.

#include <vector>

#include "safecell/controller/host/map_store_memory.hpp"
#include "safecell/controller/map_store.hpp"
#include "safecell/test/map_updates.hpp"

namespace safecell {

class StoreReceiver {
 public:
  explicit StoreReceiver(const MapStoreLayout& layout) : cells_(layout.cell_count), host_(layout) {}
  // The compressed form with a pool of `pool_blocks`.
  StoreReceiver(CellIndex cells, std::uint32_t pool_blocks)
      : StoreReceiver(MapStoreLayout::compressed(cells, pool_blocks)) {}
  MapOffer offer(const test::SentChunk& chunk, std::uint64_t capture_ns = 1) {
    return host_.store().offer(chunk.header, chunk.runs.data(), chunk.runs.size(), capture_ns);
  }
  MapOffer offer_all(const std::vector<test::SentChunk>& chunks) {
    MapOffer last;
    for (const test::SentChunk& chunk : chunks) {
      last = offer(chunk);
      if (last.outcome == MapOutcome::kRefused) return last;
    }
    return last;
  }
  test::Words held() const {
    test::Words words(cell_bits::words_for(cells_));
    host_.store().view().copy_dense(words.data());
    return words;
  }
  const MapStore& store() const { return host_.store(); }
  MapStore& host_store() { return host_.store(); }

 private:
  CellIndex cells_;
  HostMapStore host_;
};

// A store holding `map` as a keyframe of version 1.
inline void hold(StoreReceiver& receiver, const test::Words& map, CellIndex cells) {
  (void)receiver.offer_all(test::update_of(nullptr, 0, map, 1, cells, 1024));
}

}  // namespace safecell

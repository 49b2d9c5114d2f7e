#pragma once
// What a sender emits for a map update, for the tests of the receivers (the dense MapAssembler,
// the controller's MapStore): chunks of a keyframe or a delta, cut at a given run capacity, random
// maps to send, and the dense reference receiver. Header-only; the tests that include it link
// safecell::cspace.

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/map_assembler.hpp"
#include "safecell/cspace/map_chunk.hpp"
#include "safecell/cspace/map_hash.hpp"
#include "safecell/cspace/map_update_sequence.hpp"

namespace safecell::test {

using Words = std::vector<std::uint64_t>;

struct SentChunk {
  MapChunkHeader header;
  std::vector<std::uint8_t> runs;
};

// A keyframe of `target` when base is null, else the delta base -> target.
inline std::vector<SentChunk> update_of(const Words* base, std::uint64_t base_version,
                                        const Words& target, std::uint64_t version, CellIndex cells,
                                        std::size_t capacity) {
  std::vector<SentChunk> chunks;
  CellIndex from = 0;
  do {
    SentChunk chunk;
    chunk.header.kind = base ? MapChunkKind::kDelta : MapChunkKind::kKeyframe;
    chunk.header.map_version = version;
    chunk.header.base_version = base ? base_version : 0;
    chunk.header.map_hash = map_hash(target.data(), cells);
    chunk.header.chunk_index = static_cast<std::uint32_t>(chunks.size());
    chunk.header.first_cell = from;
    chunk.runs.resize(capacity);
    std::size_t size = 0;
    chunk.header.end_cell =
        base ? encode_delta_chunk(base->data(), target.data(), cells, from, chunk.runs.data(),
                                  capacity, size)
             : encode_keyframe_chunk(target.data(), cells, from, chunk.runs.data(), capacity, size);
    chunk.runs.resize(size);
    from = chunk.header.end_cell;
    chunks.push_back(std::move(chunk));
  } while (from < cells);
  for (auto& chunk : chunks) chunk.header.chunk_count = static_cast<std::uint32_t>(chunks.size());
  return chunks;
}

// Alternating free and forbidden stretches of 1 .. max_run cells, each value by a coin toss.
inline Words random_map(CellIndex cells, std::mt19937_64& rng, CellIndex max_run = 400) {
  Words words(cell_bits::words_for(cells), 0);
  for (CellIndex at = 0; at < cells;) {
    const CellIndex end = std::min(cells, static_cast<CellIndex>(at + 1 + rng() % max_run));
    if (rng() % 2 == 0) cell_bits::set_range(words.data(), at, end);
    at = end;
  }
  return words;
}

// The dense reference receiver: MapAssembler with its memory.
class DenseReceiver {
 public:
  explicit DenseReceiver(CellIndex cells)
      : cells_(cells),
        words_{Words(cell_bits::words_for(cells)), Words(cell_bits::words_for(cells))},
        hashes_{Words(map_hash_blocks(cells)), Words(map_hash_blocks(cells))},
        assembler_({{words_[0].data(), words_[1].data()}, {hashes_[0].data(), hashes_[1].data()}},
                   cells) {}

  MapAssembler::Offer offer(const SentChunk& chunk) {
    return assembler_.offer(chunk.header, chunk.runs.data(), chunk.runs.size());
  }
  // Over a whole update: its refusal, else the last chunk's outcome.
  MapAssembler::Offer offer_all(const std::vector<SentChunk>& chunks) {
    MapAssembler::Offer last;
    for (const SentChunk& chunk : chunks) {
      last = offer(chunk);
      if (last.outcome == MapAssembler::Outcome::kRefused) return last;
    }
    return last;
  }
  Words held() const {
    return Words(assembler_.map(), assembler_.map() + cell_bits::words_for(cells_));
  }
  const MapAssembler& assembler() const { return assembler_; }
  std::uint64_t version() const { return assembler_.version(); }

 private:
  CellIndex cells_;
  Words words_[2];
  Words hashes_[2];
  MapAssembler assembler_;
};

}  // namespace safecell::test

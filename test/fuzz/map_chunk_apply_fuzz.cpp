// Map chunks with any header and any run list, offered to the dense assembler and to the
// controller's store in both forms (dense; compressed with a pool of 3 blocks, so it overflows),
// each holding a map: never a read or write outside their storage; a refused chunk leaves the
// held map as it was; an applied update's map has the hash it claimed; for the same version, the
// dense store holds the assembler's map and the compressed one never holds a cell free that the
// assembler holds forbidden.
//
// Input: a sequence of chunks, each  [kind 1][version 1][base 1][index 1][count 1][first 2]
// [end 2][hash selector 1, its upper 7 bits the store's slice budget (0: whole)][run bytes n 1]
// [n bytes]; the grid has 3000 cells.

#include <cstring>

#include "fuzz_targets.hpp"
#include "safecell/base/assert.hpp"
#include "safecell/controller/map_store.hpp"
#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/map_assembler.hpp"
#include "safecell/cspace/map_hash.hpp"

namespace safecell::fuzz {
namespace {

constexpr CellIndex kCells = 3000;
constexpr std::uint32_t kWords = cell_bits::words_for(kCells);
constexpr std::uint32_t kBlocks = map_hash_blocks(kCells);
constexpr MapStoreLayout kCompressedLayout = MapStoreLayout::compressed(kCells, 3);
constexpr MapStoreLayout kDenseLayout = MapStoreLayout::of(kCells);

// Offers one chunk to `store` whole (slice 0) or in slices of that many work units, leaving the
// upkeep after a swap or refusal to the next chunk, as the link does; checks that the held map
// changes only with an applied update, to the version and hash it claimed. Returns the held map.
void offer_and_check(MapStore& store, const MapChunkHeader& header, const std::uint8_t* runs,
                     std::size_t runs_size, std::uint32_t slice, std::uint64_t* held) {
  std::uint64_t before[kWords];
  store.view().copy_dense(before);
  const std::uint64_t version_before = store.version();
  MapOffer offer;
  if (slice == 0) {
    offer = store.offer(header, runs, runs_size, 1);
  } else {
    offer = store.accept(header, runs, runs_size, 1);
    while (offer.outcome == MapOutcome::kWorking) {
      SAFECELL_ASSERT(store.version() == version_before);  // no half update shows
      std::uint32_t budget = slice;
      offer = store.work(budget);
    }
  }
  store.view().copy_dense(held);
  if (offer.outcome == MapOutcome::kApplied) {
    SAFECELL_ASSERT(store.version() == header.map_version && store.hash() == header.map_hash);
  } else {
    SAFECELL_ASSERT(store.version() == version_before);
    SAFECELL_ASSERT(std::memcmp(before, held, sizeof before) == 0);
  }
}

}  // namespace

int map_chunk_apply(const std::uint8_t* data, std::size_t size) {
  static std::uint64_t words[2][kWords];
  static std::uint64_t hashes[2][kBlocks];
  MapAssembler assembler({{words[0], words[1]}, {hashes[0], hashes[1]}}, kCells);
  static StaticMapStoreMemory<kCompressedLayout> compressed_memory;
  MapStore compressed(kCompressedLayout, compressed_memory.storage());
  static StaticMapStoreMemory<kDenseLayout> dense_memory;
  MapStore dense(kDenseLayout, dense_memory.storage());
  // A first map to hold: cells 100..199 forbidden, version 1.
  {
    std::uint64_t target[kWords] = {};
    cell_bits::set_range(target, 100, 200);
    std::uint8_t runs[64];
    std::size_t runs_size = 0;
    (void)encode_keyframe_chunk(target, kCells, 0, runs, sizeof runs, runs_size);
    MapChunkHeader header;
    header.map_version = 1;
    header.map_hash = map_hash(target, kCells);
    header.chunk_count = 1;
    header.end_cell = kCells;
    SAFECELL_ASSERT(assembler.offer(header, runs, runs_size).outcome ==
                    MapAssembler::Outcome::kApplied);
    SAFECELL_ASSERT(compressed.offer(header, runs, runs_size, 1).outcome == MapOutcome::kApplied);
    SAFECELL_ASSERT(dense.offer(header, runs, runs_size, 1).outcome == MapOutcome::kApplied);
  }
  std::size_t at = 0;
  while (at + 11 <= size) {
    const std::uint8_t* field = data + at;
    MapChunkHeader header;
    header.kind = (field[0] & 1) != 0 ? MapChunkKind::kDelta : MapChunkKind::kKeyframe;
    header.map_version = field[1];
    header.base_version = field[2];
    header.chunk_index = field[3];
    header.chunk_count = field[4];
    header.first_cell = static_cast<CellIndex>(field[5] | (field[6] << 8));
    header.end_cell = static_cast<CellIndex>(field[7] | (field[8] << 8));
    const std::size_t runs_size = field[10];
    at += 11;
    if (at + runs_size > size) break;
    // The hash: the held map's, or a fixed value (right by chance only).
    header.map_hash = (field[9] & 1) != 0 ? assembler.hash() : 0x1234;
    std::uint64_t held_before[kWords];
    std::memcpy(held_before, assembler.map(), sizeof held_before);
    const std::uint64_t version_before = assembler.version();
    const MapAssembler::Offer offer = assembler.offer(header, data + at, runs_size);
    const std::uint32_t slice = field[9] >> 1U;
    std::uint64_t compressed_now[kWords];
    offer_and_check(compressed, header, data + at, runs_size, slice, compressed_now);
    std::uint64_t dense_now[kWords];
    offer_and_check(dense, header, data + at, runs_size, slice, dense_now);
    at += runs_size;
    if (offer.outcome == MapAssembler::Outcome::kApplied) {
      SAFECELL_ASSERT(assembler.version() == header.map_version);
      SAFECELL_ASSERT(map_hash(assembler.map(), kCells) == header.map_hash);
    } else {
      SAFECELL_ASSERT(assembler.version() == version_before);
      SAFECELL_ASSERT(std::memcmp(held_before, assembler.map(), sizeof held_before) == 0);
    }
    if (compressed.version() == assembler.version()) {
      for (std::uint32_t w = 0; w < kWords; ++w) {
        SAFECELL_ASSERT((assembler.map()[w] & ~compressed_now[w]) == 0);
      }
    }
    if (dense.version() == assembler.version()) {
      SAFECELL_ASSERT(std::memcmp(assembler.map(), dense_now, sizeof dense_now) == 0);
    }
    // Bits past the last cell stay zero.
    SAFECELL_ASSERT((assembler.map()[kWords - 1] >> (kCells % 64)) == 0);
  }
  return 0;
}

}  // namespace safecell::fuzz

SAFECELL_FUZZ_ENTRY_POINT(map_chunk_apply)

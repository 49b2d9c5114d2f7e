#pragma once
// The hash of a forbidden map, defined per block of cells and combined by XOR, so that applying
// an update re-hashes only the blocks it changed and the map hash follows in O(1) per block.
//
//   block b       cells [512 b, 512 (b + 1)), i.e. words [8 b, 8 b + 8) of the map
//   block hash    k = mix(b + 1); for each word w of the block (zero past the map's last word):
//                 k = mix(k ^ w)
//   map hash      mix(mix(cell_count) ^ (k_0 ^ k_1 ^ ... ^ k_last))
//   mix           the 64-bit finaliser of MurmurHash3 (two multiply-xorshift rounds)
// Computed over 64-bit word values, so it is equal on every platform whatever its byte order. It
// checks that a receiver rebuilt the sender's map (every chunk applied, none twice, none torn); the
// link's CRC is what guards the bytes. Each block hash is keyed by the block's index, so equal
// blocks at different places do not cancel. Test vectors are in test/cspace/map_hash_test.cpp.
// Real-time safe: no allocation; caller storage only.

#include <cstdint>

#include "safecell/base/mix64.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

inline constexpr std::uint32_t kMapHashBlockCells = 512;
inline constexpr std::uint32_t kMapHashBlockWords = kMapHashBlockCells / 64;

constexpr std::uint32_t map_hash_blocks(std::uint32_t cell_count) noexcept {
  return static_cast<std::uint32_t>((std::uint64_t{cell_count} + kMapHashBlockCells - 1) /
                                    kMapHashBlockCells);
}

// The mixing step, a block's starting value and the final step, for receivers that hash a map as
// they rebuild it (the controller's compressed store hashes each block it stores).
constexpr std::uint64_t map_hash_mix(std::uint64_t x) noexcept { return mix64(x); }
constexpr std::uint64_t map_block_hash_seed(std::uint32_t block) noexcept {
  return map_hash_mix(std::uint64_t{block} + 1);
}
// The hash a map chunk carries on the link (MapChunk.map_hash): the map hash bound to the camera
// counts the map was fused from, so that a fault behind a valid CRC that changes them (a
// corrupted encode buffer, resealed) is refused as a wrong map, never taken as more healthy
// cameras than there were. The binding is an XOR with a mixed key of both counts, so the same
// call takes it off again: the receiver compares map_hash_with_cameras(chunk's hash, chunk's
// counts) with the hash of the map it rebuilt.
constexpr std::uint64_t map_hash_with_cameras(std::uint64_t hash, std::uint32_t healthy_cameras,
                                              std::uint32_t camera_count) noexcept {
  const std::uint64_t counts = (std::uint64_t{healthy_cameras} << 32) | camera_count;
  return hash ^ map_hash_mix(map_hash_mix(counts ^ 0x9E3779B97F4A7C15ull));
}
// The binding of the speed reduction a map is sent with (MapChunk.speed_reduction_permille), on
// top of the cameras': a fault that turns a reduced map into a full-speed one is refused like a
// changed cell. XOR with a mixed key again, so the same call takes it off. No reduction binds
// nothing: an update without the field hashes as it did before the field.
constexpr std::uint64_t map_hash_with_speed_reduction(std::uint64_t hash,
                                                      std::uint32_t reduction_permille) noexcept {
  if (reduction_permille == 0) return hash;
  return hash ^
         map_hash_mix(map_hash_mix(std::uint64_t{reduction_permille} ^ 0xD1B54A32D192ED03ull));
}
// The map hash from the XOR of all its block hashes.
constexpr std::uint64_t map_hash_from_combined(std::uint64_t combined_block_hashes,
                                               CellIndex cell_count) noexcept {
  return map_hash_mix(map_hash_mix(cell_count) ^ combined_block_hashes);
}

// The hash of block `block` of a map of cell_count cells (precondition: block < blocks).
std::uint64_t map_block_hash(const std::uint64_t* words, CellIndex cell_count,
                             std::uint32_t block) noexcept;

// The map hash from the block hashes (map_hash_blocks(cell_count) of them).
std::uint64_t map_hash_of_blocks(const std::uint64_t* block_hashes, CellIndex cell_count) noexcept;

// The map hash from scratch: every block.
std::uint64_t map_hash(const std::uint64_t* words, CellIndex cell_count) noexcept;

// Block hashes kept up to date over caller storage (map_hash_blocks(cell_count) entries): after a
// change of cells [begin, end), `refresh` recomputes the blocks they lie in.
class MapBlockHashes {
 public:
  MapBlockHashes(std::uint64_t* block_hashes, CellIndex cell_count) noexcept
      : hashes_(block_hashes), cell_count_(cell_count) {}

  void refresh_all(const std::uint64_t* words) noexcept;
  void refresh(const std::uint64_t* words, CellIndex begin, CellIndex end) noexcept;
  std::uint64_t map_hash() const noexcept { return map_hash_of_blocks(hashes_, cell_count_); }

 private:
  std::uint64_t* hashes_;
  CellIndex cell_count_;
};

}  // namespace safecell

#pragma once
// The memory of a MapStore on Linux: every array of MapStoreStorage allocated once, at init, to
// the sizes of a MapStoreLayout. (A bare-metal build uses static arrays of the same sizes.)
// Not copyable: the store keeps pointers into it.

#include <cstdint>
#include <vector>

#include "safecell/controller/map_store.hpp"

namespace safecell {

class MapStoreMemory {
 public:
  explicit MapStoreMemory(const MapStoreLayout& layout)
      : layout_(layout),
        sides_{std::vector<std::uint64_t>(layout.dense_words()),
               std::vector<std::uint64_t>(layout.dense_words())},
        changed_bits_(layout.changed_bits_words()),
        slots_{std::vector<std::uint32_t>(layout.table_blocks()),
               std::vector<std::uint32_t>(layout.table_blocks())},
        pool_(std::size_t{layout.pool_blocks} * kStoreBlockWords),
        free_blocks_(layout.pool_blocks),
        changed_blocks_(layout.table_blocks()),
        changed_hashes_(layout.table_blocks()),
        block_hashes_(layout.table_blocks()) {}
  MapStoreMemory(const MapStoreMemory&) = delete;
  MapStoreMemory& operator=(const MapStoreMemory&) = delete;

  const MapStoreLayout& layout() const { return layout_; }
  MapStoreStorage storage() {
    return {{sides_[0].data(), sides_[1].data()},
            changed_bits_.data(),
            {slots_[0].data(), slots_[1].data()},
            pool_.data(),
            free_blocks_.data(),
            changed_blocks_.data(),
            changed_hashes_.data(),
            block_hashes_.data()};
  }

 private:
  MapStoreLayout layout_;
  std::vector<std::uint64_t> sides_[2];
  std::vector<std::uint64_t> changed_bits_;
  std::vector<std::uint32_t> slots_[2];
  std::vector<std::uint64_t> pool_;
  std::vector<std::uint32_t> free_blocks_;
  std::vector<std::uint32_t> changed_blocks_;
  std::vector<std::uint64_t> changed_hashes_;
  std::vector<std::uint64_t> block_hashes_;
};

// A MapStore with its memory, for the Linux module and the tests.
class HostMapStore {
 public:
  explicit HostMapStore(const MapStoreLayout& layout)
      : memory_(layout), store_(layout, memory_.storage()) {}
  MapStore& store() { return store_; }
  const MapStore& store() const { return store_; }

 private:
  MapStoreMemory memory_;
  MapStore store_;
};

}  // namespace safecell

#pragma once
// The memory of a GridPlanner on Linux, allocated once at init to a PlannerLayout's sizes.
// Not copyable: the planner keeps pointers into it.

#include <cstdint>
#include <vector>

#include "safecell/controller/grid_planner.hpp"

namespace safecell {

class PlannerMemoryHost {
 public:
  explicit PlannerMemoryHost(const PlannerLayout& layout)
      : cost_(layout.cell_count),
        stamp_(layout.cell_count),
        move_(layout.cell_count),
        slot_(layout.cell_count),
        heap_(layout.heap_capacity),
        path_(layout.path_capacity) {}
  PlannerMemoryHost(const PlannerMemoryHost&) = delete;
  PlannerMemoryHost& operator=(const PlannerMemoryHost&) = delete;

  PlannerMemory memory() {
    return {cost_.data(), stamp_.data(), move_.data(), slot_.data(), heap_.data(), path_.data()};
  }

 private:
  std::vector<std::uint32_t> cost_;
  std::vector<std::uint32_t> stamp_;
  std::vector<std::uint8_t> move_;
  std::vector<std::uint32_t> slot_;
  std::vector<PlannerHeapEntry> heap_;
  std::vector<CellIndex> path_;
};

}  // namespace safecell

#pragma once
// The global planner of the safe gross-motion service: A* over the free cells of the grid.
//
// Moves go one cell along one discretised joint (joints that are not discretised have one cell and
// never block). A move into cell c costs kStepCost plus clearance_weight for each forbidden cell
// next to c, so paths keep away from forbidden cells where they can; the heuristic (kStepCost
// times the cells still to go along every joint) never overestimates, so a path is found whenever
// one exists within the memory given.
// Memory: the caller's, fixed at init (PlannerLayout: per cell a cost, a stamp, the move that
// reached it and its place in the heap; a heap; the path). A cell is in the heap at most once (a
// cheaper way to it lowers its entry in place), so a heap and a path of one entry per cell never
// run out: PlannerLayout::for_grid gives those. A smaller layout may run out; the search then
// ends with kOutOfMemory, never with a wrong answer.
// Thread context: the controller's cycle or a lower-priority task of its own, never both at once.
// Real-time: O(cells the search reaches * log heap); bounded by max_expansions per plan().

#include <cstddef>
#include <cstdint>

#include "safecell/controller/map_view.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

struct PlannerLayout {
  CellIndex cell_count = 0;
  std::uint32_t heap_capacity = 0;
  std::uint32_t path_capacity = 0;

  constexpr std::size_t bytes() const noexcept {
    return std::size_t{cell_count} * 13 + std::size_t{heap_capacity} * 8 +
           std::size_t{path_capacity} * 4;
  }
  // Room for every cell in the heap and on the path: such a plan never runs out of memory
  // (25 bytes per cell; 4.7 MB for the default cell's 186,480 cells).
  static constexpr PlannerLayout for_grid(CellIndex cell_count) noexcept {
    return {cell_count, cell_count, cell_count < 2 ? 2 : cell_count};
  }
};

struct PlannerHeapEntry {
  std::uint32_t priority;  // cost so far + heuristic
  CellIndex cell;
};

struct PlannerMemory {
  std::uint32_t* cost;     // cell_count: cost so far, valid where stamp == the search's
  std::uint32_t* stamp;    // cell_count: which search wrote cost and move (0: none yet)
  std::uint8_t* move;      // cell_count: the move that reached the cell (2 * joint + direction)
  std::uint32_t* slot;     // cell_count: the cell's place in the heap, kNotQueued when not in it
  PlannerHeapEntry* heap;  // heap_capacity
  CellIndex* path;         // path_capacity
};

struct PlannerConfig {
  std::uint32_t clearance_weight = 6;  // per forbidden neighbour; kStepCost is 10
  std::uint32_t max_expansions = 2'000'000;
};

enum class PlanStatus : std::uint8_t {
  kFound,
  kGoalForbidden,
  kNoPath,       // every cell reachable from the start was searched
  kOutOfMemory,  // heap or path memory, or max_expansions, ran out first
  kInvalid,      // start or goal outside the grid
};

const char* to_string(PlanStatus status) noexcept;

struct PlanResult {
  PlanStatus status = PlanStatus::kInvalid;
  std::uint32_t length = 0;    // cells of the path, start and goal included
  std::uint32_t expanded = 0;  // cells taken off the heap
  // Without a path: the reached cell nearest the goal, and the forbidden cell next to it on the
  // way to the goal (along blocked_joint), which is what the operator is told.
  CellIndex closest_cell = 0;
  bool has_blocking_cell = false;
  CellIndex blocking_cell = 0;
  std::uint8_t blocked_joint = 0xFF;
};

class GridPlanner {
 public:
  static constexpr std::uint32_t kStepCost = 10;
  static constexpr std::uint32_t kNotQueued =
      0xFFFFFFFF;  // PlannerMemory::slot of a cell not queued

  GridPlanner(const CspaceGrid& grid, const PlannerLayout& layout, const PlannerMemory& memory,
              const PlannerConfig& config = {}) noexcept;

  // A path of free cells from start to goal (start itself may be forbidden: the robot is there).
  PlanResult plan(const MapView& map, CellIndex start, CellIndex goal) noexcept;
  // The last plan's path: path()[0] == start ... path()[length - 1] == goal.
  const CellIndex* path() const noexcept { return memory_.path; }

 private:
  std::uint32_t heuristic(const GridCoords& from, const GridCoords& goal) const noexcept;
  std::uint32_t entry_cost(const MapView& map, CellIndex cell,
                           const GridCoords& coords) const noexcept;
  // Puts the cell in the heap, or lowers its entry there; false when the heap is full.
  bool queue(PlannerHeapEntry entry) noexcept;
  void sift_up(std::uint32_t at, PlannerHeapEntry entry) noexcept;
  PlannerHeapEntry pop() noexcept;
  void describe_block(const MapView& map, CellIndex closest, const GridCoords& goal,
                      PlanResult& result) const noexcept;

  const CspaceGrid& grid_;
  PlannerLayout layout_;
  PlannerMemory memory_;
  PlannerConfig config_;
  std::uint32_t search_ = 0;
  std::uint32_t heap_size_ = 0;
};

}  // namespace safecell

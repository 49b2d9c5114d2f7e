#include "safecell/controller/grid_planner.hpp"

#include "safecell/base/assert.hpp"

namespace safecell {
namespace {

constexpr std::uint8_t kNoMove = 0xFF;

std::uint32_t distance(std::uint32_t a, std::uint32_t b) noexcept { return a > b ? a - b : b - a; }

}  // namespace

const char* to_string(PlanStatus status) noexcept {
  switch (status) {
    case PlanStatus::kFound:
      return "path found";
    case PlanStatus::kGoalForbidden:
      return "goal cell forbidden";
    case PlanStatus::kNoPath:
      return "no free path";
    case PlanStatus::kOutOfMemory:
      return "planner memory exhausted";
    case PlanStatus::kInvalid:
      return "start or goal outside the grid";
  }
  return "unknown";
}

GridPlanner::GridPlanner(const CspaceGrid& grid, const PlannerLayout& layout,
                         const PlannerMemory& memory, const PlannerConfig& config) noexcept
    : grid_(grid), layout_(layout), memory_(memory), config_(config) {
  SAFECELL_ASSERT(layout.cell_count == grid.cell_count() && layout.heap_capacity > 0 &&
                  layout.path_capacity > 1);
  SAFECELL_ASSERT(memory.cost != nullptr && memory.stamp != nullptr && memory.move != nullptr &&
                  memory.slot != nullptr && memory.heap != nullptr && memory.path != nullptr);
  for (CellIndex c = 0; c < layout.cell_count; ++c) memory_.stamp[c] = 0;
}

std::uint32_t GridPlanner::heuristic(const GridCoords& from,
                                     const GridCoords& goal) const noexcept {
  std::uint32_t cells = 0;
  for (std::uint32_t j = 0; j < grid_.joint_count(); ++j)
    cells += distance(from.along[j], goal.along[j]);
  return cells * kStepCost;
}

std::uint32_t GridPlanner::entry_cost(const MapView& map, CellIndex cell,
                                      const GridCoords& coords) const noexcept {
  std::uint32_t forbidden_neighbours = 0;
  for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
    const CellIndex stride = grid_.stride(j);
    if (coords.along[j] > 0 && map.forbidden(cell - stride)) ++forbidden_neighbours;
    if (coords.along[j] + 1 < grid_.cells_along(j) && map.forbidden(cell + stride)) {
      ++forbidden_neighbours;
    }
  }
  return kStepCost + config_.clearance_weight * forbidden_neighbours;
}

bool GridPlanner::queue(PlannerHeapEntry entry) noexcept {
  std::uint32_t at = memory_.slot[entry.cell];
  if (at == kNotQueued) {
    if (heap_size_ == layout_.heap_capacity) return false;
    at = heap_size_++;
  }
  // A queued cell only ever gets a lower priority (a cheaper way to it), so its entry moves up.
  sift_up(at, entry);
  return true;
}

void GridPlanner::sift_up(std::uint32_t at, PlannerHeapEntry entry) noexcept {
  while (at > 0) {
    const std::uint32_t parent = (at - 1) / 2;
    if (memory_.heap[parent].priority <= entry.priority) break;
    memory_.heap[at] = memory_.heap[parent];
    memory_.slot[memory_.heap[at].cell] = at;
    at = parent;
  }
  memory_.heap[at] = entry;
  memory_.slot[entry.cell] = at;
}

PlannerHeapEntry GridPlanner::pop() noexcept {
  const PlannerHeapEntry top = memory_.heap[0];
  memory_.slot[top.cell] = kNotQueued;
  const PlannerHeapEntry last = memory_.heap[--heap_size_];
  if (heap_size_ == 0) return top;
  std::uint32_t at = 0;
  for (;;) {
    std::uint32_t child = 2 * at + 1;
    if (child >= heap_size_) break;
    if (child + 1 < heap_size_ && memory_.heap[child + 1].priority < memory_.heap[child].priority) {
      ++child;
    }
    if (last.priority <= memory_.heap[child].priority) break;
    memory_.heap[at] = memory_.heap[child];
    memory_.slot[memory_.heap[at].cell] = at;
    at = child;
  }
  memory_.heap[at] = last;
  memory_.slot[last.cell] = at;
  return top;
}

PlanResult GridPlanner::plan(const MapView& map, CellIndex start, CellIndex goal) noexcept {
  PlanResult result;
  const Result<GridCoords> goal_coords = grid_.coords_of(goal);
  if (!grid_.coords_of(start).ok() || !goal_coords.ok()) return result;
  if (map.forbidden(goal)) {
    result.status = PlanStatus::kGoalForbidden;
    result.has_blocking_cell = true;
    result.blocking_cell = goal;
    return result;
  }
  if (++search_ == 0) {  // the stamps wrapped: forget them all once
    for (CellIndex c = 0; c < layout_.cell_count; ++c) memory_.stamp[c] = 0;
    search_ = 1;
  }
  heap_size_ = 0;
  memory_.stamp[start] = search_;
  memory_.cost[start] = 0;
  memory_.move[start] = kNoMove;
  memory_.slot[start] = kNotQueued;
  const std::uint32_t start_h = heuristic(grid_.coords_of(start).value(), goal_coords.value());
  (void)queue({start_h, start});
  CellIndex closest = start;
  std::uint32_t closest_h = start_h;
  bool out_of_memory = false;
  while (heap_size_ > 0) {
    const PlannerHeapEntry entry = pop();
    const GridCoords coords = grid_.coords_of(entry.cell).value();
    const std::uint32_t h = heuristic(coords, goal_coords.value());
    ++result.expanded;
    if (h < closest_h) {
      closest_h = h;
      closest = entry.cell;
    }
    if (entry.cell == goal) break;
    if (result.expanded >= config_.max_expansions) {
      out_of_memory = true;
      break;
    }
    for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
      for (std::uint8_t direction = 0; direction < 2; ++direction) {
        if (direction == 0 ? coords.along[j] == 0 : coords.along[j] + 1 >= grid_.cells_along(j)) {
          continue;
        }
        const CellIndex next =
            direction == 0 ? entry.cell - grid_.stride(j) : entry.cell + grid_.stride(j);
        if (map.forbidden(next)) continue;
        GridCoords next_coords = coords;
        next_coords.along[j] = direction == 0 ? coords.along[j] - 1 : coords.along[j] + 1;
        const std::uint32_t cost = memory_.cost[entry.cell] + entry_cost(map, next, next_coords);
        if (memory_.stamp[next] == search_) {
          if (memory_.cost[next] <= cost) continue;
        } else {
          memory_.stamp[next] = search_;
          memory_.slot[next] = kNotQueued;
        }
        memory_.cost[next] = cost;
        memory_.move[next] = static_cast<std::uint8_t>(2 * j + direction);
        if (!queue({cost + heuristic(next_coords, goal_coords.value()), next}))
          out_of_memory = true;
      }
    }
    if (out_of_memory) break;
  }
  if (memory_.stamp[goal] != search_ || (out_of_memory && closest != goal)) {
    result.status = out_of_memory ? PlanStatus::kOutOfMemory : PlanStatus::kNoPath;
    describe_block(map, closest, goal_coords.value(), result);
    return result;
  }
  // Walk back from the goal, then reverse.
  std::uint32_t length = 0;
  for (CellIndex cell = goal;;) {
    if (length == layout_.path_capacity) {
      result.status = PlanStatus::kOutOfMemory;
      return result;
    }
    memory_.path[length++] = cell;
    const std::uint8_t move = memory_.move[cell];
    if (cell == start || move == kNoMove) break;
    const CellIndex stride = grid_.stride(move / 2);
    cell = (move % 2) == 0 ? cell + stride : cell - stride;
  }
  for (std::uint32_t i = 0; i < length / 2; ++i) {
    const CellIndex swap = memory_.path[i];
    memory_.path[i] = memory_.path[length - 1 - i];
    memory_.path[length - 1 - i] = swap;
  }
  result.status = PlanStatus::kFound;
  result.length = length;
  return result;
}

void GridPlanner::describe_block(const MapView& map, CellIndex closest, const GridCoords& goal,
                                 PlanResult& result) const noexcept {
  result.closest_cell = closest;
  const GridCoords coords = grid_.coords_of(closest).value();
  for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
    if (coords.along[j] == goal.along[j]) continue;
    const CellIndex next =
        coords.along[j] < goal.along[j] ? closest + grid_.stride(j) : closest - grid_.stride(j);
    if (map.forbidden(next)) {
      result.has_blocking_cell = true;
      result.blocking_cell = next;
      result.blocked_joint = static_cast<std::uint8_t>(j);
      return;
    }
  }
}

}  // namespace safecell

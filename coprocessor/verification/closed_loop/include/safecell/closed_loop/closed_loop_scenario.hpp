#pragma once
// The scenarios of the closed-loop validation: a robot task (a start and a few goals, each move
// swinging the arm round its base) and a person's visit of one of three kinds, drawn at random:
//   approach  walks straight at the robot's base, stops within the arm's reach, reaches towards
//             it, and goes back out;
//   reach     walks to the edge of the arm's sweep and reaches into it;
//   cross     walks through the cell on a straight line, 0.8 .. 1.6 m past the robot's base.
// When the cell names its entries, people come in through one: they start outside, walk along the
// fence to where the visit's path begins, and after it walk along the fence to an entry and out
// (the walk in is timed so that they reach the path's start at the drawn time; it may begin
// before the run). Without entries they step in anywhere along the walls.
// The robot moves either as a robot program or with the gross-motion service (RobotTask).
// People walk at 0.8 .. 1.6 m/s (ISO 13855's approach speed is the top). Tasks come from a small
// pool, so that each task's time without people (its baseline) is run once. Every scenario is
// drawn from (seed, index) alone: one of a run can be run again by itself.

#include <cstdint>
#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/closed_loop/person_visit.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

struct RobotTask {
  std::size_t index = 0;  // in the pool
  // Even tasks move as a robot program (planned without the map: the look-ahead alone protects
  // people), odd ones with the safe gross-motion service (re-planned around people).
  bool program_motion = true;
  std::vector<double> start_rad;
  std::vector<std::vector<double>> goals_rad;
};

struct ClosedLoopScenario {
  std::size_t index = 0;
  std::string kind;  // approach, reach, cross
  RobotTask task;
  PersonVisitPlan person;
};

inline constexpr std::size_t kDefaultTaskPool = 8;

// Task `index` of the pool of a run with `seed`.
RobotTask draw_task(const CellModel& cell, const CspaceGrid& grid, std::uint64_t seed,
                    std::size_t index);

// Scenario `index` of a run with `seed`, its task from a pool of `task_pool`.
ClosedLoopScenario draw_scenario(const CellModel& cell, const CspaceGrid& grid, std::uint64_t seed,
                                 std::size_t index, std::size_t task_pool);

}  // namespace safecell

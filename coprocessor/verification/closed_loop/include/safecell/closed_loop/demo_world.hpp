#pragma once
// The world of the closed-loop demo: the robot's task (pick on one side, place on the other,
// repeated: every move sweeps the arm through the side of the cell the person comes to) and the
// person's visit: they come in through the cell's first entry (or, in a cell that names none, at
// a corner), walk along the fence towards the arm, stand and reach towards it, and walk out the
// way they came (to another corner). Times are seconds since the demo began.

#include <optional>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/closed_loop/person_visit.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

class DemoWorld {
 public:
  // The person comes in at `person_enters_s`. Goals and start lie inside the grid.
  DemoWorld(const CellModel& cell, const CspaceGrid& grid, double person_enters_s);

  [[nodiscard]] const std::vector<double>& start_rad() const { return start_rad_; }
  [[nodiscard]] const std::vector<std::vector<double>>& goals_rad() const { return goals_rad_; }

  // The person at time_s; nullopt while they are outside the cell.
  [[nodiscard]] std::optional<HumanPose> person_at(double time_s) const {
    return person_.at(time_s);
  }
  [[nodiscard]] double person_enters_s() const { return person_.enters_s(); }
  [[nodiscard]] double person_leaves_s() const { return person_.leaves_s(); }

 private:
  std::vector<double> start_rad_;
  std::vector<std::vector<double>> goals_rad_;
  PersonVisit person_;
};

}  // namespace safecell

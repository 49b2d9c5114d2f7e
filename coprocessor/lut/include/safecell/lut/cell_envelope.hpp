#pragma once
// The conservative envelope of a C-space cell: balls that hold every point of the robot for every
// configuration inside the cell (each joint anywhere within the cell's width; a joint that is not
// discretised anywhere in its range). This is what LUT-1 projects and what the static obstacles
// are tested against (DESIGN.md §3, "Conservativeness").
//
// Method. Each ball of link j is placed at the cell's centre configuration and then swept by
// joints j, j-1, ..., 0 in turn. Turning joint k by at most h about its axis moves the ball's
// centre, at distance r from the axis, by at most the chord 2 r sin(h / 2) (h capped at pi); the
// swept ball lies in the ball grown by that chord. For wide sweeps the ball about the centre's
// foot point on the axis, grown by r, is smaller and used instead. A prismatic joint grows it by
// half the cell's width. Turning joint k moves the axes of joints before it not at all, so the
// grown ball is then swept by joint k-1 the same way. No sampling: the bound holds exactly.
//
// This bound is the rigorous form of the paper's "m_max / 2": moving inside a cell along every
// discretised joint at once adds the joints' chords, so the envelope is wider than m_max / 2 for
// points far out on the arm.

#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/lut/robot_balls.hpp"
#include "safecell/robot/robot_model.hpp"

namespace safecell {

class CellEnvelope {
 public:
  // padding_m: added to every ball (calibration and model error). Throws std::invalid_argument
  // when the grid's joint count is not the robot's, or the padding is negative or not finite.
  CellEnvelope(const RobotModel& robot, RobotBalls balls, const CspaceGrid& grid, double padding_m);

  // The envelope of one cell, in the robot base frame (= the cell frame), into `balls` (cleared
  // first). Thread-safe; `balls` is the caller's scratch and keeps its capacity.
  // Precondition: coords inside the grid (std::out_of_range otherwise).
  void balls_of_cell(const GridCoords& coords, std::vector<Ball>& balls) const {
    balls_of_bodies(coords, 0, balls);
  }

  // Bodies: 0 is the base, body j + 1 is link j. The balls of body b depend only on the cells of
  // joints 0..b-1, so for the bodies near the base whose joints have few cell combinations
  // ("prefixes") they can be computed once per prefix and reused by every cell that shares it.
  [[nodiscard]] std::size_t body_count() const { return robot_balls_.links.size() + 1; }
  // The first body with more than `max_prefixes` prefixes; bodies before it are worth caching.
  [[nodiscard]] std::size_t first_uncached_body(std::size_t max_prefixes) const;
  [[nodiscard]] std::size_t prefix_count(std::size_t body) const;
  [[nodiscard]] std::size_t prefix_of(const GridCoords& coords, std::size_t body) const;
  // The balls of one body for one prefix (appended to `balls`).
  void append_body_balls(std::size_t body, std::size_t prefix, std::vector<Ball>& balls) const;
  // The balls of bodies first_body.. of the cell, into `balls` (cleared first).
  void balls_of_bodies(const GridCoords& coords, std::size_t first_body,
                       std::vector<Ball>& balls) const;

  [[nodiscard]] const CspaceGrid& grid() const { return grid_; }
  [[nodiscard]] std::size_t ball_count() const { return robot_balls_.count(); }

 private:
  void append_balls(const GridCoords& coords, std::size_t first_body, std::size_t end_body,
                    std::vector<Ball>& balls) const;

  RobotModel robot_;
  RobotBalls robot_balls_;
  CspaceGrid grid_;
  double padding_m_;
};

}  // namespace safecell

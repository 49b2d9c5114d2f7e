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
//
// Head and tail. The bodies near the base (the head) depend on few joint-cell combinations
// ("prefixes"), so users derive what they need from them once per prefix. The balls of the
// other bodies (the tail, links k.. with k = tail_body() - 1) are swept by joints n-1..k in the
// frame of link k, where joint k's axis is fixed and the result depends only on the cells of
// joints k+1..: made once per such combination at construction, and balls held wholly inside
// another ball of the same combination dropped (the swept wrist collapses into a few large balls).
// Per cell only the rest remains: place them with link k's pose and sweep by joints k-1..0. The
// envelope holds the robot all the same: every point lies in a kept ball before the last sweeps,
// and the sweeps of that ball hold its paths.
//
// Parts. The fusion votes per robot part (robot_parts.hpp), so each part's envelope must be had
// on its own. The tail tables are kept per segment of the tail, cut where a part begins: a ball
// dropped as inside another is then only ever dropped for one of its own part.

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/envelope/robot_balls.hpp"
#include "safecell/geometry/point_transform.hpp"
#include "safecell/robot/robot_model.hpp"

namespace safecell {

class CellEnvelope {
 public:
  // Bodies with at most this many prefixes belong to the head, unless told otherwise.
  static constexpr std::size_t kMaxHeadPrefixes = 4096;
  // Tail tables larger than this many balls in all are not made; the tail is then computed per
  // cell like the head.
  static constexpr std::size_t kMaxTailBalls = std::size_t{1} << 18;
  // Changes whenever the balls of a cell change (table fingerprints include it). 2: tail tables;
  // 3: tail tables per part segment; 4: users move the tail along lines of joint-0 cells and
  // grow it by 1e-9 m (first_joint_motions).
  static constexpr std::uint32_t kMethodVersion = 4;

  // padding_m: added to every ball (calibration and model error). part_starts: the first body of
  // each part (ascending; body 0 implied), where the tail tables are cut. Bodies with at most
  // max_head_prefixes prefixes form the head. Throws std::invalid_argument when the grid's joint
  // count is not the robot's, the padding is negative or not finite, or a part start is not a
  // body.
  CellEnvelope(const RobotModel& robot, RobotBalls balls, const CspaceGrid& grid, double padding_m,
               const std::vector<std::size_t>& part_starts = {},
               std::size_t max_head_prefixes = kMaxHeadPrefixes);

  // The envelope of one cell, in the robot base frame (= the cell frame), into `balls` (cleared
  // first). Thread-safe; `balls` is the caller's scratch and keeps its capacity.
  // Precondition: coords inside the grid (std::out_of_range otherwise).
  void balls_of_cell(const GridCoords& coords, std::vector<Ball>& balls) const {
    balls_of_bodies(coords, 0, body_count(), balls);
  }

  // Bodies: 0 is the base, body j + 1 is link j. The balls of body b depend only on the cells of
  // joints 0..b-1 (its prefix).
  [[nodiscard]] std::size_t body_count() const { return robot_balls_.links.size() + 1; }
  // The first body of the tail (body_count() when every body has few prefixes).
  [[nodiscard]] std::size_t tail_body() const { return tail_body_; }
  [[nodiscard]] std::size_t prefix_count(std::size_t body) const;
  [[nodiscard]] std::size_t prefix_of(const GridCoords& coords, std::size_t body) const;
  // The balls of one body for one prefix (appended to `balls`).
  void append_body_balls(std::size_t body, std::size_t prefix, std::vector<Ball>& balls) const;
  // The balls of bodies first_body..end_body-1 of the cell, into `balls` (cleared first).
  // Thread-safe. From the tail tables where the range begins and ends at segment bounds.
  void balls_of_bodies(const GridCoords& coords, std::size_t first_body, std::size_t end_body,
                       std::vector<Ball>& balls) const;
  // For tests that most cells fail (a static obstacle far from most of the robot): balls that
  // hold every ball balls_of_bodies gives the cell's tail, into `bounds` (cleared first). The tail
  // tables' balls of each suffix are bounded once at construction, a few neighbours per bound;
  // per cell each bound is placed and grown by the sweeps of joints k-1..0 as if its balls were
  // at its far side: several times fewer operations than the balls. Returns false, `bounds` empty,
  // when there are no tail tables or one of those joints' cells is wider than 120 degrees (a sweep
  // may then move a ball's centre, which the bound does not follow). No grid that make_grid
  // accepts has such cells (a discretised joint's l_i is at least m_max / 2, so its cells are at
  // most 2 rad wide), so no test reaches that refusal: it keeps a later change to the grid from
  // making the bounds wrong without a sign. Thread-safe.
  bool tail_bounds(const GridCoords& coords, std::vector<Ball>& bounds) const;
  // Joint 0 moves everything after it rigidly, about (or along) its own axis, which no joint
  // moves; the sweeps keep their sizes under that motion (the axes of later joints move along,
  // joint 0's own sweep depends only on the distance from its axis). So the balls of bodies 1..
  // (all but the base) of a cell are those of the cell with joint 0 at its first cell and the
  // other joints' cells the same, moved by motions[coords.along[0]]: one motion per cell of joint
  // 0, into `motions` (cleared first). Equal up to rounding (about 1e-15 m per metre from the
  // axis): moved_ball adds a margin far above it. Thread-safe.
  void first_joint_motions(std::vector<Eigen::Isometry3d>& motions) const;
  // The ball moved by one of first_joint_motions and grown by kMotionMargin_m, so that it holds
  // the ball computed for the cell directly.
  static constexpr double kMotionMargin_m = 1e-9;
  [[nodiscard]] static Ball moved_ball(const Eigen::Isometry3d& motion, const Ball& ball) {
    return Ball{transform_point(motion, ball.centre_m), ball.radius_m + kMotionMargin_m};
  }
  // How many balls the tail tables hold in all (0 when there are none).
  [[nodiscard]] std::size_t tail_table_balls() const;

  [[nodiscard]] const CspaceGrid& grid() const { return grid_; }
  [[nodiscard]] std::size_t ball_count() const { return robot_balls_.count(); }

 private:
  struct CellFrames;  // link poses and joint axes at a cell's centre

  [[nodiscard]] const CellFrames& frames_of(const GridCoords& coords) const;
  // The balls of bodies first_body..end_body-1, each swept by its joints down to joint
  // lowest_joint.
  void append_link_balls(const CellFrames& frames, std::size_t first_body, std::size_t end_body,
                         std::size_t lowest_joint, std::vector<Ball>& balls) const;
  void make_tail_tables(std::size_t max_head_prefixes, const std::vector<std::size_t>& part_starts);
  [[nodiscard]] std::size_t suffix_of(const GridCoords& coords) const;
  // The tail segment that begins at `body`, or segment_starts_.size() when none does.
  [[nodiscard]] std::size_t segment_starting_at(std::size_t body) const;

  RobotModel robot_;
  RobotBalls robot_balls_;
  CspaceGrid grid_;
  double padding_m_;
  std::size_t tail_body_ = 0;
  // First body of each tail segment, ascending; the last ends at body_count().
  std::vector<std::size_t> segment_starts_;
  // [segment][suffix]: in link (tail_body_ - 1)'s frame; empty when there are no tables.
  std::vector<std::vector<std::vector<Ball>>> tail_tables_;
  // [segment][suffix]: balls that hold the balls of tail_tables_[segment][suffix], same frame.
  std::vector<std::vector<std::vector<Ball>>> tail_bounds_;
};

}  // namespace safecell

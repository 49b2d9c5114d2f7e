#pragma once
// Neighbouring balls gathered under one bounding ball, so that a drawing can skip a whole group
// whose bound's image rectangle a mask already holds (add_grouped_ball_rects): the table builds
// draw a cell's silhouette as the union of its sub-cells' balls, and almost all of those balls
// land where an earlier sub-cell drew already.

#include <cstdint>
#include <span>
#include <vector>

#include "safecell/envelope/ball_projection.hpp"
#include "safecell/envelope/robot_balls.hpp"
#include "safecell/features/feature_mask.hpp"

namespace safecell {

struct BallGroup {
  Ball bound;               // holds every ball of the group, with kBoundMargin_m to spare
  std::uint32_t first = 0;  // the group's balls: balls[first .. end - 1]
  std::uint32_t end = 0;

  // Added to every bound, metres: far above the rounding of the image rectangles (about 1e-15 of
  // a metre per metre), so that a ball that touches its bound from inside still has its
  // rectangle inside the bound's.
  static constexpr double kBoundMargin_m = 1e-6;
};

// Orders `balls` so that near balls lie next to each other (Z-order of their centres; the set
// of balls is unchanged) and cuts them into runs of up to `group_size` balls, each with a bound,
// into `groups` (cleared first). A group with a ball that is not finite gets a bound of infinite
// radius. Throws std::invalid_argument for group_size 0 or more than 2^32 - 1 balls.
void group_balls(std::vector<Ball>& balls, std::size_t group_size, std::vector<BallGroup>& groups);

// mask |= the feature rectangle of every ball, as add_ball_rects(projection, balls, mask) does,
// skipping each group whose bound's rectangle the mask holds all of already (or whose bound the
// camera does not see). The same mask to the bit: where the projection's rectangles nest
// (BallProjection::rectangles_nest()), a ball inside the bound has its rectangle inside the
// bound's; where they do not, every ball is drawn. Throws std::invalid_argument unless the groups
// cut the balls into consecutive runs from the first ball to the last.
void add_grouped_ball_rects(const BallProjection& projection, std::span<const Ball> balls,
                            std::span<const BallGroup> groups, FeatureMask& mask);

}  // namespace safecell

#include "safecell/envelope/ball_groups.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace safecell {
namespace {

// Bits 0, 3, 6, ... of the result are those of x (x < 2^10).
std::uint32_t spread_bits(std::uint32_t x) {
  x = (x | (x << 16U)) & 0x030000FFU;
  x = (x | (x << 8U)) & 0x0300F00FU;
  x = (x | (x << 4U)) & 0x030C30C3U;
  x = (x | (x << 2U)) & 0x09249249U;
  return x;
}

// The box of the balls' finite centres (low > high when there is none).
std::pair<Eigen::Vector3d, Eigen::Vector3d> centres_box(std::span<const Ball> balls) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  for (const Ball& ball : balls) {
    if (!ball.centre_m.allFinite()) continue;
    low = low.cwiseMin(ball.centre_m);
    high = high.cwiseMax(ball.centre_m);
  }
  return {low, high};
}

// The smallest ball around the middle of the balls' centres that holds them all, plus the margin;
// a ball of infinite radius when one of them is not finite (its rectangle is then the whole
// image, as add_ball_rects draws such a ball).
Ball bound_of(std::span<const Ball> balls) {
  for (const Ball& ball : balls) {
    if (!ball.centre_m.allFinite() || !std::isfinite(ball.radius_m)) {
      return Ball{Eigen::Vector3d::Zero(), std::numeric_limits<double>::infinity()};
    }
  }
  const auto [low, high] = centres_box(balls);
  const Eigen::Vector3d middle = 0.5 * (low + high);
  double radius_m = 0.0;
  for (const Ball& ball : balls) {
    radius_m = std::max(radius_m, (ball.centre_m - middle).norm() + ball.radius_m);
  }
  return Ball{middle, radius_m + BallGroup::kBoundMargin_m};
}

}  // namespace

void group_balls(std::vector<Ball>& balls, std::size_t group_size, std::vector<BallGroup>& groups) {
  if (group_size == 0) throw std::invalid_argument("balls grouped by 0");
  if (balls.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument(std::to_string(balls.size()) +
                                " balls, more than a group can name");
  }
  groups.clear();
  if (balls.empty()) return;
  // 1024 steps along the longest side of the finite centres' box.
  const auto box = centres_box(balls);
  const Eigen::Vector3d& low = box.first;
  const Eigen::Vector3d& high = box.second;
  const double extent = (high - low).maxCoeff();
  const double steps_per_m = std::isfinite(extent) && extent > 0.0 ? 1023.0 / extent : 0.0;
  const auto z_order = [&](const Ball& ball) {
    std::uint32_t code = 0;
    if (!ball.centre_m.allFinite() || steps_per_m <= 0.0) return code;
    for (int axis = 0; axis < 3; ++axis) {
      const auto step =
          static_cast<std::uint32_t>(std::lround((ball.centre_m[axis] - low[axis]) * steps_per_m));
      code |= spread_bits(std::min<std::uint32_t>(step, 1023U)) << static_cast<unsigned>(axis);
    }
    return code;
  };
  std::stable_sort(balls.begin(), balls.end(),
                   [&](const Ball& a, const Ball& b) { return z_order(a) < z_order(b); });
  for (std::size_t first = 0; first < balls.size(); first += group_size) {
    const std::size_t end = std::min(balls.size(), first + group_size);
    groups.push_back(BallGroup{bound_of(std::span<const Ball>(balls).subspan(first, end - first)),
                               static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(end)});
  }
}

void add_grouped_ball_rects(const BallProjection& projection, std::span<const Ball> balls,
                            std::span<const BallGroup> groups, FeatureMask& mask) {
  // The groups must name every ball once, in order: a ball left out would never be drawn.
  std::size_t next = 0;
  for (const BallGroup& group : groups) {
    if (group.first != next || group.end < group.first || group.end > balls.size()) {
      throw std::invalid_argument("ball groups that do not cut the " +
                                  std::to_string(balls.size()) + " balls into runs");
    }
    next = group.end;
  }
  if (next != balls.size()) {
    throw std::invalid_argument("ball groups that name " + std::to_string(next) + " of " +
                                std::to_string(balls.size()) + " balls");
  }
  if (!projection.rectangles_nest()) {
    add_ball_rects(projection, balls, mask);
    return;
  }
  // The bounds of a chunk of groups are projected together, and the balls of the groups the mask
  // does not hold yet are drawn together: both project several balls at a time.
  constexpr std::size_t kChunk = 32;
  thread_local std::vector<Ball> bounds;
  thread_local std::vector<Ball> drawn;
  std::optional<FeatureRect> rects[kChunk];
  for (std::size_t first = 0; first < groups.size(); first += kChunk) {
    const std::size_t count = std::min(kChunk, groups.size() - first);
    bounds.clear();
    for (std::size_t i = 0; i < count; ++i) bounds.push_back(groups[first + i].bound);
    projection.feature_rects(bounds, {rects, count});
    drawn.clear();
    for (std::size_t i = 0; i < count; ++i) {
      if (!rects[i] || mask.all_in_rect(*rects[i])) continue;
      const BallGroup& group = groups[first + i];
      drawn.insert(drawn.end(), balls.begin() + group.first, balls.begin() + group.end);
    }
    add_ball_rects(projection, drawn, mask);
  }
}

}  // namespace safecell

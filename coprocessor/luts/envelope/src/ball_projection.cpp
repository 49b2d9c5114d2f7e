#include "safecell/envelope/ball_projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "safecell/compute/cpu_clones.hpp"

namespace safecell {
namespace {

// A ball closer to the camera plane than this covers the whole image.
constexpr double kNearPlane_m = 1e-3;
constexpr int kEdgeSamples = 32;
constexpr double kCurvatureMargin_px = 2.0;

// Balls projected per call of tangent_ranges: a fixed count, so that the compiler vectorises the
// loop without a remainder.
constexpr std::size_t kBatch = 16;

// Per ball of a batch, in the camera frame: the depth range of the ball, and the normalised image
// coordinate range [x0, x1] x [y0, y1] that its tangent planes through the optical centre bound:
// x = (x z +- r sqrt(x^2 + z^2 - r^2)) / (z^2 - r^2), the same for y. Lanes of balls that reach
// the plane z = kNearPlane_m are finite but meaningless.
struct TangentRanges {
  double z_near[kBatch];
  double z_far[kBatch];
  double x0[kBatch];
  double x1[kBatch];
  double y0[kBatch];
  double y1[kBatch];
};

// Branch-free, so that several balls share each square root and division instruction (this runs
// for every ball of the robot's cell in every camera each cycle). The file is compiled without
// errno for math functions and without trapping comparisons, which lets this loop vectorise.
SAFECELL_CPU_CLONES void tangent_ranges(const double (&transform)[3][4],
                                        const Ball* __restrict balls,
                                        TangentRanges& __restrict ranges) {
  double m[3][4];  // a copy the stores below cannot alias, so that it stays in registers
  std::copy(&transform[0][0], &transform[0][0] + 12, &m[0][0]);
  for (std::size_t i = 0; i < kBatch; ++i) {
    const Eigen::Vector3d& c = balls[i].centre_m;
    const double x = m[0][0] * c.x() + m[0][1] * c.y() + m[0][2] * c.z() + m[0][3];
    const double y = m[1][0] * c.x() + m[1][1] * c.y() + m[1][2] * c.z() + m[1][3];
    const double z = m[2][0] * c.x() + m[2][1] * c.y() + m[2][2] * c.z() + m[2][3];
    const double radius = balls[i].radius_m;
    ranges.z_near[i] = z - radius;
    ranges.z_far[i] = z + radius;
    const double denominator = z - radius <= kNearPlane_m ? 1.0 : z * z - radius * radius;
    const double inverse = 1.0 / denominator;
    const double root_x = radius * std::sqrt(x * x + denominator);
    const double root_y = radius * std::sqrt(y * y + denominator);
    ranges.x0[i] = (x * z - root_x) * inverse;
    ranges.x1[i] = (x * z + root_x) * inverse;
    ranges.y0[i] = (y * z - root_y) * inverse;
    ranges.y1[i] = (y * z + root_y) * inverse;
  }
}

// Per ball of a batch, the feature columns and rows its pixel box spans, before clipping: -1 for
// an edge left of (above) the image, columns (rows) for one right of (below) it.
struct CellRanges {
  int col0[kBatch];
  int col1[kBatch];
  int row0[kBatch];
  int row1[kBatch];
};

// From normalised image coordinates to feature cells, without lens distortion.
struct PixelToCell {
  double fx_px, cx_px, fy_px, cy_px;
  double inverse_cell_width, inverse_cell_height;
  double columns, rows;
};

// The feature column (row) of a box edge at pixel coordinate px. Pixel centres are integers:
// pixel column c covers u in [c - 0.5, c + 0.5), so feature column floor((u + 0.5) / cell
// width), held to -1..count before the conversion so that huge boxes (a ball at the camera)
// convert safely; -1 and count mark "outside". Not a number goes to the edge that widens the box
// (callers make such a box the whole image). Branch-free.
inline int low_edge(double px, double inverse, double count) {
  const double cell = std::floor((px + 0.5) * inverse);
  const double held = cell > -1.0 ? cell : -1.0;  // and NaN
  return static_cast<int>(held < count ? held : count);
}
inline int high_edge(double px, double inverse, double count) {
  const double cell = std::floor((px + 0.5) * inverse);
  const double held = cell < count ? cell : count;  // and NaN
  return static_cast<int>(held > -1.0 ? held : -1.0);
}

// low_edge and high_edge of every ball of a batch at once, for the same reason as tangent_ranges.
SAFECELL_CPU_CLONES void feature_cell_ranges(const TangentRanges& __restrict ranges,
                                             const PixelToCell& scale,
                                             CellRanges& __restrict cells) {
  for (std::size_t i = 0; i < kBatch; ++i) {
    cells.col0[i] =
        low_edge(scale.fx_px * ranges.x0[i] + scale.cx_px, scale.inverse_cell_width, scale.columns);
    cells.col1[i] = high_edge(scale.fx_px * ranges.x1[i] + scale.cx_px, scale.inverse_cell_width,
                              scale.columns);
    cells.row0[i] =
        low_edge(scale.fy_px * ranges.y0[i] + scale.cy_px, scale.inverse_cell_height, scale.rows);
    cells.row1[i] =
        high_edge(scale.fy_px * ranges.y1[i] + scale.cy_px, scale.inverse_cell_height, scale.rows);
  }
}

}  // namespace

BallProjection::BallProjection(const PinholeCamera& camera, const FeatureGrid& grid)
    : intrinsics_(camera.intrinsics()),
      grid_(grid),
      distorted_(!(camera.intrinsics().distortion == LensDistortion{})),
      max_radius_sq_(monotonic_radius_sq(camera.intrinsics().distortion)),
      inverse_cell_width_(1.0 / grid.cell_width_px()),
      inverse_cell_height_(1.0 / grid.cell_height_px()) {
  if (grid.image_width_px() != intrinsics_.width_px ||
      grid.image_height_px() != intrinsics_.height_px) {
    throw std::invalid_argument(
        "camera '" + camera.name() + "' has " + std::to_string(intrinsics_.width_px) + " x " +
        std::to_string(intrinsics_.height_px) + " px, the feature grid covers " +
        std::to_string(grid.image_width_px()) + " x " + std::to_string(grid.image_height_px()));
  }
  const Eigen::Isometry3d& to_camera = camera.cell_to_camera();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) transform_[r][c] = to_camera.linear()(r, c);
    transform_[r][3] = to_camera.translation()(r);
  }
}

inline std::optional<FeatureRect> BallProjection::cells_of(const PixelBox& box) const {
  const auto columns = static_cast<double>(grid_.columns());
  const auto rows = static_cast<double>(grid_.rows());
  if (std::isnan(box.u0 + box.u1 + box.v0 + box.v1)) {  // cannot happen for finite balls; be safe
    return FeatureRect{0, 0, static_cast<std::uint16_t>(grid_.columns() - 1),
                       static_cast<std::uint16_t>(grid_.rows() - 1)};
  }
  return clipped(low_edge(box.u0, inverse_cell_width_, columns),
                 low_edge(box.v0, inverse_cell_height_, rows),
                 high_edge(box.u1, inverse_cell_width_, columns),
                 high_edge(box.v1, inverse_cell_height_, rows));
}

inline std::optional<FeatureRect> BallProjection::clipped(int col0, int row0, int col1,
                                                          int row1) const {
  if (col1 < 0 || row1 < 0 || col0 >= grid_.columns() || row0 >= grid_.rows()) return std::nullopt;
  return FeatureRect{static_cast<std::uint16_t>(std::max(col0, 0)),
                     static_cast<std::uint16_t>(std::max(row0, 0)),
                     static_cast<std::uint16_t>(std::min(col1, grid_.columns() - 1)),
                     static_cast<std::uint16_t>(std::min(row1, grid_.rows() - 1))};
}

std::optional<FeatureRect> BallProjection::feature_rect(const Ball& ball_in_cell) const {
  std::optional<FeatureRect> rect;
  feature_rects({&ball_in_cell, 1}, {&rect, 1});
  return rect;
}

void BallProjection::feature_rects(std::span<const Ball> balls_in_cell,
                                   std::span<std::optional<FeatureRect>> rects) const {
  if (balls_in_cell.size() != rects.size()) {
    throw std::invalid_argument(std::to_string(balls_in_cell.size()) + " balls, room for " +
                                std::to_string(rects.size()) + " rectangles");
  }
  const PixelBox whole_image{-1e9, -1e9, 1e9, 1e9};
  const PixelToCell scale{intrinsics_.fx_px,
                          intrinsics_.cx_px,
                          intrinsics_.fy_px,
                          intrinsics_.cy_px,
                          inverse_cell_width_,
                          inverse_cell_height_,
                          static_cast<double>(grid_.columns()),
                          static_cast<double>(grid_.rows())};
  Ball padded[kBatch];  // the last, partial batch; the rest are balls of radius 0
  TangentRanges ranges;
  CellRanges cells;
  for (std::size_t first = 0; first < balls_in_cell.size(); first += kBatch) {
    const std::size_t count = std::min(kBatch, balls_in_cell.size() - first);
    const Ball* batch = balls_in_cell.data() + first;
    if (count < kBatch) batch = std::copy_n(batch, count, padded) - count;
    tangent_ranges(transform_, batch, ranges);
    if (!distorted_) feature_cell_ranges(ranges, scale, cells);
    for (std::size_t i = 0; i < count; ++i) {
      std::optional<FeatureRect>& rect = rects[first + i];
      if (ranges.z_near[i] <= kNearPlane_m) {
        rect = ranges.z_far[i] <= kNearPlane_m ? std::nullopt : cells_of(whole_image);
        continue;
      }
      if (!distorted_) {
        if (std::isnan(ranges.x0[i] + ranges.x1[i] + ranges.y0[i] + ranges.y1[i])) {
          rect = cells_of(whole_image);  // cannot happen for finite balls; be safe
        } else {
          rect = clipped(cells.col0[i], cells.row0[i], cells.col1[i], cells.row1[i]);
        }
        continue;
      }
      const auto box = distorted_box(ranges.x0[i], ranges.y0[i], ranges.x1[i], ranges.y1[i]);
      rect = cells_of(box ? *box : whole_image);
    }
  }
}

std::optional<BallProjection::PixelBox> BallProjection::distorted_box(double x0, double y0,
                                                                      double x1, double y1) const {
  // The lens model is monotonic in r only up to max_radius_sq_: the box must stay inside it.
  const double far_x = std::max(std::abs(x0), std::abs(x1));
  const double far_y = std::max(std::abs(y0), std::abs(y1));
  if (far_x * far_x + far_y * far_y >= max_radius_sq_) return std::nullopt;
  PixelBox box{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
               -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  const auto add = [&](double x, double y) {
    const Eigen::Vector2d d = distort(intrinsics_.distortion, {x, y});
    const double u = intrinsics_.fx_px * d.x() + intrinsics_.cx_px;
    const double v = intrinsics_.fy_px * d.y() + intrinsics_.cy_px;
    box.u0 = std::min(box.u0, u);
    box.u1 = std::max(box.u1, u);
    box.v0 = std::min(box.v0, v);
    box.v1 = std::max(box.v1, v);
  };
  for (int i = 0; i <= kEdgeSamples; ++i) {
    const double s = static_cast<double>(i) / kEdgeSamples;
    const double x = x0 + s * (x1 - x0);
    const double y = y0 + s * (y1 - y0);
    add(x, y0);
    add(x, y1);
    add(x0, y);
    add(x1, y);
  }
  box.u0 -= kCurvatureMargin_px;
  box.v0 -= kCurvatureMargin_px;
  box.u1 += kCurvatureMargin_px;
  box.v1 += kCurvatureMargin_px;
  return box;
}

void add_ball_rects(const BallProjection& projection, std::span<const Ball> balls_in_cell,
                    FeatureMask& mask) {
  // All balls of a chunk projected before any is drawn: the projection works on several balls at
  // a time.
  constexpr std::size_t kChunk = 64;
  std::optional<FeatureRect> rects[kChunk];
  for (std::size_t first = 0; first < balls_in_cell.size(); first += kChunk) {
    const std::size_t count = std::min(kChunk, balls_in_cell.size() - first);
    projection.feature_rects(balls_in_cell.subspan(first, count), {rects, count});
    for (std::size_t i = 0; i < count; ++i) {
      if (rects[i]) mask.set_rect(*rects[i]);
    }
  }
}

}  // namespace safecell

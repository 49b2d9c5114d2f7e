#include "safecell/lut/ball_projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace safecell {
namespace {

// A ball closer to the camera plane than this covers the whole image.
constexpr double kNearPlane_m = 1e-3;
constexpr int kEdgeSamples = 32;
constexpr double kCurvatureMargin_px = 2.0;

// The normalised coordinate range [lo, hi] of a ball along one image axis, from the tangent
// planes through the optical centre (see the header). denominator = z^2 - r^2 > 0.
void tangent_range(double x, double z, double radius, double denominator, double inverse,
                   double& lo, double& hi) {
  const double root = radius * std::sqrt(x * x + denominator);
  lo = (x * z - root) * inverse;
  hi = (x * z + root) * inverse;
}

}  // namespace

BallProjection::BallProjection(const PinholeCamera& camera, const FeatureGrid& grid)
    : rotation_(camera.cell_to_camera().linear()),
      translation_(camera.cell_to_camera().translation()),
      intrinsics_(camera.intrinsics()),
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
}

inline std::optional<FeatureRect> BallProjection::cells_of(const PixelBox& box) const {
  // Pixel centres are integers: pixel column c covers u in [c - 0.5, c + 0.5), so feature
  // column floor((u + 0.5) / cell width). Clamped before the conversion, so that huge boxes
  // (a ball at the camera) convert safely; -1 and columns() mark "outside".
  const auto cell_of = [](double px, double inverse_size, int count) {
    const double cell = (px + 0.5) * inverse_size;
    if (cell < 0.0) return -1;
    if (cell >= count) return count;
    return static_cast<int>(cell);
  };
  if (std::isnan(box.u0 + box.u1 + box.v0 + box.v1)) {  // cannot happen for finite balls; be safe
    return FeatureRect{0, 0, static_cast<std::uint16_t>(grid_.columns() - 1),
                       static_cast<std::uint16_t>(grid_.rows() - 1)};
  }
  const int col0 = cell_of(box.u0, inverse_cell_width_, grid_.columns());
  const int col1 = cell_of(box.u1, inverse_cell_width_, grid_.columns());
  const int row0 = cell_of(box.v0, inverse_cell_height_, grid_.rows());
  const int row1 = cell_of(box.v1, inverse_cell_height_, grid_.rows());
  if (col1 < 0 || row1 < 0 || col0 >= grid_.columns() || row0 >= grid_.rows()) return std::nullopt;
  return FeatureRect{static_cast<std::uint16_t>(std::max(col0, 0)),
                     static_cast<std::uint16_t>(std::max(row0, 0)),
                     static_cast<std::uint16_t>(std::min(col1, grid_.columns() - 1)),
                     static_cast<std::uint16_t>(std::min(row1, grid_.rows() - 1))};
}

std::optional<FeatureRect> BallProjection::feature_rect(const Ball& ball_in_cell) const {
  // Written out: this runs for every ball of the robot's cell in every camera each cycle, and
  // Eigen's fixed-size product was not inlined here.
  const Eigen::Vector3d& c = ball_in_cell.centre_m;
  const Eigen::Matrix3d& r = rotation_;
  const Eigen::Vector3d centre(
      r(0, 0) * c.x() + r(0, 1) * c.y() + r(0, 2) * c.z() + translation_.x(),
      r(1, 0) * c.x() + r(1, 1) * c.y() + r(1, 2) * c.z() + translation_.y(),
      r(2, 0) * c.x() + r(2, 1) * c.y() + r(2, 2) * c.z() + translation_.z());
  const double radius = ball_in_cell.radius_m;
  if (centre.z() - radius <= kNearPlane_m) {
    if (centre.z() + radius <= kNearPlane_m) return std::nullopt;  // wholly behind the camera
    return cells_of(PixelBox{-1e9, -1e9, 1e9, 1e9});
  }
  double x0 = 0.0;
  double x1 = 0.0;
  double y0 = 0.0;
  double y1 = 0.0;
  const double denominator = centre.z() * centre.z() - radius * radius;
  const double inverse = 1.0 / denominator;
  tangent_range(centre.x(), centre.z(), radius, denominator, inverse, x0, x1);
  tangent_range(centre.y(), centre.z(), radius, denominator, inverse, y0, y1);
  if (!distorted_) {
    return cells_of(PixelBox{
        intrinsics_.fx_px * x0 + intrinsics_.cx_px, intrinsics_.fy_px * y0 + intrinsics_.cy_px,
        intrinsics_.fx_px * x1 + intrinsics_.cx_px, intrinsics_.fy_px * y1 + intrinsics_.cy_px});
  }
  const auto box = distorted_box(x0, y0, x1, y1);
  return box ? cells_of(*box) : cells_of(PixelBox{-1e9, -1e9, 1e9, 1e9});
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

}  // namespace safecell

#pragma once
// Which feature cells of a camera a ball can cover: the bounding rectangle of its image.
//
// Without lens distortion the box is exact: the planes through the optical centre tangent to
// the ball touch it at normalised x = (x z +- r sqrt(x^2 + z^2 - r^2)) / (z^2 - r^2), and the same
// for y. With distortion the box's edges are sampled densely, distorted, and the result grown by
// two pixels for the curvature between samples. A ball that reaches the camera plane, or whose box
// leaves the range where the lens model holds, covers the whole image.

#include <optional>
#include <span>

#include "safecell/camera/feature_grid.hpp"
#include "safecell/camera/pinhole_camera.hpp"
#include "safecell/envelope/robot_balls.hpp"
#include "safecell/features/feature_mask.hpp"

namespace safecell {

class BallProjection {
 public:
  // Throws std::invalid_argument when the grid does not tile the camera's image size.
  BallProjection(const PinholeCamera& camera, const FeatureGrid& grid);

  // The feature cells the ball's image can touch, clipped to the image; nullopt when the image
  // lies wholly outside it (or behind the camera).
  [[nodiscard]] std::optional<FeatureRect> feature_rect(const Ball& ball_in_cell) const;
  // feature_rect() of every ball, into the same place of `rects`: the same rectangles, computed
  // several balls at a time. Throws std::invalid_argument when the spans differ in size.
  void feature_rects(std::span<const Ball> balls_in_cell,
                     std::span<std::optional<FeatureRect>> rects) const;
  // Whether a ball inside another has its rectangle inside the other's (or none): true without
  // lens distortion, where the rectangles are exact. With distortion the box's edges are sampled,
  // and the nesting holds only up to the sampling.
  [[nodiscard]] bool rectangles_nest() const { return !distorted_; }

 private:
  struct PixelBox {
    double u0, v0, u1, v1;
  };
  [[nodiscard]] std::optional<PixelBox> distorted_box(double x0, double y0, double x1,
                                                      double y1) const;
  [[nodiscard]] std::optional<FeatureRect> cells_of(const PixelBox& box) const;
  // A box of feature columns col0..col1 and rows row0..row1 (-1 and columns/rows: beyond the
  // image) clipped to the image; nullopt when it lies wholly outside.
  [[nodiscard]] std::optional<FeatureRect> clipped(int col0, int row0, int col1, int row1) const;

  // Cell frame to camera frame, row by row: x, y, z = the rows applied to (x, y, z, 1).
  double transform_[3][4] = {};
  CameraIntrinsics intrinsics_;
  FeatureGrid grid_;
  bool distorted_ = false;
  double max_radius_sq_ = 0.0;
  double inverse_cell_width_ = 0.0;
  double inverse_cell_height_ = 0.0;
};

// mask |= the feature rectangle of every ball (projected several at a time).
void add_ball_rects(const BallProjection& projection, std::span<const Ball> balls_in_cell,
                    FeatureMask& mask);

}  // namespace safecell

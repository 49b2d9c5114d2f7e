#pragma once
// "Visible" of ../shared/VALIDATION.md, from the renderer's ground truth and never from the
// pipeline: a body (a human or an object of the scene) is visible in a camera when at least one
// feature cell has at least half of its pixels showing that body front-most in the camera's
// object-id image (camera_renderer.hpp). When it is not, why not: hidden by the robot, by a static
// obstacle or by another body, outside the camera's view, or too small to fill half a feature
// cell even unhidden.

#include <array>
#include <cstddef>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "safecell/camera/feature_grid.hpp"
#include "safecell/features/feature_mask.hpp"
#include "safecell/sim/body_id.hpp"

namespace safecell {

enum class UnseenReason : std::uint8_t {
  kHiddenByRobot,
  kHiddenByStaticObstacle,
  kHiddenByOtherBody,
  kOutsideViews,
  kTooSmall,
};
inline constexpr std::size_t kUnseenReasonCount = 5;

// "hidden_by_robot", "hidden_by_static_obstacle", "hidden_by_other_body", "outside_views",
// "too_small": the keys of the JSON report.
[[nodiscard]] const char* to_string(UnseenReason reason);

// The feature cells in which at least half of the pixels are `body` (object_ids: CV_16UC1 of
// body codes, the grid's image size; std::invalid_argument otherwise). Visible: any().
[[nodiscard]] FeatureMask front_most_cells(const cv::Mat& object_ids, BodyCode body,
                                           const FeatureGrid& grid);
// Per camera (object_ids: one image each), whether `body` is visible in it.
[[nodiscard]] std::vector<bool> visible_per_camera(const std::vector<cv::Mat>& object_ids,
                                                   BodyCode body, const FeatureGrid& grid);
// The body code of a scene's body b, counting its `humans` first, then its objects.
[[nodiscard]] BodyCode scene_body_code(std::size_t humans, std::size_t b);

// The feature cells at least half covered by the non-zero pixels of `coverage` (CV_8UC1).
[[nodiscard]] FeatureMask covered_cells(const cv::Mat& coverage, const FeatureGrid& grid);

// Why `body` is not visible in a camera. alone: the body's own pixels with nothing in front
// (SimulatedCell::coverage of its surfaces). No pixel: outside the view; no feature cell half
// covered even alone: too small; otherwise hidden by whatever shows front-most on most of its
// pixels.
[[nodiscard]] UnseenReason why_not_visible(const cv::Mat& object_ids, const cv::Mat& alone,
                                           BodyCode body, const FeatureGrid& grid);

// Counts per reason, in the order of UnseenReason.
using UnseenReasons = std::array<std::size_t, kUnseenReasonCount>;

}  // namespace safecell

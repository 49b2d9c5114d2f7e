#include "safecell/sim/camera_renderer.hpp"

#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <random>

namespace safecell {
namespace {

constexpr std::size_t kNoiseTableSize = 1u << 16;  // a power of two

bool has_distortion(const LensDistortion& lens) { return !(lens == LensDistortion{}); }

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

CameraRenderer::CameraRenderer(PinholeCamera camera, const std::vector<SurfaceMesh>& scenery,
                               const SensorSettings& sensor)
    : camera_(std::move(camera)),
      sensor_(sensor),
      rasteriser_(camera_.intrinsics(), camera_.cell_to_camera()) {
  for (const auto& surface : scenery) rasteriser_.draw(surface.mesh, surface.albedo, surface.body);
  scenery_gray_ = rasteriser_.gray().clone();
  scenery_depth_ = rasteriser_.depth().clone();
  scenery_ids_ = rasteriser_.ids().clone();

  const CameraIntrinsics& k = camera_.intrinsics();
  if (has_distortion(k.distortion)) {
    // For each pixel of the real (distorted) image, where it lies in the ideal rendering.
    lens_map_x_.create(k.height_px, k.width_px, CV_32FC1);
    lens_map_y_.create(k.height_px, k.width_px, CV_32FC1);
    const double max_radius_sq = monotonic_radius_sq(k.distortion);
    for (int v = 0; v < k.height_px; ++v) {
      for (int u = 0; u < k.width_px; ++u) {
        const Eigen::Vector2d distorted((u - k.cx_px) / k.fx_px, (v - k.cy_px) / k.fy_px);
        const auto ideal = undistort(k.distortion, distorted, max_radius_sq);
        lens_map_x_.at<float>(v, u) =
            ideal ? static_cast<float>(k.fx_px * ideal->x() + k.cx_px) : -1.0f;
        lens_map_y_.at<float>(v, u) =
            ideal ? static_cast<float>(k.fy_px * ideal->y() + k.cy_px) : -1.0f;
      }
    }
  }

  std::mt19937_64 rng(sensor_.seed);
  std::normal_distribution<double> gauss(0.0, sensor_.noise_sigma);
  noise_table_.resize(kNoiseTableSize);
  for (auto& sample : noise_table_) {
    sample = static_cast<std::int8_t>(std::clamp(std::lround(gauss(rng)), -127l, 127l));
  }
}

cv::Mat CameraRenderer::lens_view(const cv::Mat& ideal, int interpolation) const {
  if (lens_map_x_.empty()) return ideal;
  cv::Mat real;
  cv::remap(ideal, real, lens_map_x_, lens_map_y_, interpolation, cv::BORDER_CONSTANT, 0);
  return real;
}

void CameraRenderer::add_sensor_effects(cv::Mat& frame, std::uint64_t frame_index,
                                        double time_s) const {
  const double gain = 1.0 + sensor_.lighting_drift * std::sin(2.0 * std::numbers::pi * time_s /
                                                              sensor_.lighting_period_s);
  // Each row reads a contiguous run of the noise table from a random start: independent samples
  // along the row, a fresh start per row and frame.
  std::uint64_t state = sensor_.seed ^ (frame_index * 0xD1B54A32D192ED03ull);
  for (int y = 0; y < frame.rows; ++y) {
    auto* row = frame.ptr<std::uint8_t>(y);
    const std::size_t start = splitmix64(state);
    for (int x = 0; x < frame.cols; ++x) {
      const long value =
          std::lround(gain * row[x]) +
          noise_table_[(start + static_cast<std::size_t>(x)) & (kNoiseTableSize - 1)];
      row[x] = static_cast<std::uint8_t>(std::clamp(value, 0l, 255l));
    }
  }
}

cv::Mat CameraRenderer::render(const std::vector<SurfaceMesh>& moving, std::uint64_t frame_index,
                               double time_s, cv::Mat* object_ids) {
  scenery_gray_.copyTo(rasteriser_.gray());
  scenery_depth_.copyTo(rasteriser_.depth());
  scenery_ids_.copyTo(rasteriser_.ids());
  for (const auto& surface : moving) rasteriser_.draw(surface.mesh, surface.albedo, surface.body);
  if (object_ids != nullptr) *object_ids = lens_view(rasteriser_.ids(), cv::INTER_NEAREST).clone();
  cv::Mat frame = lens_view(rasteriser_.gray(), cv::INTER_LINEAR).clone();
  add_sensor_effects(frame, frame_index, time_s);
  return frame;
}

cv::Mat CameraRenderer::object_ids(const std::vector<SurfaceMesh>& moving) {
  scenery_depth_.copyTo(rasteriser_.depth());
  scenery_ids_.copyTo(rasteriser_.ids());
  for (const auto& surface : moving) rasteriser_.draw(surface.mesh, surface.albedo, surface.body);
  return lens_view(rasteriser_.ids(), cv::INTER_NEAREST).clone();
}

cv::Mat CameraRenderer::coverage(const std::vector<SurfaceMesh>& meshes) {
  rasteriser_.clear();
  for (const auto& surface : meshes) rasteriser_.draw(surface.mesh, 255);
  const cv::Mat covered =
      rasteriser_.depth() < static_cast<double>(std::numeric_limits<float>::infinity());
  return lens_view(covered, cv::INTER_NEAREST).clone();
}

}  // namespace safecell

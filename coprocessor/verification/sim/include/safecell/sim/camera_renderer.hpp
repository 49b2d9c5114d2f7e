#pragma once
// What one camera of the simulated cell sees: the still scenery (drawn once and kept), the
// moving robot and humans drawn over it with a z-buffer, the camera's lens distortion, a slow
// lighting drift and sensor noise. Deterministic: the same seed, frame index and scene give the
// same image. Not thread-safe: one renderer per camera and thread.

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "safecell/camera/pinhole_camera.hpp"
#include "safecell/sim/rasteriser.hpp"
#include "safecell/sim/surface_mesh.hpp"

namespace safecell {

struct SensorSettings {
  double noise_sigma = 2.0;     // gray levels, Gaussian, independent per pixel and frame
  double lighting_drift = 0.0;  // amplitude of the brightness gain's slow sine (0.05 = +-5 %)
  double lighting_period_s = 30.0;
  std::uint64_t seed = 1;
};

class CameraRenderer {
 public:
  CameraRenderer(PinholeCamera camera, const std::vector<SurfaceMesh>& scenery,
                 const SensorSettings& sensor);

  const PinholeCamera& camera() const { return camera_; }

  // The 8-bit frame (CV_8UC1) at `time_s`, frame number `frame_index` of the sequence. With
  // `object_ids`, also which body each pixel shows front-most (CV_16UC1 of body codes, through
  // the same lens; a pixel the lens maps from outside the rendering is background).
  cv::Mat render(const std::vector<SurfaceMesh>& moving, std::uint64_t frame_index, double time_s,
                 cv::Mat* object_ids = nullptr);

  // The object-id image alone (as render() gives it) of the scenery with `moving` in it: no
  // frame, no noise. For coverage maps, which need many.
  cv::Mat object_ids(const std::vector<SurfaceMesh>& moving);

  // The pixels (CV_8UC1, 255 = covered) the meshes cover, whatever stands in front of them.
  cv::Mat coverage(const std::vector<SurfaceMesh>& meshes);

 private:
  cv::Mat lens_view(const cv::Mat& ideal, int interpolation) const;
  void add_sensor_effects(cv::Mat& frame, std::uint64_t frame_index, double time_s) const;

  PinholeCamera camera_;
  SensorSettings sensor_;
  Rasteriser rasteriser_;
  cv::Mat scenery_gray_;
  cv::Mat scenery_depth_;
  cv::Mat scenery_ids_;
  cv::Mat lens_map_x_;  // empty for a lens without distortion
  cv::Mat lens_map_y_;
  std::vector<std::int8_t> noise_table_;
};

}  // namespace safecell

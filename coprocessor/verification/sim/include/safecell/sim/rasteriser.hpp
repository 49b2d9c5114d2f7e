#pragma once
// A z-buffered triangle rasteriser for an ideal pinhole camera: 8-bit gray with flat Lambert
// shading under a fixed light from above, a 32-bit depth buffer (camera z in metres) and a 16-bit
// object-id buffer (the body code of the front-most surface, body_id.hpp).
// Pixel centres sit at integer coordinates, as in OpenCV. Triangles are clipped at a near plane,
// so geometry around or behind the camera draws correctly. Single-threaded; one per camera.

#include <Eigen/Geometry>
#include <cstdint>
#include <opencv2/core.hpp>

#include "safecell/camera/camera_intrinsics.hpp"
#include "safecell/geometry/shape.hpp"
#include "safecell/sim/body_id.hpp"

namespace safecell {

class Rasteriser {
 public:
  // The lens distortion of `intrinsics` is ignored here (see CameraRenderer).
  Rasteriser(const CameraIntrinsics& intrinsics, const Eigen::Isometry3d& cell_to_camera);

  // Gray 0, depth +infinity and body 0 (background) everywhere.
  void clear();
  // Draws every triangle of a mesh given in the cell frame. albedo: the surface's brightness
  // when lit head-on; body: the code its front-most pixels get in the object-id buffer.
  void draw(const TriangleMesh& mesh, std::uint8_t albedo, BodyCode body = 0);

  cv::Mat& gray() { return gray_; }
  cv::Mat& depth() { return depth_; }
  const cv::Mat& gray() const { return gray_; }
  const cv::Mat& depth() const { return depth_; }
  cv::Mat& ids() { return ids_; }
  const cv::Mat& ids() const { return ids_; }

 private:
  void draw_camera_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c, std::uint8_t shade, BodyCode body);

  CameraIntrinsics intrinsics_;
  Eigen::Isometry3d cell_to_camera_;
  cv::Mat gray_;   // CV_8UC1
  cv::Mat depth_;  // CV_32FC1
  cv::Mat ids_;    // CV_16UC1
};

}  // namespace safecell

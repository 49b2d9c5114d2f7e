#pragma once
// The checks that make a camera out of numbers, shared by the PinholeCamera constructor and the
// calibration file reader so both refuse the same values, each naming the value its own way.

#include <Eigen/Core>
#include <string>

#include "safecell/camera/camera_intrinsics.hpp"

namespace safecell {

// What each value is called where it came from ("intrinsics.fx_px", "camera_matrix (fx)").
struct CameraFieldNames {
  std::string width;
  std::string height;
  std::string fx;
  std::string fy;
  std::string cx;
  std::string cy;
  std::string distortion;
  std::string rotation;
  std::string translation;
};

// max |R^T R - I|.
double orthonormality_error(const Eigen::Matrix3d& rotation);

// Throws CameraError "source: field: ..." for the first value that makes no camera.
void check_camera_values(const std::string& source, const CameraFieldNames& names,
                         const CameraIntrinsics& intrinsics, const Eigen::Matrix3d& rotation,
                         const Eigen::Vector3d& translation_m);

}  // namespace safecell

#pragma once
// Camera calibration files in OpenCV's YAML format (as cv::FileStorage writes it), one camera
// per file:
//
//   %YAML:1.0
//   ---
//   image_width: 704
//   image_height: 576
//   camera_matrix: !!opencv-matrix            # 3x3 [fx 0 cx; 0 fy cy; 0 0 1], pixels
//     rows: 3
//     cols: 3
//     dt: d
//     data: [ 458.7, 0., 351.5, 0., 458.7, 287.5, 0., 0., 1. ]
//   distortion_coefficients: !!opencv-matrix  # 5x1 or 1x5 (k1 k2 p1 p2 k3); 4 entries: k3 = 0
//   cell_to_camera_rotation: !!opencv-matrix  # 3x3; or cell_to_camera_rvec, 3x1 Rodrigues
//   cell_to_camera_translation_m: !!opencv-matrix  # 3x1, metres
//
// x_camera = R x_cell + t (see pinhole_camera.hpp for the frames). As OpenCV requires, the file
// begins with "%YAML:1.0"; matrices are opencv-matrix nodes; other keys (an OpenCV calibration
// tool's extras) are ignored.

#include <filesystem>
#include <string>

#include "safecell/camera/pinhole_camera.hpp"

namespace safecell {

// Throws CameraError, whose message names the file, the key, the value and what was expected,
// for a file that cannot be read, is not YAML, lacks a key, has a matrix of the wrong shape or a
// value that is not finite, a rotation that is not one, or values that make no camera.
[[nodiscard]] PinholeCamera read_camera_calibration(const std::filesystem::path& path,
                                                    std::string name);

// Writes atomically: a temporary file in the same directory, flushed to disk, then renamed over
// `path`, so a reader sees the old file or the new one, never a part. Numbers are written with
// 17 significant digits, so reading gives back the same camera. Throws CameraError on failure.
void write_camera_calibration(const std::filesystem::path& path, const PinholeCamera& camera);

}  // namespace safecell

#include <opencv2/core.hpp>
#include <string>

#include "error_text.hpp"
#include "safecell/camera/calibration_file.hpp"
#include "safecell/camera/camera_error.hpp"
#include "safecell/files/atomic_write.hpp"

namespace safecell {
namespace {

cv::Mat to_mat(const Eigen::MatrixXd& matrix) {
  cv::Mat mat(static_cast<int>(matrix.rows()), static_cast<int>(matrix.cols()), CV_64F);
  for (int r = 0; r < mat.rows; ++r) {
    for (int c = 0; c < mat.cols; ++c) mat.at<double>(r, c) = matrix(r, c);
  }
  return mat;
}

std::string calibration_yaml(const PinholeCamera& camera) {
  const CameraIntrinsics& in = camera.intrinsics();
  const LensDistortion& d = in.distortion;
  Eigen::Matrix3d camera_matrix;
  camera_matrix << in.fx_px, 0.0, in.cx_px, 0.0, in.fy_px, in.cy_px, 0.0, 0.0, 1.0;
  cv::FileStorage storage(
      ".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  storage.writeComment(
      "safecell camera calibration: pixels (OpenCV convention), cell frame z up, metres; "
      "x_camera = cell_to_camera_rotation * x_cell + cell_to_camera_translation_m");
  storage << "image_width" << in.width_px;
  storage << "image_height" << in.height_px;
  storage << "camera_matrix" << to_mat(camera_matrix);
  storage << "distortion_coefficients"
          << to_mat(Eigen::Matrix<double, 5, 1>(d.k1, d.k2, d.p1, d.p2, d.k3));
  storage << "cell_to_camera_rotation" << to_mat(camera.cell_to_camera().linear());
  storage << "cell_to_camera_translation_m" << to_mat(camera.cell_to_camera().translation());
  return storage.releaseAndGetString();
}

}  // namespace

void write_camera_calibration(const std::filesystem::path& path, const PinholeCamera& camera) {
  std::string yaml;
  try {
    yaml = calibration_yaml(camera);
  } catch (const cv::Exception& error) {
    throw_camera_error(path.string(), "(file)",
                       "OpenCV cannot format the calibration (" + one_line(error.what()) + ")");
  }
  try {
    write_file_atomically(path, yaml);
  } catch (const FileError& error) {
    throw_camera_error(path.string(), "(file)", error.problem());
  }
}

}  // namespace safecell

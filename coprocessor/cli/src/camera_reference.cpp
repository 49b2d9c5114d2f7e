#include "camera_reference.hpp"

#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>

#include "png_output.hpp"
#include "progress_bar.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/files/atomic_write.hpp"
#include "safecell/reference/median_image.hpp"

namespace safecell {
namespace {

std::filesystem::path reference_file(const std::filesystem::path& folder,
                                     const CameraConfig& camera) {
  return folder / (camera.name + ".png");
}

cv::Size image_size(const CellModel& cell, std::size_t camera) {
  const CameraIntrinsics& k = cell.cameras.at(camera).intrinsics();
  return {k.width_px, k.height_px};
}

}  // namespace

std::vector<cv::Mat> read_reference_images(const std::filesystem::path& folder,
                                           const CellModel& cell) {
  std::vector<cv::Mat> images;
  for (std::size_t c = 0; c < cell.config.cameras.size(); ++c) {
    const std::filesystem::path file = reference_file(folder, cell.config.cameras[c]);
    if (!std::filesystem::is_regular_file(file)) {
      throw FileError(file, "no such file (the reference image of camera '" +
                                cell.config.cameras[c].name + "')");
    }
    cv::Mat image;
    try {
      image = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
    } catch (const cv::Exception& error) {
      throw FileError(file, std::string("cannot decode: ") + error.what());
    }
    if (image.empty()) throw FileError(file, "cannot decode as an image");
    const cv::Size expected = image_size(cell, c);
    if (image.type() != CV_8UC1 || image.size() != expected) {
      throw FileError(
          file, "is " + std::to_string(image.cols) + " x " + std::to_string(image.rows) + " with " +
                    std::to_string(image.channels()) + " channel(s) of " +
                    std::to_string(image.elemSize1() * 8) + " bits; expected 8-bit gray " +
                    std::to_string(expected.width) + " x " + std::to_string(expected.height) +
                    " (the camera's calibration)");
    }
    images.push_back(image);
  }
  return images;
}

std::vector<cv::Mat> record_reference_images(FrameSetAcquirer& acquirer, std::size_t sets,
                                             std::ostream& log) {
  if (sets == 0) throw std::invalid_argument("reference: at least one frame set is needed");
  log << "reference images: the median of " << sets
      << " frame sets; the cell must be empty of people now\n";
  std::vector<std::vector<cv::Mat>> frames(acquirer.camera_count());
  ProgressBar progress(log, &log == &std::cerr && ProgressBar::stderr_is_terminal());
  for (std::size_t s = 0; s < sets; ++s) {
    const FrameSet set = acquirer.acquire();
    for (std::size_t c = 0; c < set.frames.size(); ++c) {
      const CameraFrame& frame = set.frames[c];
      if (!frame.known()) {
        throw InputError("reference: frame set " + std::to_string(s + 1) + " of " +
                         std::to_string(sets) + ": " + frame.view.detail);
      }
      frames[c].push_back(frame.image);
    }
    progress.update("reference", static_cast<double>(s + 1) / static_cast<double>(sets));
  }
  progress.finish();
  std::vector<cv::Mat> medians;
  medians.reserve(frames.size());
  for (const auto& camera_frames : frames) medians.push_back(median_image(camera_frames));
  return medians;
}

void write_reference_images(const std::filesystem::path& folder, const CellModel& cell,
                            const std::vector<cv::Mat>& images) {
  std::filesystem::create_directories(folder);
  for (std::size_t c = 0; c < images.size(); ++c) {
    write_png(reference_file(folder, cell.config.cameras.at(c)), images[c]);
  }
}

}  // namespace safecell

#pragma once
// The reference images of the service on real cameras (the empty cell each camera's frames are
// compared with): read from a folder, one `<camera>.png` per camera, or recorded from the
// cameras as the per-pixel median of the first frame sets. While the reference is recorded the
// cell must be empty of people; the robot may move, since the median shows the background
// wherever the robot covers a pixel in fewer than half of the sets. Private to the CLI.

#include <filesystem>
#include <opencv2/core.hpp>
#include <ostream>
#include <vector>

#include "safecell/acquisition/frame_set_acquirer.hpp"
#include "safecell/cell/cell_model.hpp"

namespace safecell {

// `<folder>/<camera>.png` for each camera of the cell, as 8-bit gray of the camera's size.
// Throws FileError naming the file: missing, not an image, or of another size or depth.
std::vector<cv::Mat> read_reference_images(const std::filesystem::path& folder,
                                           const CellModel& cell);

// The median of the next `sets` frame sets. Throws std::invalid_argument naming the camera and
// its cause when a camera delivers no usable frame while the reference is recorded.
std::vector<cv::Mat> record_reference_images(FrameSetAcquirer& acquirer, std::size_t sets,
                                             std::ostream& log);

// Each image as `<folder>/<camera>.png`, written atomically (read_reference_images reads them).
void write_reference_images(const std::filesystem::path& folder, const CellModel& cell,
                            const std::vector<cv::Mat>& images);

}  // namespace safecell

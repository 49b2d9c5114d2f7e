#include "safecell/acquisition/cell_camera_sources.hpp"

#include "safecell/acquisition/image_folder_source.hpp"
#include "safecell/acquisition/video_capture_source.hpp"
#include "safecell/cell/cell_error.hpp"

namespace safecell {

std::vector<std::unique_ptr<CameraSource>> cell_camera_sources(const CellModel& cell) {
  std::vector<std::unique_ptr<CameraSource>> sources;
  for (std::size_t c = 0; c < cell.config.cameras.size(); ++c) {
    const CameraConfig& camera = cell.config.cameras[c];
    if (!camera.source) {
      throw_cell_error(camera.at, "cameras[" + std::to_string(c) + "].source",
                       "missing; on real cameras each camera needs one (device, video, folder, "
                       "gstreamer or url)");
    }
    const CameraIntrinsics& k = cell.cameras.at(c).intrinsics();
    const cv::Size size(k.width_px, k.height_px);
    if (camera.source->kind == CameraSourceConfig::Kind::kImageFolder) {
      sources.push_back(
          std::make_unique<ImageFolderSource>(camera.name, size, camera.source->spec));
    } else {
      // VideoCaptureSource tells the kinds apart by the spec itself; the cell file has checked
      // that each kind's spec reads as that kind.
      sources.push_back(
          std::make_unique<VideoCaptureSource>(camera.name, size, camera.source->spec));
    }
  }
  return sources;
}

}  // namespace safecell

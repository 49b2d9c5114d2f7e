#include "safecell/acquisition/cell_camera_sources.hpp"

#include "safecell/acquisition/image_folder_source.hpp"
#include "safecell/acquisition/live_replay_source.hpp"
#include "safecell/acquisition/video_capture_source.hpp"
#include "safecell/cell/cell_error.hpp"

namespace safecell {

std::vector<std::unique_ptr<CameraSource>> cell_camera_sources(const CellModel& cell,
                                                               Recordings recordings) {
  std::vector<std::unique_ptr<CameraSource>> sources;
  const auto replay_clock = std::make_shared<ReplayClock>();  // one for the whole recording
  for (std::size_t c = 0; c < cell.config.cameras.size(); ++c) {
    const CameraConfig& camera = cell.config.cameras[c];
    if (!camera.source) {
      throw_cell_error(camera.at, "cameras[" + std::to_string(c) + "].source",
                       "missing; on real cameras each camera needs one (device, video, folder, "
                       "gstreamer or url)");
    }
    const CameraIntrinsics& k = cell.cameras.at(c).intrinsics();
    const cv::Size size(k.width_px, k.height_px);
    using Kind = CameraSourceConfig::Kind;
    using Video = VideoCaptureSource::Kind;
    const std::string& spec = camera.source->spec;
    switch (camera.source->kind) {
      case Kind::kImageFolder:
        sources.push_back(std::make_unique<ImageFolderSource>(camera.name, size, spec));
        break;
      // The kind the cell file names, not what the text looks like: a video file called "0" is
      // still a file.
      case Kind::kDevice:
        sources.push_back(
            std::make_unique<VideoCaptureSource>(camera.name, size, Video::kDevice, spec));
        break;
      case Kind::kVideoFile:
        sources.push_back(
            std::make_unique<VideoCaptureSource>(camera.name, size, Video::kFile, spec));
        break;
      case Kind::kGstreamer:
        sources.push_back(
            std::make_unique<VideoCaptureSource>(camera.name, size, Video::kPipeline, spec));
        break;
      case Kind::kStream:
        sources.push_back(
            std::make_unique<VideoCaptureSource>(camera.name, size, Video::kStream, spec));
        break;
    }
    const bool recorded =
        camera.source->kind == Kind::kImageFolder || camera.source->kind == Kind::kVideoFile;
    if (recorded && recordings == Recordings::kLive) {
      sources.back() = std::make_unique<LiveReplaySource>(std::move(sources.back()), replay_clock);
    }
  }
  return sources;
}

}  // namespace safecell

#include "safecell/campaign/camera_fault_injector.hpp"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace safecell {
namespace {

constexpr double kKnockPixels = 12.0;  // far more than a reference's alignment tolerance

}  // namespace

void CameraFaultInjector::begin(FaultClass fault, std::vector<std::size_t> cameras) {
  if (site_of(fault) != FaultSite::kCameras) {
    throw std::logic_error(std::string("CameraFaultInjector: ") + to_string(fault) +
                           " is not a camera fault");
  }
  fault_ = fault;
  cameras_ = std::move(cameras);
  frozen_.assign(cameras_.size(), cv::Mat());
}

FrameSet CameraFaultInjector::acquire() {
  FrameSet set = source_.acquire();
  if (!fault_) return set;
  for (std::size_t i = 0; i < cameras_.size(); ++i) {
    if (cameras_[i] >= set.frames.size()) continue;
    CameraFrame& frame = set.frames[cameras_[i]];
    if (frame.image.empty()) continue;
    ++injected_;
    switch (*fault_) {
      case FaultClass::kCameraFrozen:
        if (frozen_[i].empty()) frozen_[i] = frame.image.clone();
        frame.image = frozen_[i].clone();
        break;
      case FaultClass::kCameraBlinded:
        frame.image.setTo(255);
        break;
      case FaultClass::kCameraMoved: {
        const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, kKnockPixels, 0, 1, kKnockPixels);
        cv::Mat moved;
        cv::warpAffine(frame.image, moved, shift, frame.image.size(), cv::INTER_NEAREST,
                       cv::BORDER_REPLICATE);
        frame.image = moved;
        break;
      }
      case FaultClass::kCameraUnplugged:
        frame.image = cv::Mat();
        frame.view = camera_fault_report(frame.camera, CameraFault::kStopped,
                                         "no frame (unplugged by the fault campaign)");
        break;
      default:
        break;
    }
  }
  return set;
}

}  // namespace safecell

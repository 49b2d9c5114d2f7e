#include "safecell/acquisition/camera_views.hpp"

#include <stdexcept>

namespace safecell {

CameraViews::CameraViews(std::vector<CameraHealthMonitor> monitors, Log log)
    : monitors_(std::move(monitors)),
      log_(std::move(log)),
      last_faults_(monitors_.size(), CameraFault::kNone) {
  if (monitors_.empty()) throw std::invalid_argument("camera views: no health monitor");
  if (!log_) throw std::invalid_argument("camera views: no log");
}

void CameraViews::check(FrameSet& set) {
  if (set.frames.size() != monitors_.size()) {
    throw std::invalid_argument("camera views: frame set " + std::to_string(set.index) + " has " +
                                std::to_string(set.frames.size()) + " cameras, the monitors " +
                                std::to_string(monitors_.size()));
  }
  for (std::size_t i = 0; i < monitors_.size(); ++i) {
    CameraFrame& frame = set.frames[i];
    if (frame.camera != monitors_[i].camera_name()) {
      throw std::invalid_argument("camera views: frame set " + std::to_string(set.index) +
                                  " has camera '" + frame.camera + "' where the monitor is for '" +
                                  monitors_[i].camera_name() + "'");
    }
    if (frame.known()) frame.view = monitors_[i].check(frame.image);
    log_change(frame, i);
  }
}

void CameraViews::log_change(const CameraFrame& frame, std::size_t index) {
  CameraFault& last = last_faults_[index];
  if (frame.view.fault == last) return;
  if (frame.known()) {
    log_("view known again: camera '" + frame.camera + "' (was: " + to_string(last) + ")");
  } else {
    log_("view unknown: " + frame.view.detail);
  }
  last = frame.view.fault;
}

CameraViews camera_views_for(const CellModel& cell, const std::vector<cv::Mat>& references,
                             CameraViews::Log log, const HealthSettings& settings) {
  if (references.size() != cell.cameras.size()) {
    throw std::invalid_argument("camera views: " + std::to_string(cell.cameras.size()) +
                                " cameras but " + std::to_string(references.size()) +
                                " reference images");
  }
  std::vector<CameraHealthMonitor> monitors;
  for (std::size_t c = 0; c < references.size(); ++c) {
    monitors.emplace_back(cell.cameras[c].name(), references[c], settings);
  }
  return CameraViews(std::move(monitors), std::move(log));
}

}  // namespace safecell

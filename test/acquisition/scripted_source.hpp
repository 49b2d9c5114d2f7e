#pragma once
// A camera source for tests: it delivers the frames a script draws, fails where the script says,
// and writes every grab() and retrieve() into a shared call log.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "safecell/acquisition/camera_source.hpp"

namespace safecell::test {

class ScriptedSource final : public CameraSource {
 public:
  // frame_at(n): the image of the n-th grab (from 0, failed grabs counted); grab_fault_at(n): a
  // fault for that grab.
  using FrameAt = std::function<cv::Mat(int grab_index)>;
  using FaultAt = std::function<CameraFault(int grab_index)>;

  ScriptedSource(
      std::string name, cv::Size size, FrameAt frame_at, std::vector<std::string>* calls = nullptr,
      FaultAt grab_fault_at = [](int) { return CameraFault::kNone; })
      : name_(std::move(name)),
        size_(size),
        frame_at_(std::move(frame_at)),
        grab_fault_at_(std::move(grab_fault_at)),
        calls_(calls) {}

  [[nodiscard]] const std::string& name() const override { return name_; }
  [[nodiscard]] cv::Size frame_size() const override { return size_; }

  HealthReport grab() override {
    record("grab");
    const int attempt = grabs_++;
    const CameraFault fault = grab_fault_at_(attempt);
    if (fault != CameraFault::kNone) return camera_fault_report(name_, fault, "scripted");
    latched_ = attempt;
    return {};
  }
  HealthReport retrieve(SourceFrame& frame) override {
    record("retrieve");
    frame = SourceFrame{frame_at_(latched_), exposure_s_, "script"};
    return {};
  }

  void set_exposure_s(std::optional<double> exposure_s) { exposure_s_ = exposure_s; }

 private:
  void record(const std::string& call) {
    if (calls_ != nullptr) calls_->push_back(call + " " + name_);
  }

  std::string name_;
  cv::Size size_;
  FrameAt frame_at_;
  FaultAt grab_fault_at_;
  std::vector<std::string>* calls_;
  std::optional<double> exposure_s_;
  int grabs_ = 0;
  int latched_ = -1;
};

}  // namespace safecell::test

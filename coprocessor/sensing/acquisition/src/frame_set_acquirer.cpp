#include "safecell/acquisition/frame_set_acquirer.hpp"

#include <algorithm>
#include <chrono>
#include <opencv2/imgproc.hpp>
#include <set>
#include <sstream>
#include <stdexcept>

namespace safecell {
namespace {

double steady_now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// "704 x 576 8-bit gray", "640 x 480 16-bit 3-channel".
std::string describe(const cv::Mat& image) {
  std::ostringstream text;
  text << image.cols << " x " << image.rows << ' ';
  if (image.depth() == CV_8U && image.channels() == 1) {
    text << "8-bit gray";
  } else {
    text << (image.elemSize1() * 8) << "-bit " << image.channels() << "-channel";
  }
  return text.str();
}

// The frame as 8-bit gray, converting 8-bit colour; empty for any other format.
cv::Mat as_gray(const cv::Mat& image) {
  if (image.depth() != CV_8U) return {};
  switch (image.channels()) {
    case 1:
      return image;
    case 3: {
      cv::Mat gray;
      cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
      return gray;
    }
    case 4: {
      cv::Mat gray;
      cv::cvtColor(image, gray, cv::COLOR_BGRA2GRAY);
      return gray;
    }
    default:
      return {};
  }
}

}  // namespace

FrameSetAcquirer::FrameSetAcquirer(std::vector<std::unique_ptr<CameraSource>> sources)
    : sources_(std::move(sources)), counters_(sources_.size(), 0) {
  if (sources_.empty()) throw std::invalid_argument("frame set acquirer: no camera source");
  std::set<std::string> names;
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    if (!sources_[i]) {
      throw std::invalid_argument("frame set acquirer: camera source " + std::to_string(i) +
                                  " is null");
    }
    if (!names.insert(sources_[i]->name()).second) {
      throw std::invalid_argument("frame set acquirer: two camera sources are named '" +
                                  sources_[i]->name() + "'");
    }
  }
}

FrameSet FrameSetAcquirer::acquire() {
  // Grab everything first: the grabs are what must happen close together in time.
  std::vector<HealthReport> grabbed(sources_.size());
  std::vector<double> grab_times_s(sources_.size());
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    grab_times_s[i] = steady_now_s();
    grabbed[i] = sources_[i]->grab();
  }
  FrameSet set;
  set.index = ++sets_;
  set.frames.reserve(sources_.size());
  std::uint64_t passed_over = 0;
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    set.frames.push_back(retrieve_one(i, grabbed[i], grab_times_s[i]));
    passed_over = std::max(passed_over, set.frames.back().passed_over);
  }
  sets_passed_over_ += passed_over;
  return set;
}

CameraFrame FrameSetAcquirer::retrieve_one(std::size_t index, const HealthReport& grabbed,
                                           double grab_time_s) {
  CameraSource& source = *sources_[index];
  CameraFrame frame;
  frame.camera = source.name();
  frame.counter = counters_[index];
  frame.exposure_s = grab_time_s;
  if (!grabbed.healthy()) {
    frame.view = grabbed;
    return frame;
  }
  SourceFrame delivered;
  frame.view = source.retrieve(delivered);
  if (!frame.known()) return frame;

  frame.counter = ++counters_[index];
  frame.passed_over = delivered.passed_over;
  if (delivered.exposure_s) {
    frame.exposure_s = *delivered.exposure_s;
    frame.stamp_source = StampSource::kBackend;
  }
  cv::Mat gray = as_gray(delivered.image);
  const cv::Size expected = source.frame_size();
  if (gray.empty() || gray.size() != expected) {
    std::ostringstream detail;
    detail << "got " << describe(delivered.image) << ", expected 8-bit gray " << expected.width
           << " x " << expected.height;
    if (!delivered.origin.empty()) detail << ", from '" << delivered.origin << "'";
    frame.view = camera_fault_report(source.name(), CameraFault::kWrongFormat, detail.str());
    return frame;
  }
  frame.image = std::move(gray);
  return frame;
}

}  // namespace safecell

#include "safecell/acquisition/image_folder_source.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <sstream>

#include "frame_times_csv.hpp"
#include "safecell/acquisition/acquisition_error.hpp"

namespace safecell {
namespace {

bool is_image_file(const std::filesystem::directory_entry& entry) {
  std::string extension = entry.path().extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return entry.is_regular_file() && (extension == ".png" || extension == ".pgm");
}

double unix_time_s(std::filesystem::file_time_type time) {
  const auto system_time = std::chrono::file_clock::to_sys(time);
  return std::chrono::duration<double>(system_time.time_since_epoch()).count();
}

}  // namespace

ImageFolderSource::ImageFolderSource(std::string camera_name, cv::Size frame_size,
                                     std::filesystem::path folder)
    : name_(std::move(camera_name)), frame_size_(frame_size), folder_(std::move(folder)) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder_, error)) {
    open_problem_ = "cannot open image folder '" + folder_.string() + "': not a directory";
    return;
  }
  for (std::filesystem::directory_iterator entry(folder_, error), end; !error && entry != end;
       entry.increment(error)) {
    if (is_image_file(*entry)) files_.push_back(entry->path());
  }
  if (error) {
    open_problem_ = "cannot list image folder '" + folder_.string() + "': " + error.message();
    return;
  }
  std::sort(files_.begin(), files_.end(),
            [](const auto& a, const auto& b) { return a.filename() < b.filename(); });
  const std::filesystem::path csv = folder_ / kFrameTimesFile;
  if (std::filesystem::exists(csv)) {
    read_times_from_csv(csv);
  } else {
    read_times_from_files();
  }
}

void ImageFolderSource::read_times_from_csv(const std::filesystem::path& csv) {
  const std::map<std::string, FrameTime> rows = read_frame_times_csv(csv);
  std::set<std::string> images;
  const FrameTime* previous = nullptr;
  for (const auto& file : files_) {
    const std::string file_name = file.filename().string();
    const auto row = rows.find(file_name);
    if (row == rows.end()) {
      throw_acquisition_error(csv, 0, "file", "no row for image '" + file_name + "'");
    }
    if (previous != nullptr && !(row->second.time_s > previous->time_s)) {
      std::ostringstream problem;
      problem << row->second.time_s << " of '" << file_name << "' is not after " << previous->time_s
              << " of line " << previous->line;
      throw_acquisition_error(csv, row->second.line, "time_s", problem.str());
    }
    times_s_.push_back(row->second.time_s);
    images.insert(file_name);
    previous = &row->second;
  }
  for (const auto& [file_name, row] : rows) {
    if (images.count(file_name) == 0) {
      throw_acquisition_error(
          csv, row.line, "file",
          "'" + file_name + "' is not a PNG or PGM file in '" + folder_.string() + "'");
    }
  }
}

void ImageFolderSource::read_times_from_files() {
  for (const auto& file : files_) times_s_.push_back(unix_time_s(last_write_time(file)));
}

HealthReport ImageFolderSource::grab() {
  if (!opened()) return camera_fault_report(name_, CameraFault::kUnavailable, open_problem_);
  if (next_ >= files_.size()) {
    return camera_fault_report(name_, CameraFault::kStopped,
                               "image folder '" + folder_.string() + "' exhausted after " +
                                   std::to_string(files_.size()) + " frames");
  }
  ++next_;
  return {};
}

HealthReport ImageFolderSource::retrieve(SourceFrame& frame) {
  if (next_ == 0) {
    return camera_fault_report(name_, CameraFault::kStopped, "retrieve() before any grab()");
  }
  const std::size_t index = next_ - 1;
  const std::string path = files_[index].string();
  frame = SourceFrame{};
  frame.origin = path;
  frame.exposure_s = times_s_[index];
  try {
    frame.image = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& error) {
    return camera_fault_report(name_, CameraFault::kCorruptFrame,
                               "cannot decode image file '" + path + "': " + error.what());
  }
  if (frame.image.empty()) {
    return camera_fault_report(
        name_, CameraFault::kCorruptFrame,
        "cannot decode image file '" + path + "' (truncated, corrupt or not an image)");
  }
  return {};
}

}  // namespace safecell

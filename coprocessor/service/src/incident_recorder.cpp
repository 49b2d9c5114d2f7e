#include "safecell/service/incident_recorder.hpp"

#include <chrono>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <stdexcept>

#include "safecell/files/atomic_write.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

// "20261202-171503": the wall-clock time the incident was written, for people to sort by.
std::string utc_stamp() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::ostringstream text;
  text << std::put_time(&utc, "%Y%m%d-%H%M%S");
  return text.str();
}

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw FileError(file, "cannot be written");
}

void write_bits(const fs::path& file, const CellSet& map) {
  std::string bytes;
  bytes.reserve(map.words().size() * 8);
  for (const std::uint64_t word : map.words()) {
    for (int b = 0; b < 8; ++b) bytes.push_back(static_cast<char>((word >> (8 * b)) & 0xFFU));
  }
  write_text(file, bytes);
}

}  // namespace

IncidentRecorder::IncidentRecorder(IncidentSettings settings) : settings_(std::move(settings)) {
  if (settings_.folder.empty()) {
    throw std::invalid_argument("incident recorder: no folder for the incidents");
  }
  if (!(settings_.keep_s >= 0.1 && settings_.keep_s <= 60.0) ||
      !(settings_.after_s >= 0.0 && settings_.after_s <= 60.0)) {
    throw std::invalid_argument("incident recorder: keep " + std::to_string(settings_.keep_s) +
                                " s and after " + std::to_string(settings_.after_s) +
                                " s, expected 0.1..60 s and 0..60 s");
  }
}

void IncidentRecorder::add_cycle(double exposure_s, const FrameSet& frames,
                                 const ServiceCycle& cycle, const CellSet& map) {
  Cycle kept;
  kept.exposure_s = exposure_s;
  kept.index = cycle.index;
  for (const CameraFrame& frame : frames.frames) {
    kept.cameras.push_back(frame.camera);
    kept.images.push_back(frame.known() ? frame.image.clone() : cv::Mat());
  }
  kept.pose_known = cycle.pose_known;
  kept.q = cycle.q;
  kept.known_views = cycle.known_views;
  kept.forbidden_cells = cycle.forbidden_cells;
  kept.all_forbidden = cycle.all_forbidden;
  kept.map = map;
  cycles_.push_back(std::move(kept));
  forget_cycles_before(exposure_s - settings_.keep_s);
}

void IncidentRecorder::add_joint_state(RecordedJointState state) {
  const double time_s = state.time_s;
  joints_.push_back(std::move(state));
  forget_joints_before(time_s - settings_.keep_s);
}

void IncidentRecorder::forget_cycles_before(double time_s) {
  // While an incident is being recorded, everything from keep_s before its trigger stays.
  const double keep_from = trigger_s_ ? std::min(time_s, *trigger_s_ - settings_.keep_s) : time_s;
  while (!cycles_.empty() && cycles_.front().exposure_s < keep_from) cycles_.pop_front();
}

void IncidentRecorder::forget_joints_before(double time_s) {
  const double keep_from = trigger_s_ ? std::min(time_s, *trigger_s_ - settings_.keep_s) : time_s;
  while (!joints_.empty() && joints_.front().time_s < keep_from) joints_.pop_front();
}

void IncidentRecorder::trigger(double time_s, const std::string& cause) {
  if (written_ >= settings_.max_incidents) return;
  if (!trigger_s_) trigger_s_ = time_s;
  if (causes_.size() < 32) causes_.push_back(cause);
}

std::optional<fs::path> IncidentRecorder::poll(double now_s) {
  if (!trigger_s_ || now_s < *trigger_s_ + settings_.after_s) return std::nullopt;
  return write();
}

std::optional<fs::path> IncidentRecorder::flush() {
  if (!trigger_s_) return std::nullopt;
  return write();
}

fs::path IncidentRecorder::write() {
  const double trigger_s = *trigger_s_;
  const std::string name = "incident-" + utc_stamp() + "-" + std::to_string(written_ + 1);
  const fs::path partial = settings_.folder / ("." + name + ".partial");
  fs::path final_folder = settings_.folder / name;
  fs::remove_all(partial);
  fs::create_directories(partial / "maps");

  nlohmann::ordered_json incident;
  incident["format"] = "safecell incident 1";
  incident["causes"] = causes_;
  incident["trigger_s"] = trigger_s;
  incident["cycles"] = nlohmann::ordered_json::array();
  std::vector<std::ofstream> frame_times;
  std::vector<std::string> cameras;
  for (const Cycle& cycle : cycles_) {
    if (cameras.empty()) {
      cameras = cycle.cameras;
      for (const std::string& camera : cameras) {
        fs::create_directories(partial / "frames" / camera);
        frame_times.emplace_back(partial / "frames" / camera / "frame_times.csv");
        frame_times.back() << "file,time_s\n" << std::setprecision(17);
      }
    }
    nlohmann::ordered_json entry;
    entry["cycle"] = cycle.index;
    entry["exposure_s"] = cycle.exposure_s;
    entry["pose_known"] = cycle.pose_known;
    entry["q_rad"] = cycle.q;
    entry["known_views"] = cycle.known_views;
    entry["forbidden_cells"] = cycle.forbidden_cells;
    entry["all_forbidden"] = cycle.all_forbidden;
    const std::string stem = std::to_string(cycle.index);
    for (std::size_t c = 0; c < cycle.images.size() && c < cameras.size(); ++c) {
      if (cycle.images[c].empty()) continue;  // the view was unknown: no frame
      const std::string file = stem + ".png";
      if (!cv::imwrite((partial / "frames" / cameras[c] / file).string(), cycle.images[c])) {
        throw FileError(partial / "frames" / cameras[c] / file, "cannot be written");
      }
      frame_times[c] << file << ',' << cycle.exposure_s << '\n';
    }
    write_bits(partial / "maps" / (stem + ".bits"), cycle.map);
    incident["cycles"].push_back(entry);
  }
  incident["cameras"] = cameras;
  for (std::size_t c = 0; c < frame_times.size(); ++c) {
    frame_times[c].close();
    if (!frame_times[c]) throw FileError(partial / "frames" / cameras[c], "frame_times.csv");
  }
  std::ostringstream joints;
  joints << std::setprecision(17) << "time_s,state,speed_scale,q_rad\n";
  for (const RecordedJointState& joint : joints_) {
    joints << joint.time_s << ',' << joint.state << ',' << joint.speed_scale << ',';
    for (std::size_t j = 0; j < joint.q.size(); ++j) joints << (j ? " " : "") << joint.q[j];
    joints << '\n';
  }
  write_text(partial / "joints.csv", joints.str());
  write_text(partial / "incident.json", incident.dump(2) + "\n");
  fs::rename(partial, final_folder);  // the folder appears whole or not at all

  ++written_;
  trigger_s_.reset();
  causes_.clear();
  if (!cycles_.empty()) forget_cycles_before(cycles_.back().exposure_s - settings_.keep_s);
  if (!joints_.empty()) forget_joints_before(joints_.back().time_s - settings_.keep_s);
  return final_folder;
}

}  // namespace safecell

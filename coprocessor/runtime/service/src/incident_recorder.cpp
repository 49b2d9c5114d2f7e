#include "safecell/service/incident_recorder.hpp"

#include <chrono>
#include <ctime>
#include <future>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <stdexcept>

#include "safecell/acquisition/exposure_sync.hpp"
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

// Every file of an incident is written durably (flushed to disk, renamed into place): a folder
// that has been renamed to its final name is whole after a power cut too.
void write_text(const fs::path& file, const std::string& text) {
  write_file_atomically(file, text);
}

void write_image(const fs::path& file, const cv::Mat& image) {
  std::vector<std::uint8_t> png;
  if (!cv::imencode(".png", image, png)) throw FileError(file, "cannot be encoded as PNG");
  write_file_atomically(file, {reinterpret_cast<const char*>(png.data()), png.size()});
}

void write_bits(const fs::path& file, const CellSet& map) {
  std::string bytes;
  bytes.reserve(map.words().size() * 8);
  for (const std::uint64_t word : map.words()) {
    for (int b = 0; b < 8; ++b) bytes.push_back(static_cast<char>((word >> (8 * b)) & 0xFFU));
  }
  write_text(file, bytes);
}

nlohmann::ordered_json cycle_json(const IncidentCycle& cycle) {
  nlohmann::ordered_json entry;
  entry["cycle"] = cycle.index;
  entry["exposure_s"] = cycle.exposure_s;
  entry["pose_known"] = cycle.pose_known;
  entry["q_rad"] = cycle.q;
  entry["known_views"] = cycle.known_views;
  entry["forbidden_cells"] = cycle.forbidden_cells;
  entry["all_forbidden"] = cycle.all_forbidden;
  entry["views"] = nlohmann::ordered_json::array();
  for (const IncidentView& view : cycle.views) {
    entry["views"].push_back(
        {{"exposure_s", view.exposure_s ? nlohmann::ordered_json(*view.exposure_s)
                                        : nlohmann::ordered_json(nullptr)},
         {"fault", to_string(view.fault)},
         {"detail", view.detail}});
  }
  return entry;
}

// What one incident holds, copied for its writer thread.
struct IncidentContent {
  fs::path folder;
  std::string name;
  std::vector<std::string> causes;
  double trigger_s = 0.0;
  std::vector<IncidentRecorder::Cycle> cycles;
  std::vector<IncidentJointState> joints;
  std::vector<IncidentExplanation> explanations;
};

void write_joints(const fs::path& file, const std::vector<IncidentJointState>& joints) {
  std::ostringstream text;
  text << std::setprecision(17) << "time_s,state,speed_scale,q_rad,velocity_rad_s\n";
  const auto spaced = [&text](const std::vector<double>& values) {
    for (std::size_t j = 0; j < values.size(); ++j) text << (j ? " " : "") << values[j];
  };
  for (const IncidentJointState& joint : joints) {
    text << joint.time_s << ',' << joint.state << ',' << joint.speed_scale << ',';
    spaced(joint.q);
    text << ',';
    spaced(joint.velocity);
    text << '\n';
  }
  write_text(file, text.str());
}

void write_into(const fs::path& partial, const IncidentContent& content,
                const IncidentSetup& setup) {
  fs::create_directories(partial / "maps");
  nlohmann::ordered_json incident;
  incident["format"] = kIncidentFormat;
  incident["causes"] = content.causes;
  incident["trigger_s"] = content.trigger_s;
  incident["stop_explanations"] = nlohmann::ordered_json::array();
  for (const IncidentExplanation& explanation : content.explanations) {
    incident["stop_explanations"].push_back(
        {{"time_s", explanation.time_s}, {"text", explanation.text}});
  }
  incident["setup"] = {{"cell_file", setup.cell_file.string()},
                       {"grid_fingerprint", fingerprint_hex(setup.grid_fingerprint)},
                       {"lut_fingerprint", fingerprint_hex(setup.lut_fingerprint)},
                       {"sync_error_s", setup.sync_error_s}};
  write_text(partial / "cell.yaml", setup.cell_text);

  const std::vector<std::string> cameras =
      content.cycles.empty() ? std::vector<std::string>{} : content.cycles.front().cameras;
  incident["cameras"] = cameras;
  std::vector<std::ostringstream> frame_times(cameras.size());
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    fs::create_directories(partial / "frames" / cameras[c]);
    frame_times[c] << "file,time_s\n" << std::setprecision(17);
    if (c < setup.reference.size()) {
      fs::create_directories(partial / "reference");
      write_image(partial / "reference" / (cameras[c] + ".png"), setup.reference[c]);
    }
  }
  incident["cycles"] = nlohmann::ordered_json::array();
  for (const IncidentRecorder::Cycle& kept : content.cycles) {
    for (std::size_t c = 0; c < kept.images.size() && c < cameras.size(); ++c) {
      if (kept.images[c].empty()) continue;  // the camera delivered nothing: no file
      const fs::path file = incident_frame_file(partial, cameras[c], kept.cycle.index);
      write_image(file, kept.images[c]);
      frame_times[c] << file.filename().string() << ',' << *kept.cycle.views[c].exposure_s << '\n';
    }
    write_bits(incident_map_file(partial, kept.cycle.index), kept.map);
    incident["cycles"].push_back(cycle_json(kept.cycle));
  }
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    write_text(partial / "frames" / cameras[c] / "frame_times.csv", frame_times[c].str());
  }
  write_joints(partial / "joints.csv", content.joints);
  // Text from outside (causes, details) may hold bytes that are not UTF-8: replaced, not thrown.
  write_text(partial / "incident.json",
             incident.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
}

// Writes under a hidden name and renames the whole folder into place; on any failure the
// partial folder goes and the outcome says why. Runs on a writer thread.
IncidentOutcome write_incident(const IncidentContent& content, const IncidentSetup& setup) {
  const fs::path partial = content.folder / ("." + content.name + ".partial");
  try {
    fs::path final_folder = content.folder / content.name;
    for (int k = 2; fs::exists(final_folder); ++k) {  // a name taken by an earlier run
      final_folder = content.folder / (content.name + "-" + std::to_string(k));
    }
    fs::remove_all(partial);
    write_into(partial, content, setup);
    for (const fs::path& folder : {partial / "frames", partial / "reference", partial}) {
      sync_directory(folder);  // the folders created in them
    }
    fs::rename(partial, final_folder);  // the folder appears whole or not at all
    sync_directory(content.folder);
    return {final_folder, ""};
  } catch (const std::exception& error) {
    std::error_code ignored;
    fs::remove_all(partial, ignored);
    return {{}, content.name + ": not written: " + error.what()};
  }
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
  std::error_code ignored;
  for (const auto& entry : fs::directory_iterator(settings_.folder, ignored)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(".incident-", 0) == 0 && name.size() > 8 &&
        name.compare(name.size() - 8, 8, ".partial") == 0) {
      fs::remove_all(entry.path(), ignored);
    }
  }
}

IncidentRecorder::~IncidentRecorder() {
  for (std::future<IncidentOutcome>& write : writes_) write.wait();
}

void IncidentRecorder::add_cycle(double exposure_s, const FrameSet& frames,
                                 const ServiceCycle& cycle, const CellSet& map) {
  Cycle kept;
  kept.cycle.index = cycle.index;
  kept.cycle.exposure_s = exposure_s;
  kept.cycle.pose_known = cycle.pose_known;
  kept.cycle.q = cycle.q;
  kept.cycle.known_views = cycle.known_views;
  kept.cycle.forbidden_cells = cycle.forbidden_cells;
  kept.cycle.all_forbidden = cycle.all_forbidden;
  // Each camera's exposure on the same seconds as the set's: its offset from the set's median.
  const double median_s = frames.frames.empty() ? 0.0 : median_exposure_s(frames);
  for (const CameraFrame& frame : frames.frames) {
    kept.cameras.push_back(frame.camera);
    const bool delivered = !frame.image.empty() && frame.image.type() == CV_8UC1;
    // Copied: a camera may reuse its buffer. A faulted view's frame is kept for the pictures.
    kept.images.push_back(delivered ? frame.image.clone() : cv::Mat());
    IncidentView view;
    if (delivered) view.exposure_s = exposure_s + (frame.exposure_s - median_s);
    view.fault = frame.view.fault;
    view.detail = frame.view.detail;
    kept.cycle.views.push_back(std::move(view));
  }
  kept.map = map;
  cycles_.push_back(std::move(kept));
  forget_cycles_before(exposure_s - settings_.keep_s);
}

void IncidentRecorder::add_joint_state(IncidentJointState state) {
  const double time_s = state.time_s;
  joints_.push_back(std::move(state));
  forget_joints_before(time_s - settings_.keep_s);
}

void IncidentRecorder::add_stop_explanation(double time_s, std::string text) {
  explanations_.push_back({time_s, std::move(text)});
  const double from = keep_from(time_s - settings_.keep_s);
  while (!explanations_.empty() && explanations_.front().time_s < from) explanations_.pop_front();
}

double IncidentRecorder::keep_from(double time_s) const {
  // While an incident is being recorded, everything from keep_s before its trigger stays.
  return trigger_s_ ? std::min(time_s, *trigger_s_ - settings_.keep_s) : time_s;
}

void IncidentRecorder::forget_cycles_before(double time_s) {
  const double from = keep_from(time_s);
  while (!cycles_.empty() && cycles_.front().cycle.exposure_s < from) cycles_.pop_front();
}

void IncidentRecorder::forget_joints_before(double time_s) {
  const double from = keep_from(time_s);
  while (!joints_.empty() && joints_.front().time_s < from) joints_.pop_front();
}

void IncidentRecorder::trigger(double time_s, const std::string& cause) {
  if (handed_over_ >= settings_.max_incidents) return;
  if (!trigger_s_) trigger_s_ = time_s;
  if (causes_.size() < 32) causes_.push_back(cause);
}

std::vector<IncidentOutcome> IncidentRecorder::poll(double now_s) {
  if (trigger_s_ && now_s >= *trigger_s_ + settings_.after_s) hand_over();
  return collect(false);
}

std::vector<IncidentOutcome> IncidentRecorder::flush() {
  if (trigger_s_) hand_over();
  return collect(true);
}

std::vector<IncidentOutcome> IncidentRecorder::collect(bool wait) {
  std::vector<IncidentOutcome> outcomes = std::move(dropped_);
  not_written_ += outcomes.size();
  dropped_.clear();
  for (auto write = writes_.begin(); write != writes_.end();) {
    if (!wait && write->wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      ++write;
      continue;
    }
    outcomes.push_back(write->get());
    ++(outcomes.back().error.empty() ? written_ : not_written_);
    write = writes_.erase(write);
  }
  return outcomes;
}

void IncidentRecorder::hand_over() {
  ++handed_over_;
  const std::string name = "incident-" + utc_stamp() + "-" + std::to_string(handed_over_);
  if (writes_.size() >= kMaxWritesInFlight) {
    dropped_.push_back({{},
                        name + ": dropped, " + std::to_string(writes_.size()) +
                            " incidents are still being written"});
  } else {
    // The writer's own copy: the images are shared, never written again by the recorder.
    IncidentContent content{
        settings_.folder,
        name,
        causes_,
        *trigger_s_,
        std::vector<Cycle>(cycles_.begin(), cycles_.end()),
        std::vector<IncidentJointState>(joints_.begin(), joints_.end()),
        std::vector<IncidentExplanation>(explanations_.begin(), explanations_.end())};
    writes_.push_back(
        std::async(std::launch::async, [content = std::move(content), setup = &settings_.setup] {
          return write_incident(content, *setup);
        }));
  }
  trigger_s_.reset();
  causes_.clear();
  if (!cycles_.empty()) forget_cycles_before(cycles_.back().cycle.exposure_s - settings_.keep_s);
  if (!joints_.empty()) forget_joints_before(joints_.back().time_s - settings_.keep_s);
}

}  // namespace safecell

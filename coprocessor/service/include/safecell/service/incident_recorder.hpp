#pragma once
// The incident recorder: the service's last seconds kept in memory (each cycle's frames, the
// robot's pose at the exposure, the forbidden map sent; the controller's joint stream with its
// state), and on a stop or a fault written into a folder of its own for `safecell replay`. The
// folder is built under a hidden temporary name and renamed when whole, so a folder that exists
// is complete:
//   incident.json           the cause, the trigger time, the cameras, the cycles (exposure,
//                           pose, views known, forbidden cells, why all was forbidden)
//   frames/<camera>/        <cycle>.png and frame_times.csv (an image folder source reads it)
//   maps/<cycle>.bits       the forbidden map sent: its cell bits as little-endian 64-bit words
//   joints.csv              time_s, state, speed_scale, q_rad (per joint, space-separated)
// Times are seconds since the run began, on the service's clock.
// Thread context: the service's thread; not synchronised.

#include <cstdint>
#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "safecell/acquisition/frame_set.hpp"
#include "safecell/lut/cell_set.hpp"
#include "safecell/service/sensing_service.hpp"

namespace safecell {

struct IncidentSettings {
  std::filesystem::path folder;    // incidents go into <folder>/<time>-<cause>/
  double keep_s = 3.0;             // recorded before the trigger
  double after_s = 1.0;            // and after it
  std::size_t max_incidents = 50;  // then no more are written (the disk)
};

// One joint state of the controller's stream, as the recorder keeps it.
struct RecordedJointState {
  double time_s = 0.0;
  std::string state;  // the controller's state by name (moving, slowed, stopped, fault, ...)
  double speed_scale = 0.0;
  std::vector<double> q;
};

class IncidentRecorder {
 public:
  // Throws std::invalid_argument for times outside 0.1..60 s or a missing folder name.
  explicit IncidentRecorder(IncidentSettings settings);

  // A cycle of the service at `exposure_s`: its frames (copied: a camera may reuse its buffer),
  // what the cycle found and the map it sent.
  void add_cycle(double exposure_s, const FrameSet& frames, const ServiceCycle& cycle,
                 const CellSet& map);
  void add_joint_state(RecordedJointState state);

  // An incident begins at `time_s` with `cause`, unless one is being recorded (it then covers
  // this one too; the cause is added to its list).
  void trigger(double time_s, const std::string& cause);
  // Writes the incident being recorded once `now_s` is after_s past its trigger; the folder
  // written, if any.
  std::optional<std::filesystem::path> poll(double now_s);
  // Writes the incident being recorded now, with what it has (the end of a run).
  std::optional<std::filesystem::path> flush();

  [[nodiscard]] std::size_t incidents_written() const { return written_; }

 private:
  struct Cycle {
    double exposure_s = 0.0;
    std::uint64_t index = 0;
    std::vector<std::string> cameras;
    std::vector<cv::Mat> images;  // empty where the view was unknown
    bool pose_known = false;
    std::vector<double> q;
    std::uint32_t known_views = 0;
    std::size_t forbidden_cells = 0;
    std::string all_forbidden;
    CellSet map{0};
  };

  // Each stream by its own times (the joint stream runs ahead of the frames' exposures).
  void forget_cycles_before(double time_s);
  void forget_joints_before(double time_s);
  std::filesystem::path write();

  IncidentSettings settings_;
  std::deque<Cycle> cycles_;
  std::deque<RecordedJointState> joints_;
  std::optional<double> trigger_s_;
  std::vector<std::string> causes_;
  std::size_t written_ = 0;
};

}  // namespace safecell

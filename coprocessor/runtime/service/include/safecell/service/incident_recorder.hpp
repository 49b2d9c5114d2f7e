#pragma once
// The incident recorder: the service's last seconds kept in memory (each cycle's frames, the
// robot's pose at the exposure, the forbidden map sent; the controller's joint stream with its
// state), and on a stop or a fault written into a folder of its own for `safecell replay`, laid
// out as incident_folder.hpp says. The folder is built under a hidden temporary name and renamed
// when whole, so a folder that exists is complete; one that cannot be written is removed again.
// Thread context: the service's thread; not synchronised.

#include <cstdint>
#include <deque>
#include <filesystem>
#include <future>
#include <optional>
#include <string>
#include <vector>

#include "safecell/acquisition/frame_set.hpp"
#include "safecell/cellsets/cell_set.hpp"
#include "safecell/service/incident_folder.hpp"
#include "safecell/service/sensing_service.hpp"

namespace safecell {

struct IncidentSettings {
  std::filesystem::path folder;    // incidents go into <folder>/incident-<UTC time>-<n>/
  double keep_s = 3.0;             // recorded before the trigger
  double after_s = 1.0;            // and after it
  std::size_t max_incidents = 50;  // then no more are written (the disk)
  IncidentSetup setup;             // what the service runs with, written into every incident
};

// What became of an incident handed to the writer.
struct IncidentOutcome {
  std::filesystem::path folder;  // written here; empty when it was not
  std::string error;             // why not (the disk), naming the file
};

class IncidentRecorder {
 public:
  // Throws std::invalid_argument for times outside 0.1..60 s or a missing folder name. Removes
  // the partial folders a crashed run left in the folder.
  explicit IncidentRecorder(IncidentSettings settings);
  // Waits for the writes in flight.
  ~IncidentRecorder();
  IncidentRecorder(const IncidentRecorder&) = delete;
  IncidentRecorder& operator=(const IncidentRecorder&) = delete;

  // A cycle of the service at `exposure_s`: its frames (copied: a camera may reuse its buffer),
  // what the cycle found and the map it sent.
  void add_cycle(double exposure_s, const FrameSet& frames, const ServiceCycle& cycle,
                 const CellSet& map);
  void add_joint_state(IncidentJointState state);
  // Why the controller slowed down or stopped at `time_s` (the service's stop explanation),
  // kept as the joint stream is; written into incident.json as "stop_explanations".
  void add_stop_explanation(double time_s, std::string text);

  // An incident begins at `time_s` with `cause`, unless one is being recorded (it then covers
  // this one too; the cause is added to its list).
  void trigger(double time_s, const std::string& cause);
  // Hands the incident being recorded to a writer thread once `now_s` is after_s past its
  // trigger, and returns what became of the writes that have ended since the last call. Writing
  // runs beside the service: encoding a few hundred frames takes longer than the controller's
  // watchdog allows between maps. With kMaxWritesInFlight writes still running, the incident is
  // dropped and that is its outcome. A write that fails removes its partial folder; the service
  // logs the outcome and goes on (recording is not what keeps anybody safe).
  std::vector<IncidentOutcome> poll(double now_s);
  // Hands over the incident being recorded now, with what it has, and waits for every write
  // (the end of a run).
  std::vector<IncidentOutcome> flush();

  // Incidents written whole so far (outcomes returned without an error).
  [[nodiscard]] std::size_t incidents_written() const { return written_; }
  // Incidents that could not be written (the disk) or were dropped (writers busy).
  [[nodiscard]] std::size_t incidents_not_written() const { return not_written_; }

  static constexpr std::size_t kMaxWritesInFlight = 2;

  // One kept cycle (public for the writer; not part of the interface).
  struct Cycle {
    IncidentCycle cycle;
    std::vector<std::string> cameras;
    std::vector<cv::Mat> images;  // per camera; empty where it delivered no frame
    CellSet map{0};
  };

 private:
  // Each stream by its own times (the joint stream runs ahead of the frames' exposures).
  void forget_cycles_before(double time_s);
  void forget_joints_before(double time_s);
  // Where keeping of the stream that runs up to `time_s` starts (keep_s before it, or before the
  // trigger of the incident being recorded).
  [[nodiscard]] double keep_from(double time_s) const;
  // Hands the incident to a writer, or drops it with an outcome saying why.
  void hand_over();
  std::vector<IncidentOutcome> collect(bool wait);

  IncidentSettings settings_;
  std::deque<Cycle> cycles_;
  std::deque<IncidentJointState> joints_;
  std::deque<IncidentExplanation> explanations_;
  std::optional<double> trigger_s_;
  std::vector<std::string> causes_;
  std::size_t handed_over_ = 0;
  std::size_t written_ = 0;
  std::size_t not_written_ = 0;
  std::vector<IncidentOutcome> dropped_;
  std::vector<std::future<IncidentOutcome>> writes_;
};

}  // namespace safecell

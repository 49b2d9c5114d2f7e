#pragma once
// The report folder of `safecell demo`: the pictures composed during the run (camera views,
// forbidden-map slices with the robot's path), timeline.png, floor_coverage.png, summary.json and
// index.html, all written atomically. Private to the CLI.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "report_video.hpp"
#include "safecell/cellsets/cell_set.hpp"
#include "safecell/closed_loop/closed_loop_record.hpp"
#include "safecell/closed_loop/demo_world.hpp"
#include "safecell/service/incident_folder.hpp"
#include "safecell/validation/scene_check.hpp"
#include "simulated_sensing.hpp"

namespace safecell {

// The pictures of one moment, composed in the loop and written after it (PNG encoding would cost
// the loop frames).
struct DemoSnapshot {
  std::size_t cycle = 0;
  double time_s = 0.0;
  cv::Mat views;
  CellSet forbidden;
  CellIndex robot_cell = 0;
  std::vector<CellIndex> path;
};

inline constexpr double kDemoPathSeconds = 3.0;  // of the robot's path drawn on each slice

// The four cameras with their blocked, robot and obstacle cells, and the controller's state.
cv::Mat demo_views_picture(const std::vector<cv::Mat>& frames, const SensingPipeline& pipeline,
                           const CellModel& cell, const std::string& state);

// While the person is within 1 m of the robot (FCL, at each frame's exposure): how much of the
// C-space the fused map and the map sent (forbidden whole by the protective separation) left free.
struct NearPersonFreeSpace {
  static constexpr double kNear_m = 1.0;
  std::size_t frames = 0;
  std::size_t separation_frames = 0;  // of them, maps the protective separation forbade whole
  std::size_t slowed_frames = 0;      // maps sent with its reduced speed (not forbidden whole)
  double speed_limit_sum = 0.0;       // the speed limit sent (1: none, 0: a stop), summed
  double map_free_sum = 0.0;          // the fused map's free share, summed over the frames
  double sent_free_sum = 0.0;         // the sent map's

  [[nodiscard]] double map_free_share() const {
    return frames == 0 ? 0.0 : map_free_sum / static_cast<double>(frames);
  }
  [[nodiscard]] double sent_free_share() const {
    return frames == 0 ? 0.0 : sent_free_sum / static_cast<double>(frames);
  }
  [[nodiscard]] double mean_speed_limit() const {
    return frames == 0 ? 0.0 : speed_limit_sum / static_cast<double>(frames);
  }
};

struct DemoRun {
  double seconds = 0.0;
  double fps = 0.0;
  ClosedLoopRecord record;
  std::vector<DemoSnapshot> snapshots;
  ReportVideo video{5.0};  // the cameras with the state, 5 frames a second of the run
  SceneCheck checks;
  std::size_t frames_skipped = 0;
  std::vector<double> acknowledged_s;  // when the demo's operator acknowledged a fault
  std::vector<IncidentExplanation> stop_explanations;  // why the controller slowed or stopped
  NearPersonFreeSpace near_person;
  bool controller_died = false;
  std::size_t incidents_not_written = 0;  // could not be written (the disk) or dropped
  std::optional<int> controller_exit;
};

// Writes the report into `folder` and returns whether the run was safe (no contact while moving,
// nothing missed, the controller alive to the end). The summary goes to `out`.
bool write_demo_report(const std::filesystem::path& folder, const SimulatedSensing& sensing,
                       const DemoWorld& world, const std::vector<std::vector<double>>& goals,
                       const DemoRun& run, std::ostream& out, std::ostream& log);

}  // namespace safecell

#pragma once
// One closed-loop scenario in simulated time: the whole loop (render -> the coprocessor's sensing
// pipeline -> the link (real UDP, the real protocol) -> safecell-controller --lockstep -> its
// simulated robot) with a person's visit, and the FCL ground truth at every controller cycle.
//
// Time: the controller's clock moves only when this driver says (lockstep_controller.hpp). A frame
// set is exposed every 1/fps; its map reaches the controller `latency_ms` later (camera readout,
// transfer and processing: the pipeline's own time does not count in simulated time, this
// figure stands for it). The cameras see the robot where the controller's simulated robot was at
// the exposure (its joints at the cycles around it, interpolated) and the person where the
// scenario has them. The ground truth: the simulated robot's own joints at every cycle (not the
// protocol's joint stream) against the person's shapes at that moment (check_contacts).

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "safecell/cell/cell_model.hpp"
#include "safecell/closed_loop/closed_loop_record.hpp"
#include "safecell/closed_loop/closed_loop_scenario.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

// What every scenario of a run shares.
struct LockstepParts {
  const CellModel& cell;
  const CspaceGrid& grid;
  SensingPipeline& pipeline;
  SimulatedCell& sim;
  std::uint64_t lut_fingerprint = 0;
  double sync_error_s = 0.002;    // the fusion's timing allowance (FusionSettings)
  std::filesystem::path program;  // safecell-controller
  std::filesystem::path folder;   // controller.yaml and controller.log of the last scenario
  std::vector<cv::Mat> camera_references;  // the empty cell per camera (health checks)
};

struct LockstepSettings {
  double fps = 30.0;
  double latency_ms = 20.0;          // exposure -> map at the controller; below one frame period
  double max_seconds = 30.0;         // a scenario ends here when the task has not
  double acknowledge_after_s = 1.0;  // the operator acknowledges a fault held this long
  bool look_ahead_off = false;       // the negative control (safety.test_only_look_ahead_off)
  // When set: a CSV of every controller cycle (time, state, speed scale, joints, velocities, the
  // person's place and the FCL distance) is written to this file.
  std::filesystem::path trace_file;
};

struct ScenarioResult {
  ContactFigures contacts;  // its per-sample distances left out
  StateFigures states;      // its latencies left out (modelled here, not measured)
  std::size_t frames = 0;
  std::size_t all_forbidden_frames = 0;
  std::map<std::string, std::size_t> all_forbidden_because;  // frames per reason
  std::size_t separation_slowed_frames = 0;  // maps sent with a speed limit below 1, not stopped
  std::string outcome;  // the controller's (task completed, task failed) or "time limit"
  bool task_completed = false;
  double task_time_s = 0.0;  // when the task ended, from the start
  double simulated_s = 0.0;
  std::uint64_t controller_cycles = 0;
};

// Runs one scenario: `person` empty for the task's baseline. Throws ClosedLoopSetupError or
// LinkSetupError when the controller program cannot be run or breaks the lockstep contract.
ScenarioResult run_lockstep_scenario(LockstepParts& parts, const LockstepSettings& settings,
                                     const RobotTask& task,
                                     const std::optional<PersonVisitPlan>& person);

}  // namespace safecell

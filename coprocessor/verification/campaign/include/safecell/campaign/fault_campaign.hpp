#pragma once
// A fault campaign on loopback with real processes: for each fault class a trial in real time,
// the coprocessor's sensing service on the simulated cell (this process), the safecell-controller
// program (a child process with its trace), and the fault-injecting proxy between them. A trial
// lets the robot work, injects the fault, ends it, lets the operator acknowledge what latched, and
// then checks the records (trial_checks.hpp).
//
// What "coprocessor killed" means here: this process's link falls silent without a word and a new
// link (a new session) opens later, which is all a controller can see of a coprocessor that died
// and started again. "Controller restarted" kills the program for real (SIGKILL).

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "safecell/campaign/fault_class.hpp"
#include "safecell/campaign/trial_checks.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

// The simulated cell's sensing the campaign runs (the CLI's SimulatedSensing).
struct CampaignSensing {
  const CellModel& cell;
  const CspaceGrid& grid;
  SensingPipeline& pipeline;
  std::uint64_t lut_fingerprint = 0;
  SimulatedCell& sim;
  double sync_error_s = 0.002;
  std::vector<cv::Mat> camera_references;  // the empty cell per camera (health checks)
};

struct CampaignSettings {
  std::vector<FaultClass> classes = all_fault_classes();
  double settle_s = 2.0;   // the robot working before the fault
  double fault_s = 1.5;    // the fault
  double recover_s = 4.0;  // after it: the operator's acknowledgement, and motion again
  double fps = 30.0;
  double link_fault_rate = 0.3;  // per datagram, for the faults injected at a rate
  std::uint64_t seed = 1;
  std::filesystem::path folder;              // a folder per trial: controller files and trace
  std::filesystem::path controller_program;  // safecell-controller
  // The negative control only: the controller's watchdog and maximum data age (ms), when not the
  // campaign's 250 ms. The checks keep the campaign's bounds, so a longer watchdog must fail.
  double test_only_controller_limits_ms = 0.0;
};

struct CampaignResult {
  std::vector<TrialResult> trials;
  TrialBounds bounds;
  [[nodiscard]] bool passed() const;
};

// Runs every class of settings.classes in turn; progress and each trial's outcome go to `log`.
// Throws ClosedLoopSetupError or LinkSetupError when a trial cannot be set up at all.
CampaignResult run_fault_campaign(const CampaignSensing& sensing, const CampaignSettings& settings,
                                  std::ostream& log);

// The result as JSON: {"passed":..,"bounds":{..},"trials":[{"fault":..,..,"failures":[..]}]}.
std::string campaign_json(const CampaignResult& result);

}  // namespace safecell

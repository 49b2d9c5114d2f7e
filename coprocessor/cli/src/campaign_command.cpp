#include "safecell/cli/campaign_command.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <sstream>

#include "command_line.hpp"
#include "safecell/campaign/fault_campaign.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/closed_loop/controller_setup.hpp"
#include "safecell/files/atomic_write.hpp"
#include "scene_options.hpp"
#include "simulated_sensing.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

std::vector<FaultClass> classes_named(const std::string& list) {
  if (list.empty()) return all_fault_classes();
  std::vector<FaultClass> classes;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    const auto fault = fault_class_named(name);
    if (!fault) {
      std::string known;
      for (FaultClass each : all_fault_classes()) known += std::string(" ") + to_string(each);
      bad_option("--faults", name, "fault classes among:" + known);
    }
    classes.push_back(*fault);
  }
  return classes;
}

void check_options(const CampaignOptions& options) {
  const auto in_range = [](double value, double low, double high) {
    return value >= low && value <= high;
  };
  if (!in_range(options.settle_s, 1.0, 60.0)) {
    bad_option("--settle", std::to_string(options.settle_s), "1..60 s");
  }
  if (!in_range(options.fault_s, 0.5, 60.0)) {
    bad_option("--fault-seconds", std::to_string(options.fault_s), "0.5..60 s");
  }
  if (!in_range(options.recover_s, 1.0, 60.0)) {
    bad_option("--recover", std::to_string(options.recover_s), "1..60 s");
  }
  if (!in_range(options.rate, 0.01, 1.0)) {
    bad_option("--rate", std::to_string(options.rate), "a probability of 0.01..1 per datagram");
  }
  if (!(options.test_only_controller_limits_ms == 0.0 ||
        in_range(options.test_only_controller_limits_ms, 1.0, 60'000.0))) {
    bad_option("--test-only-controller-limits-ms",
               std::to_string(options.test_only_controller_limits_ms), "0 or 1..60000 ms");
  }
}

std::string optional_fixed(const std::optional<double>& value, int decimals) {
  return value ? fixed(*value, decimals) : "-";
}

void print_table(const CampaignResult& result, std::ostream& out) {
  using Align = TextTable::Align;
  TextTable table({{"fault", Align::kLeft},
                   {"injected", Align::kRight},
                   {"detected", Align::kRight},
                   {"maps refused", Align::kRight},
                   {"stops", Align::kRight},
                   {"held after ms", Align::kRight},
                   {"maps applied", Align::kRight},
                   {"wrong accepted", Align::kRight},
                   {"stale motion", Align::kRight},
                   {"oldest map moved on ms", Align::kRight},
                   {"moving again s", Align::kRight},
                   {"host late ms", Align::kRight},
                   {"causes named", Align::kLeft},
                   {"result", Align::kLeft}});
  for (const TrialResult& trial : result.trials) {
    std::string causes;
    for (const std::string& cause : trial.causes) causes += (causes.empty() ? "" : ", ") + cause;
    table.add_row({to_string(trial.fault), std::to_string(trial.injected),
                   std::to_string(trial.detected), std::to_string(trial.maps_refused),
                   std::to_string(trial.stops), optional_fixed(trial.stop_ms, 0),
                   std::to_string(trial.maps_applied), std::to_string(trial.wrong_maps),
                   std::to_string(trial.stale_motion_cycles),
                   fixed(trial.worst_moving_map_age_ms, 0), optional_fixed(trial.recovered_s, 1),
                   fixed(trial.host.controller_late_ms, 0), causes.empty() ? "-" : causes,
                   std::string(trial.passed() ? "passed" : "FAILED") +
                       (trial.rerun_because ? " (2nd run)" : "")});
  }
  table.print(out);
  std::uint64_t refused_without_fault = 0;
  for (const TrialResult& trial : result.trials)
    refused_without_fault += trial.refused_without_fault;
  for (const TrialResult& trial : result.trials) {
    if (!trial.rerun_because) continue;
    out << to_string(trial.fault) << ": run twice, " << *trial.rerun_because << "; the first run: ";
    for (const std::string& failure : trial.first_run_failures) out << failure << "; ";
    out << "\n";
  }
  out << "host late ms: the controller's latest cycle beyond its period, from the fault's start "
         "(time bounds that break, or updates refused on a clean link, while a cycle is later than "
         "its watchdog's window or the service a frame behind, get one more run)\n";
  out << "map updates refused while the link had no fault: " << refused_without_fault
      << " (must be 0)\n";
  out << "bounds: held within " << fixed(result.bounds.stop_ms, 0)
      << " ms of the fault (T_wd + a late cycle), within "
      << fixed(result.bounds.latched_stop_ms, 0)
      << " ms of a latching error; motion only on maps exposed at most "
      << fixed(result.bounds.moving_map_age_ms, 0) << " ms before; moving again within "
      << fixed(result.bounds.recover_s, 1) << " s of the fault's end\n";
}

}  // namespace

int run_campaign(const CampaignOptions& options, std::ostream& out, std::ostream& err) {
  check_options(options);
  CampaignSettings settings;
  settings.classes = classes_named(options.faults);
  settings.settle_s = options.settle_s;
  settings.fault_s = options.fault_s;
  settings.recover_s = options.recover_s;
  settings.link_fault_rate = options.rate;
  settings.seed = options.seed;
  settings.folder = fs::absolute(options.out_dir);
  settings.controller_program = find_controller_program(options.controller_program);
  settings.test_only_controller_limits_ms = options.test_only_controller_limits_ms;
  if (settings.test_only_controller_limits_ms > 0.0) {
    err << "campaign: WARNING: the controller runs with a watchdog and data age limit of "
        << settings.test_only_controller_limits_ms
        << " ms, the campaign checks 250 ms: the negative control, which must fail\n";
  }
  fs::create_directories(settings.folder);

  SimulatedSensing sensing(options.cell_path, options.lut_cache, options.seed, err);
  const CampaignSensing campaign_sensing{sensing.cell,
                                         sensing.grid,
                                         sensing.pipeline,
                                         sensing.luts.set.fingerprint,
                                         sensing.sim,
                                         sensing.fusion.sync_error_s,
                                         sensing.reference.frames};
  const CampaignResult result = run_fault_campaign(campaign_sensing, settings, err);
  const std::string json = campaign_json(result);
  write_file_atomically(settings.folder / "campaign.json", json + "\n");
  if (options.json) {
    out << json << "\n";
  } else {
    print_table(result, out);
    out << (result.passed() ? "campaign passed" : "campaign FAILED") << " (" << result.trials.size()
        << " trials; " << (settings.folder / "campaign.json").string() << ")\n";
  }
  return result.passed() ? 0 : 1;
}

void add_campaign_command(CLI::App& app, CommandLine& line) {
  const auto campaign = std::make_shared<CampaignOptions>();
  CLI::App* campaign_command = app.add_subcommand(
      "campaign",
      "Fault campaign on loopback with real processes: each fault class of SAFETY.md (link "
      "corruption, repetition, reorder, loss, insertion, foreign session, delay, cut; wrong "
      "fingerprint, coprocessor killed, controller restarted; cameras frozen, blinded, moved, "
      "unplugged) injected into a working closed loop with safecell-controller; checks that the "
      "robot is held in time, that no map the coprocessor did not send is accepted, that the "
      "robot never moves on stale data, that the cause is named and that the loop recovers "
      "after acknowledgement. Prints a table, writes <out>/campaign.json; exit 1 on a failure");
  campaign_command->add_option("--faults", campaign->faults,
                               "Comma-separated fault classes (default: all)");
  campaign_command
      ->add_option("--out", campaign->out_dir, "Folder for the trials and campaign.json")
      ->capture_default_str();
  campaign_command->add_option("--cell", campaign->cell_path,
                               "The cell file (default: the built-in default cell)");
  campaign_command->add_option("--lut-cache", campaign->lut_cache,
                               "Folder of cached look-up tables; default $SAFECELL_CACHE or "
                               "~/.cache/safecell");
  campaign_command
      ->add_option("--settle", campaign->settle_s, "Seconds the robot works before each fault")
      ->capture_default_str();
  campaign_command->add_option("--fault-seconds", campaign->fault_s, "Seconds each fault lasts")
      ->capture_default_str();
  campaign_command
      ->add_option("--recover", campaign->recover_s,
                   "Seconds after each fault for acknowledgement and recovery")
      ->capture_default_str();
  campaign_command
      ->add_option("--rate", campaign->rate,
                   "Probability per datagram of the faults injected at a rate")
      ->capture_default_str();
  campaign_command->add_option("--seed", campaign->seed, "Seed of the proxy and the sensor noise")
      ->capture_default_str();
  campaign_command->add_flag("--json", campaign->json, "Print campaign.json instead of the table");
  campaign_command->add_option("--controller-program", campaign->controller_program,
                               "The safecell-controller program (default: beside safecell)");
  campaign_command->add_option(
      "--test-only-controller-limits-ms", campaign->test_only_controller_limits_ms,
      "The negative control: the controller's watchdog and data age limit in ms instead of "
      "250 (the checks keep 250): the campaign must then fail");
  campaign_command->callback([=, &line] {
    line.action = [=, &line] { line.exit_code = run_campaign(*campaign, line.out, line.err); };
  });
}

}  // namespace safecell

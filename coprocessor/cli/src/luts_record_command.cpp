#include "safecell/cli/luts_record_command.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "command_line.hpp"
#include "progress_bar.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/lut_build/recorded_luts.hpp"
#include "safecell/lut_files/lut_cache.hpp"
#include "safecell/lut_files/lut_file.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/silhouettes/silhouette_agreement.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim_sources/simulated_reference.hpp"
#include "safecell/sim_sources/simulated_robot_viewer.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

RecordingOptions recording_options(const LutsRecordOptions& options) {
  RecordingOptions recording;
  recording.key_stride = options.key_stride;
  recording.wrist_samples = options.wrist_samples;
  recording.padding_m = options.padding_m;
  return recording;
}

// The robot moved through every key of the simulated cell, with a progress bar.
void record_simulated(const CellModel& cell, RecordedSilhouettes& recording, std::ostream& err) {
  SimulatedCell sim = simulate_cell(cell, SensorSettings{});
  const std::vector<cv::Mat> reference = simulated_reference(sim, cell, 9, 1).frames;
  SimulatedRobotViewer viewer(sim, cell, reference);
  err << "recording " << grouped(recording.configuration_count())
      << " robot configurations on the simulated cell (" << grouped(recording.key_count())
      << " keys x " << recording.wrist_combinations() << " wrist samples)\n";
  ProgressBar bar(err, &err == &std::cerr && ProgressBar::stderr_is_terminal());
  recording.record([&viewer](const std::vector<double>& q) { return viewer(q); },
                   [&bar](double fraction) { bar.update("recording", fraction); });
  bar.finish();
}

nlohmann::ordered_json agreement_json(const std::vector<CameraAgreement>& agreement) {
  nlohmann::ordered_json cameras = nlohmann::ordered_json::array();
  for (const auto& camera : agreement) {
    cameras.push_back({{"name", camera.camera},
                       {"keys", camera.keys},
                       {"coverage", camera.coverage()},
                       {"fill", camera.fill()},
                       {"flagged", camera.flagged}});
  }
  return cameras;
}

void print_agreement(const std::vector<CameraAgreement>& agreement, double min_coverage,
                     std::ostream& out) {
  using Align = TextTable::Align;
  TextTable table({{"camera", Align::kLeft},
                   {"keys", Align::kRight},
                   {"coverage", Align::kRight},
                   {"fill", Align::kRight},
                   {"", Align::kLeft}});
  for (const auto& camera : agreement) {
    table.add_row({camera.camera, grouped(camera.keys), fixed(100.0 * camera.coverage(), 1) + " %",
                   fixed(100.0 * camera.fill(), 1) + " %",
                   camera.flagged ? "CHECK CALIBRATION" : "ok"});
  }
  table.print(out);
  out << "  coverage: the share of the robot's recorded feature cells inside the model's "
         "silhouette (below "
      << fixed(100.0 * min_coverage, 0)
      << " % flags the camera: robot removal would leave the robot as an obstacle)\n"
         "  fill: recorded feature cells per model feature cell (how conservative the model "
         "is)\n";
}

}  // namespace

void run_luts_record(const LutsRecordOptions& options, std::ostream& out, std::ostream& err) {
  if (options.out_dir.empty()) throw InputError("luts record needs --out DIR");
  const CellModel cell = load_cell_model(load_cell_file_or_default(options.cell_path));
  const CspaceGrid grid = make_grid(cell.config);
  const auto start = std::chrono::steady_clock::now();
  const auto recording =
      std::make_unique<RecordedSilhouettes>(cell, grid, recording_options(options));
  check_recording_bounded(*recording);
  record_simulated(cell, *recording, err);
  ProgressBar bar(err, &err == &std::cerr && ProgressBar::stderr_is_terminal());
  const char* const stages[kLutBuildStages] = {"LUT-1 from the recording", "LUT-2 inversion",
                                               "static obstacles"};
  const LutSet set =
      build_recorded_luts(cell, grid, *recording, 0,
                          [&](int stage, double fraction) { bar.update(stages[stage], fraction); });
  bar.finish();
  const fs::path file = lut_cache_file(options.out_dir, set.fingerprint);
  fs::create_directories(options.out_dir);
  write_lut_file(file, set);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const ModelSilhouettes model(cell, grid, ModelLutOptions{});
  const auto agreement = compare_with_model(cell, grid, *recording, model, options.min_coverage);
  if (options.json) {
    nlohmann::ordered_json report;
    report["file"] = file.string();
    report["fingerprint"] = hex64(set.fingerprint);
    report["configurations"] = recording->configuration_count();
    report["motion_bound_m"] = recording->motion_bound_m();
    report["build_s"] = seconds;
    report["cameras"] = agreement_json(agreement);
    out << report.dump(2) << '\n';
    return;
  }
  out << "recorded tables in " << fixed(seconds, 1) << " s: " << file.string() << "\n"
      << "  " << grouped(recording->configuration_count())
      << " configurations; silhouettes dilated for a motion of "
      << fixed(recording->motion_bound_m(), 3) << " m between keys\n";
  print_agreement(agreement, options.min_coverage, out);
}

int run_luts_check(const LutsRecordOptions& options, std::ostream& out, std::ostream& err) {
  const CellModel cell = load_cell_model(load_cell_file_or_default(options.cell_path));
  const CspaceGrid grid = make_grid(cell.config);
  const auto recording =
      std::make_unique<RecordedSilhouettes>(cell, grid, recording_options(options));
  record_simulated(cell, *recording, err);
  const ModelSilhouettes model(cell, grid, ModelLutOptions{});
  const auto agreement = compare_with_model(cell, grid, *recording, model, options.min_coverage);
  bool flagged = false;
  for (const auto& camera : agreement) flagged = flagged || camera.flagged;
  if (options.json) {
    nlohmann::ordered_json report;
    report["configurations"] = recording->configuration_count();
    report["min_coverage"] = options.min_coverage;
    report["cameras"] = agreement_json(agreement);
    report["flagged"] = flagged;
    out << report.dump(2) << '\n';
  } else {
    out << "recorded robot against the model, " << grouped(recording->key_count()) << " keys\n";
    print_agreement(agreement, options.min_coverage, out);
  }
  return flagged ? kExitCameraFlagged : 0;
}

void add_luts_record_and_check_commands(CLI::App& luts, CommandLine& line) {
  const auto record = std::make_shared<LutsRecordOptions>();
  const auto add_recording_options = [&record](CLI::App* command) {
    command->add_option("--cell", record->cell_path,
                        "Cell file (YAML); without it the built-in default cell");
    command
        ->add_option("--key-stride", record->key_stride,
                     "Cells between key configurations along each discretised joint (1: every "
                     "cell, the paper's brute force)")
        ->capture_default_str()
        ->check(CLI::Range(1, 64));
    command
        ->add_option("--wrist-samples", record->wrist_samples,
                     "Values recorded per joint that is not discretised")
        ->capture_default_str()
        ->check(CLI::Range(1, 64));
    command
        ->add_option("--min-coverage", record->min_coverage,
                     "Share of the recorded robot that must lie inside the model's silhouettes")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    command->add_flag("--json", record->json, "Print one JSON object instead of a table");
  };
  CLI::App* record_command = luts.add_subcommand(
      "record",
      "Build the tables from difference images of the robot at key configurations (recorded "
      "mode; the simulated cell stands in for the real robot and cameras)");
  add_recording_options(record_command);
  record_command->add_option("--out", record->out_dir, "Folder for the LUT file")->required();
  record_command
      ->add_option("--padding", record->padding_m, "Margin added to the motion bound, metres")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  record_command->callback(
      [=, &line] { line.action = [=, &line] { run_luts_record(*record, line.out, line.err); }; });
  CLI::App* check_command = luts.add_subcommand(
      "check",
      "Compare what each camera sees of the robot with the model's silhouettes and flag a "
      "camera whose calibration is off (exit 1); the simulated cell stands in for the real "
      "robot and cameras");
  add_recording_options(check_command);
  check_command->callback([=, &line] {
    line.action = [=, &line] { line.exit_code = run_luts_check(*record, line.out, line.err); };
  });
}

}  // namespace safecell

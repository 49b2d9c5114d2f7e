#include "safecell/cli/cell_coverage_command.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "command_line.hpp"
#include "coverage_picture.hpp"
#include "png_output.hpp"
#include "progress_bar.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/files/atomic_write.hpp"
#include "safecell/validation/floor_coverage.hpp"

namespace safecell {

void run_cell_coverage(const CellCoverageOptions& options, std::ostream& out, std::ostream& err) {
  const CellModel cell = load_cell_model(load_cell_file_or_default(options.cell_path));
  const CspaceGrid grid = make_grid(cell.config);
  CoverageOptions settings;
  settings.step_m = options.step_m;
  ProgressBar bar(err, &err == &std::cerr && ProgressBar::stderr_is_terminal());
  const FloorCoverage coverage =
      floor_coverage(cell, grid, settings, [&bar](std::size_t done, std::size_t total) {
        bar.update("floor positions", static_cast<double>(done) / static_cast<double>(total));
      });
  bar.finish();

  const std::filesystem::path folder(options.out_dir);
  std::filesystem::create_directories(folder);
  write_png(folder / "floor_coverage.png", floor_plan(cell, coverage));
  std::size_t blind = 0, standing = 0;
  for (const int seeing : coverage.cameras_seeing) {
    standing += seeing >= 0 ? 1 : 0;
    blind += seeing >= 0 && seeing < coverage.camera_threshold ? 1 : 0;
  }
  nlohmann::ordered_json json;
  json["cell"] = cell.config.name;
  json["step_m"] = coverage.step_m;
  json["body_radius_m"] = coverage.body_radius_m;
  json["camera_threshold"] = coverage.camera_threshold;
  json["positions"] = standing;
  json["blind_positions"] = blind;
  json["reach_m"] = coverage.reach_m;
  json["reach_positions"] = coverage.reach_positions();
  json["reach_blind_positions"] = coverage.reach_blind_positions();
  json["reach_blind_share"] = coverage.reach_blind_share();
  json["blind_spot_volumes"] = blind_spot_volumes(coverage).size();
  json["picture"] = (folder / "floor_coverage.png").string();
  write_file_atomically(folder / "coverage.json", json.dump(2) + "\n");
  if (options.json) {
    out << json.dump(2) << '\n';
    return;
  }
  out << "floor coverage of " << cell.config.name << ": " << grouped(standing)
      << " positions (every " << fixed(100.0 * coverage.step_m, 0)
      << " cm), a person 0.4-2.0 m tall seen by fewer than " << coverage.camera_threshold
      << " cameras at " << grouped(blind) << "\n  within the robot's reach ("
      << fixed(coverage.reach_m, 2) << " m): " << grouped(coverage.reach_blind_positions())
      << " of " << grouped(coverage.reach_positions()) << " positions blind ("
      << fixed(100.0 * coverage.reach_blind_share(), 1)
      << " %)\n  picture: " << (folder / "floor_coverage.png").string() << "\n";
}

void add_cell_coverage_command(CLI::App& cell, CommandLine& line) {
  const auto coverage = std::make_shared<CellCoverageOptions>();
  CLI::App* coverage_command = cell.add_subcommand(
      "coverage",
      "Where a person can stand that too few cameras see: a floor plan (PNG) of the cameras "
      "seeing each position, and the blind share of the robot's reach");
  coverage_command->add_option("--cell", coverage->cell_path,
                               "Cell file (YAML); without it the built-in default cell");
  coverage_command->add_option("--out", coverage->out_dir, "Folder for the picture and the JSON")
      ->capture_default_str();
  coverage_command->add_option("--step", coverage->step_m, "Floor grid spacing, metres")
      ->capture_default_str()
      ->check(CLI::Range(0.02, 1.0));
  coverage_command->add_flag("--json", coverage->json, "Print one JSON object instead of text");
  coverage_command->callback([=, &line] {
    line.action = [=, &line] { run_cell_coverage(*coverage, line.out, line.err); };
  });
}

}  // namespace safecell

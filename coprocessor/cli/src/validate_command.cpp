#include "safecell/cli/validate_command.hpp"

#include <iostream>
#include <nlohmann/json.hpp>

#include "lut_loading.hpp"
#include "progress_bar.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/lut/model_silhouettes.hpp"
#include "safecell/validation/ground_truth_validation.hpp"
#include "scene_options.hpp"

namespace safecell {

RobotRemoval removal_of(const std::string& text) {
  if (text == "occlusion-aware") return RobotRemoval::kOcclusionAware;
  if (text == "plain") return RobotRemoval::kPlain;
  bad_option("--removal", text, "occlusion-aware or plain");
}

int run_validate(const ValidateOptions& options, std::ostream& out, std::ostream& err) {
  const CellModel cell = load_cell_model(load_cell_file_or_default(options.cell_path));
  const CspaceGrid grid = make_grid(cell.config);
  ValidationOptions validation;
  validation.scenes = options.scenes;
  validation.seed = options.seed;
  validation.configurations_per_scene = options.configurations;
  validation.max_humans = options.humans;
  validation.max_objects = options.objects;
  validation.fusion.camera_threshold = cell.camera_threshold;
  validation.fusion.removal = removal_of(options.removal);
  const CachedLuts luts = cell_luts(cell, grid, options.lut_cache, err);
  const ModelSilhouettes silhouettes(cell, grid, ModelLutOptions{});
  ProgressBar bar(err, &err == &std::cerr && ProgressBar::stderr_is_terminal());
  const ValidationReport report = validate_against_ground_truth(
      cell, grid, luts.set, silhouettes, validation, [&bar](std::size_t done, std::size_t total) {
        bar.update("validating scenes", static_cast<double>(done) / static_cast<double>(total));
      });
  bar.finish();

  nlohmann::ordered_json json;
  json["scenes"] = report.scenes;
  json["objects"] = report.objects;
  json["configs_checked"] = report.configs_checked;
  json["colliding"] = report.colliding;
  json["missed"] = report.missed;
  json["unseen"] = report.unseen;
  json["false_positive_rate"] = report.false_positive_rate;
  json["phantom_cells"] = report.phantom_cells;
  json["forbidden_share"] = report.forbidden_share;
  json["features_ms_p99"] = report.features_ms_p99;
  json["fusion_ms_p99"] = report.fusion_ms_p99;
  json["seed"] = options.seed;
  json["removal"] = options.removal;
  nlohmann::ordered_json cases = nlohmann::ordered_json::array();
  for (const auto& missed : report.missed_cases) {
    cases.push_back({{"scene", missed.scene},
                     {"q_rad", missed.q},
                     {"obstacle", missed.obstacle},
                     {"cameras_seeing", missed.cameras_seeing}});
  }
  json["missed_cases"] = std::move(cases);
  if (options.json) {
    out << json.dump(2) << '\n';
  } else {
    out << "validated " << report.scenes << " scenes (with " << report.objects
        << " boxes among the humans), " << grouped(report.configs_checked)
        << " configurations against FCL ground truth (seed " << options.seed << ", "
        << options.removal << " robot removal)\n"
        << "  colliding " << grouped(report.colliding) << ", missed " << report.missed
        << ", with a human or object fewer than " << cell.camera_threshold << " cameras saw "
        << report.unseen << "\n"
        << "  false positives " << fixed(100.0 * report.false_positive_rate, 1)
        << " % of free configurations, forbidden " << fixed(100.0 * report.forbidden_share, 1)
        << " % of the grid on average, phantom cells " << fixed(report.phantom_cells, 0)
        << " per scene\n"
        << "  p99 per cycle: features " << fixed(report.features_ms_p99, 2) << " ms, fusion "
        << fixed(report.fusion_ms_p99, 2) << " ms\n";
    for (const auto& missed : report.missed_cases) {
      out << "  MISSED: scene " << missed.scene << ", " << missed.obstacle << " (seen by "
          << missed.cameras_seeing << " cameras)\n";
    }
  }
  return report.missed == 0 ? 0 : kExitValidationFailed;
}

}  // namespace safecell

#include "validation_json.hpp"

#include <stdexcept>

#include "safecell/errors/input_error.hpp"

namespace safecell {
namespace {

using Json = nlohmann::ordered_json;

Json stratum_json(const StratumCounts& counts) {
  return {{"configs", counts.configs},
          {"colliding", counts.colliding},
          {"missed", counts.missed},
          {"unseen", counts.unseen},
          {"clear", counts.clear},
          {"clear_forbidden", counts.clear_forbidden},
          {"needless_stop_share", counts.needless_stop_share()}};
}

// The value at `key`, checked: a missing key or one of another type is refused by name.
template <typename T>
T field(const nlohmann::json& json, const std::string& key, const std::string& source) {
  const auto found = json.find(key);
  if (found == json.end()) {
    throw InputError(source + ": key '" + key + "' missing, expected a report of " +
                     "`safecell validate --json`");
  }
  try {
    return found->get<T>();
  } catch (const nlohmann::json::exception&) {
    throw InputError(source + ": key '" + key + "' holds " + found->dump() +
                     ", expected a value of another type");
  }
}

StratumCounts stratum_from(const nlohmann::json& json, const std::string& source) {
  StratumCounts counts;
  counts.configs = field<std::size_t>(json, "configs", source);
  counts.colliding = field<std::size_t>(json, "colliding", source);
  counts.missed = field<std::size_t>(json, "missed", source);
  counts.unseen = field<std::size_t>(json, "unseen", source);
  counts.clear = field<std::size_t>(json, "clear", source);
  counts.clear_forbidden = field<std::size_t>(json, "clear_forbidden", source);
  return counts;
}

}  // namespace

bool same_run(const ValidationRun& a, const ValidationRun& b) {
  const auto same_error = [](const ModelError& x, const ModelError& y) {
    return x.camera_rotation_deg == y.camera_rotation_deg &&
           x.camera_translation_m == y.camera_translation_m && x.focal_error == y.focal_error &&
           x.lens_k1 == y.lens_k1 && x.robot_growth_m == y.robot_growth_m;
  };
  return a.seed == b.seed && a.scenes == b.scenes &&
         a.configurations_per_scene == b.configurations_per_scene &&
         a.camera_threshold == b.camera_threshold && a.removal == b.removal &&
         a.negative_control == b.negative_control && a.padding_m == b.padding_m &&
         a.ball_radius_m == b.ball_radius_m && a.robot_parts == b.robot_parts &&
         a.hidden_votes == b.hidden_votes && a.occlusion_reach == b.occlusion_reach &&
         a.m_max_m == b.m_max_m && a.envelope_subdivision == b.envelope_subdivision &&
         same_error(a.model_error, b.model_error) && a.shard_count == b.shard_count;
}

nlohmann::ordered_json validation_json(const ValidationRun& run, const ValidationReport& report) {
  Json json;
  json["scenes"] = report.scenes;
  json["configs_checked"] = report.configs_checked;
  json["colliding"] = report.colliding;
  json["missed"] = report.missed;
  json["unseen"] = report.unseen;
  Json reasons = Json::object();
  for (std::size_t r = 0; r < kUnseenReasonCount; ++r) {
    reasons[to_string(static_cast<UnseenReason>(r))] = report.unseen_reasons[r];
  }
  json["unseen_reasons"] = std::move(reasons);
  json["unseen_forbidden"] = report.unseen_forbidden;
  json["free"] = report.free;
  json["false_positives"] = report.false_positives;
  json["false_positive_rate"] = report.false_positive_rate();
  json["clear"] = report.clear;
  json["clear_forbidden"] = report.clear_forbidden;
  json["needless_stop_share"] = report.needless_stop_share();
  json["needless_stop_causes"] = {
      {"traced", report.causes.traced},
      {"in_cell", report.causes.in_cell},
      {"visual_hull", report.causes.visual_hull},
      {"envelope", report.causes.envelope},
      {"in_cell_share", report.causes.share(report.causes.in_cell)},
      {"visual_hull_share", report.causes.share(report.causes.visual_hull)},
      {"envelope_share", report.causes.share(report.causes.envelope)}};
  json["bodies"] = report.bodies;
  json["bodies_visible_enough"] = report.bodies_visible_enough;
  json["objects"] = report.objects;
  json["forbidden_share"] = report.forbidden_share();
  json["forbidden_share_sum"] = report.forbidden_share_sum;
  json["scenes_per_stratum"] = report.scenes_per_stratum;
  json["protective_separation"] = {{"scenes", report.separation.scenes},
                                   {"fired", report.separation.fired},
                                   {"slowed", report.separation.slowed},
                                   {"within", report.separation.within},
                                   {"missed", report.separation.missed},
                                   {"far", report.separation.far},
                                   {"needless", report.separation.needless},
                                   {"needless_share", report.separation.needless_share()}};
  Json strata = Json::object();
  for (const auto& [name, counts] : report.strata) strata[name] = stratum_json(counts);
  json["strata"] = std::move(strata);
  json["features_ms_p99"] = report.features_ms_p99;
  json["fusion_ms_p99"] = report.fusion_ms_p99;
  json["seed"] = run.seed;
  json["scenes_in_run"] = run.scenes;
  json["configs_per_scene"] = run.configurations_per_scene;
  json["camera_threshold"] = run.camera_threshold;
  json["removal"] = run.removal;
  json["negative_control"] = run.negative_control;
  json["padding_m"] = run.padding_m;
  json["ball_radius_m"] = run.ball_radius_m;
  json["robot_parts"] = run.robot_parts;
  json["hidden_votes"] = run.hidden_votes;
  json["occlusion_reach"] = run.occlusion_reach;
  json["m_max_m"] = run.m_max_m;
  json["envelope_subdivision"] = run.envelope_subdivision;
  json["model_error"] = {{"camera_rotation_deg", run.model_error.camera_rotation_deg},
                         {"camera_translation_m", run.model_error.camera_translation_m},
                         {"focal_error", run.model_error.focal_error},
                         {"lens_k1", run.model_error.lens_k1},
                         {"robot_growth_m", run.model_error.robot_growth_m}};
  json["shard_count"] = run.shard_count;
  json["shards"] = run.shards;
  Json cases = Json::array();
  for (const auto& missed : report.missed_cases) {
    cases.push_back({{"scene", missed.scene},
                     {"stratum", missed.stratum},
                     {"q_rad", missed.q},
                     {"body", missed.body},
                     {"cameras_visible", missed.cameras_visible}});
  }
  json["missed_cases"] = std::move(cases);
  return json;
}

void read_validation_json(const nlohmann::json& json, const std::string& source, ValidationRun& run,
                          ValidationReport& report) {
  if (!json.is_object()) {
    throw InputError(source + ": not a JSON object, expected a report of " +
                     "`safecell validate --json`");
  }
  report = ValidationReport{};
  report.scenes = field<std::size_t>(json, "scenes", source);
  report.configs_checked = field<std::size_t>(json, "configs_checked", source);
  report.colliding = field<std::size_t>(json, "colliding", source);
  report.missed = field<std::size_t>(json, "missed", source);
  report.unseen = field<std::size_t>(json, "unseen", source);
  const auto reasons = field<nlohmann::json>(json, "unseen_reasons", source);
  for (std::size_t r = 0; r < kUnseenReasonCount; ++r) {
    report.unseen_reasons[r] =
        field<std::size_t>(reasons, to_string(static_cast<UnseenReason>(r)), source);
  }
  report.unseen_forbidden = field<std::size_t>(json, "unseen_forbidden", source);
  report.free = field<std::size_t>(json, "free", source);
  report.false_positives = field<std::size_t>(json, "false_positives", source);
  report.clear = field<std::size_t>(json, "clear", source);
  report.clear_forbidden = field<std::size_t>(json, "clear_forbidden", source);
  const auto causes = field<nlohmann::json>(json, "needless_stop_causes", source);
  report.causes.traced = field<std::size_t>(causes, "traced", source);
  report.causes.in_cell = field<std::size_t>(causes, "in_cell", source);
  report.causes.visual_hull = field<std::size_t>(causes, "visual_hull", source);
  report.causes.envelope = field<std::size_t>(causes, "envelope", source);
  report.bodies = field<std::size_t>(json, "bodies", source);
  report.bodies_visible_enough = field<std::size_t>(json, "bodies_visible_enough", source);
  report.objects = field<std::size_t>(json, "objects", source);
  report.forbidden_share_sum = field<double>(json, "forbidden_share_sum", source);
  report.scenes_per_stratum =
      field<std::map<std::string, std::size_t>>(json, "scenes_per_stratum", source);
  if (json.contains("protective_separation")) {  // reports before it have none
    const auto separation = field<nlohmann::json>(json, "protective_separation", source);
    report.separation.scenes = field<std::size_t>(separation, "scenes", source);
    report.separation.fired = field<std::size_t>(separation, "fired", source);
    // Reports before the reduced speeds have no slow-downs: every firing was a stop.
    report.separation.slowed =
        separation.contains("slowed") ? field<std::size_t>(separation, "slowed", source) : 0;
    report.separation.within = field<std::size_t>(separation, "within", source);
    report.separation.missed = field<std::size_t>(separation, "missed", source);
    report.separation.far = field<std::size_t>(separation, "far", source);
    report.separation.needless = field<std::size_t>(separation, "needless", source);
  }
  const auto strata = field<nlohmann::json>(json, "strata", source);
  if (!strata.is_object()) {
    throw InputError(source + ": key 'strata' holds " + strata.dump() +
                     ", expected an object of strata");
  }
  for (const auto& [name, counts] : strata.items()) {
    std::string where = source;
    where.append(": strata.").append(name);
    report.strata[name] = stratum_from(counts, where);
  }
  report.features_ms_p99 = field<double>(json, "features_ms_p99", source);
  report.fusion_ms_p99 = field<double>(json, "fusion_ms_p99", source);
  const auto missed_cases = field<nlohmann::json>(json, "missed_cases", source);
  for (const auto& missed : missed_cases) {
    report.missed_cases.push_back(MissedCollision{
        field<std::size_t>(missed, "scene", source), field<std::string>(missed, "stratum", source),
        field<std::vector<double>>(missed, "q_rad", source),
        field<std::string>(missed, "body", source), field<int>(missed, "cameras_visible", source)});
  }
  run.seed = field<std::uint64_t>(json, "seed", source);
  run.scenes = field<std::size_t>(json, "scenes_in_run", source);
  run.configurations_per_scene = field<std::size_t>(json, "configs_per_scene", source);
  run.camera_threshold = field<int>(json, "camera_threshold", source);
  run.removal = field<std::string>(json, "removal", source);
  run.negative_control = field<std::string>(json, "negative_control", source);
  run.padding_m = field<double>(json, "padding_m", source);
  run.ball_radius_m = field<double>(json, "ball_radius_m", source);
  // Reports written before the vote per part have no such field: their cameras voted on the
  // whole robot.
  run.robot_parts = json.contains("robot_parts") ? field<std::string>(json, "robot_parts", source)
                                                 : std::string("whole-robot");
  // Reports written before hidden votes had none.
  run.hidden_votes = json.contains("hidden_votes") && field<bool>(json, "hidden_votes", source);
  // Reports written before the reach was an option had the default.
  run.occlusion_reach = json.contains("occlusion_reach")
                            ? field<int>(json, "occlusion_reach", source)
                            : kDefaultOcclusionReach;
  run.m_max_m = field<double>(json, "m_max_m", source);
  // Reports written before sub-cells drew whole cells.
  run.envelope_subdivision = json.contains("envelope_subdivision")
                                 ? field<std::uint32_t>(json, "envelope_subdivision", source)
                                 : 1;
  const auto error = field<nlohmann::json>(json, "model_error", source);
  run.model_error.camera_rotation_deg = field<double>(error, "camera_rotation_deg", source);
  run.model_error.camera_translation_m = field<double>(error, "camera_translation_m", source);
  run.model_error.focal_error = field<double>(error, "focal_error", source);
  run.model_error.lens_k1 = field<double>(error, "lens_k1", source);
  run.model_error.robot_growth_m = field<double>(error, "robot_growth_m", source);
  run.shard_count = field<std::size_t>(json, "shard_count", source);
  run.shards = field<std::vector<std::size_t>>(json, "shards", source);
}

}  // namespace safecell

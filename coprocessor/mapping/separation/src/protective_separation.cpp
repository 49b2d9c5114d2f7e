#include "safecell/separation/protective_separation.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace safecell {

std::vector<SeparationLevel> separation_levels(const SeparationDistanceConfig& distance,
                                               const std::vector<double>& reduced_speeds) {
  const auto at_speed = [&distance](double speed) {
    return distance.approach_speed_m_s * (distance.response_s + speed * distance.stopping_s) +
           distance.intrusion_m;
  };
  std::vector<SeparationLevel> levels{{1.0, at_speed(1.0)}};
  for (const double speed : reduced_speeds) {
    if (!(speed > 0.0 && speed < levels.back().speed)) {
      throw std::invalid_argument("protective separation: reduced speed " + std::to_string(speed) +
                                  ", expected descending fractions of the top speed in (0, 1)");
    }
    levels.push_back({speed, at_speed(speed)});
  }
  return levels;
}

ProtectiveSeparation::ProtectiveSeparation(const CellModel& cell, std::vector<RobotPart> parts,
                                           double ball_radius_m, double widening_m,
                                           std::vector<SeparationLevel> levels,
                                           int camera_threshold)
    : parts_(std::move(parts)),
      levels_(std::move(levels)),
      camera_threshold_(camera_threshold),
      grid_(cell.feature_grid) {
  if (parts_.empty()) throw std::invalid_argument("protective separation: no robot parts");
  if (levels_.empty() || levels_.front().speed != 1.0) {
    throw std::invalid_argument("protective separation: the first level must be full speed");
  }
  for (std::size_t i = 0; i < levels_.size(); ++i) {
    const SeparationLevel& level = levels_[i];
    if (!(level.separation_m >= 0.0 && level.separation_m <= 0.95)) {
      throw std::invalid_argument("protective separation distance must be 0..0.95 m, got " +
                                  std::to_string(level.separation_m));
    }
    if (i > 0 && !(level.speed > 0.0 && level.speed < levels_[i - 1].speed &&
                   level.separation_m <= levels_[i - 1].separation_m)) {
      throw std::invalid_argument(
          "protective separation: levels must slow down towards smaller distances");
    }
  }
  if (camera_threshold < 1 || static_cast<std::size_t>(camera_threshold) > cell.cameras.size()) {
    throw std::invalid_argument("protective separation: a camera threshold of " +
                                std::to_string(camera_threshold) + " for " +
                                std::to_string(cell.cameras.size()) + " cameras");
  }
  grown_.reserve(levels_.size());
  for (const SeparationLevel& level : levels_) {
    grown_.emplace_back(cell, ball_radius_m, widening_m + level.separation_m);
  }
  rects_.resize(grown_.front().camera_count());
}

std::vector<FeatureMask> ProtectiveSeparation::grown_part(std::span<const double> q,
                                                          std::size_t part) const {
  const RobotPart& body_range = parts_.at(part);
  std::vector<FeatureMask> masks(grown_.front().camera_count(), FeatureMask(grid_));
  grown_.front().add_silhouettes(q, masks, body_range.first_body, body_range.end_body);
  return masks;
}

bool ProtectiveSeparation::votes(std::size_t level, std::span<const double> q,
                                 const std::vector<bool>& known,
                                 const std::vector<const FeatureMask*>& obstacles,
                                 SeparationVerdict& verdict) const {
  const ConfigurationSilhouettes& grown = grown_[level];
  const std::size_t camera_count = rects_.size();
  std::vector<std::size_t> cameras;
  for (std::size_t part = 0; part < parts_.size(); ++part) {
    grown.place_balls(q, parts_[part].first_body, parts_[part].end_body, balls_);
    for (std::size_t camera = 0; camera < camera_count; ++camera) {
      rects_[camera].resize(balls_.size());
      grown.projection(camera).feature_rects(balls_, rects_[camera]);
    }
    for (std::size_t ball = 0; ball < balls_.size(); ++ball) {
      cameras.clear();
      for (std::size_t camera = 0; camera < camera_count; ++camera) {
        // Unknown space counts as occupied: an unknown view may hide someone next to the ball.
        const std::optional<FeatureRect>& rect = rects_[camera][ball];
        if (!known[camera] || (rect && obstacles[camera]->any_in_rect(*rect))) {
          cameras.push_back(camera);
        }
      }
      if (cameras.size() >= static_cast<std::size_t>(camera_threshold_)) {
        verdict.within_m = levels_[level].separation_m;
        verdict.part = part;
        verdict.cameras = std::move(cameras);
        return true;
      }
    }
  }
  return false;
}

SeparationVerdict ProtectiveSeparation::check(
    std::span<const double> q, const std::vector<bool>& known,
    const std::vector<const FeatureMask*>& obstacles) const {
  const std::size_t cameras = rects_.size();
  if (known.size() != cameras || obstacles.size() != cameras) {
    throw std::invalid_argument("protective separation: " + std::to_string(known.size()) +
                                " views and " + std::to_string(obstacles.size()) +
                                " obstacle masks for " + std::to_string(cameras) + " cameras");
  }
  for (std::size_t camera = 0; camera < cameras; ++camera) {
    if (!known[camera]) continue;
    const FeatureMask* mask = obstacles[camera];
    if (mask == nullptr || mask->columns() != grid_.columns() || mask->rows() != grid_.rows()) {
      throw std::invalid_argument("protective separation: camera " + std::to_string(camera) +
                                  "'s obstacles are not a mask of the " +
                                  std::to_string(grid_.columns()) + " x " +
                                  std::to_string(grid_.rows()) + " feature grid");
    }
  }
  SeparationVerdict verdict;
  // The distances shrink level by level, so a clear level leaves every later one clear.
  for (std::size_t level = 0; level < levels_.size(); ++level) {
    if (!votes(level, q, known, obstacles, verdict)) {
      verdict.speed_limit = levels_[level].speed;
      verdict.clear_m = levels_[level].separation_m;
      return verdict;
    }
  }
  verdict.speed_limit = 0.0;
  verdict.too_close = true;
  return verdict;
}

std::string describe(const SeparationVerdict& verdict, const ProtectiveSeparation& check,
                     const CellModel& cell) {
  if (verdict.speed_limit >= 1.0) return "no obstacle within the protective separation distance";
  std::ostringstream text;
  text.precision(2);
  text << std::fixed;
  if (verdict.too_close) {
    text << kSeparationStopKind << ": ";
  } else {
    text << "slowed to " << std::lround(verdict.speed_limit * 100.0)
         << " % by the protective separation: an obstacle within ";
  }
  text << verdict.within_m << " m of the robot's " << check.parts().at(verdict.part).name
       << " in camera";
  if (verdict.cameras.size() != 1) text << 's';
  for (std::size_t i = 0; i < verdict.cameras.size(); ++i) {
    text << (i == 0 ? " '" : ", '") << cell.cameras.at(verdict.cameras[i]).name() << '\'';
  }
  return text.str();
}

}  // namespace safecell

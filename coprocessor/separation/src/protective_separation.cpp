#include "safecell/separation/protective_separation.hpp"

#include <sstream>
#include <stdexcept>

namespace safecell {

ProtectiveSeparation::ProtectiveSeparation(const CellModel& cell, std::vector<RobotPart> parts,
                                           double ball_radius_m, double widening_m,
                                           double separation_m, int camera_threshold)
    : parts_(std::move(parts)),
      separation_m_(separation_m),
      camera_threshold_(camera_threshold),
      grid_(cell.feature_grid),
      grown_(cell, ball_radius_m, widening_m + separation_m) {
  if (parts_.empty()) throw std::invalid_argument("protective separation: no robot parts");
  if (!(separation_m >= 0.0 && separation_m <= 0.95)) {
    throw std::invalid_argument("protective separation distance must be 0..0.95 m, got " +
                                std::to_string(separation_m));
  }
  if (camera_threshold < 1 || static_cast<std::size_t>(camera_threshold) > cell.cameras.size()) {
    throw std::invalid_argument("protective separation: a camera threshold of " +
                                std::to_string(camera_threshold) + " for " +
                                std::to_string(cell.cameras.size()) + " cameras");
  }
  scratch_.assign(grown_.camera_count(), FeatureMask(grid_));
}

std::vector<FeatureMask> ProtectiveSeparation::grown_part(std::span<const double> q,
                                                          std::size_t part) const {
  const RobotPart& body_range = parts_.at(part);
  std::vector<FeatureMask> masks(grown_.camera_count(), FeatureMask(grid_));
  grown_.add_silhouettes(q, masks, body_range.first_body, body_range.end_body);
  return masks;
}

SeparationVerdict ProtectiveSeparation::check(
    std::span<const double> q, const std::vector<bool>& known,
    const std::vector<const FeatureMask*>& obstacles) const {
  const std::size_t cameras = grown_.camera_count();
  if (known.size() != cameras || obstacles.size() != cameras) {
    throw std::invalid_argument("protective separation: " + std::to_string(known.size()) +
                                " views and " + std::to_string(obstacles.size()) +
                                " obstacle masks for " + std::to_string(cameras) + " cameras");
  }
  SeparationVerdict verdict;
  for (std::size_t part = 0; part < parts_.size(); ++part) {
    for (FeatureMask& mask : scratch_) mask.clear();
    grown_.add_silhouettes(q, scratch_, parts_[part].first_body, parts_[part].end_body);
    verdict.cameras.clear();
    for (std::size_t camera = 0; camera < cameras; ++camera) {
      // Unknown space counts as occupied: an unknown view may hide someone next to the part.
      if (!known[camera] || scratch_[camera].intersects(*obstacles[camera])) {
        verdict.cameras.push_back(camera);
      }
    }
    if (verdict.cameras.size() >= static_cast<std::size_t>(camera_threshold_)) {
      verdict.too_close = true;
      verdict.part = part;
      return verdict;
    }
  }
  verdict.cameras.clear();
  return verdict;
}

std::string describe(const SeparationVerdict& verdict, const ProtectiveSeparation& check,
                     const CellModel& cell) {
  if (!verdict.too_close) return "no obstacle within the protective separation distance";
  std::ostringstream text;
  text.precision(2);
  text << "an obstacle within the protective separation distance: " << std::fixed
       << check.separation_m() << " m of the robot's " << check.parts().at(verdict.part).name
       << " in camera";
  if (verdict.cameras.size() != 1) text << 's';
  for (std::size_t i = 0; i < verdict.cameras.size(); ++i) {
    text << (i == 0 ? " '" : ", '") << cell.cameras.at(verdict.cameras[i]).name() << '\'';
  }
  return text.str();
}

}  // namespace safecell

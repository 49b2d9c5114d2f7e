#include "safecell/campaign/fault_class.hpp"

#include <array>
#include <utility>

namespace safecell {
namespace {

constexpr std::array<std::pair<FaultClass, const char*>, 16> kNames{{
    {FaultClass::kCorruption, "corruption"},
    {FaultClass::kResealedCorruption, "corruption-resealed"},
    {FaultClass::kRepetition, "repetition"},
    {FaultClass::kReorder, "reorder"},
    {FaultClass::kLoss, "loss"},
    {FaultClass::kInsertion, "insertion"},
    {FaultClass::kForeignSession, "foreign-session"},
    {FaultClass::kDelay, "delay"},
    {FaultClass::kLinkCut, "link-cut"},
    {FaultClass::kWrongFingerprint, "wrong-fingerprint"},
    {FaultClass::kCoprocessorKilled, "coprocessor-killed"},
    {FaultClass::kControllerRestarted, "controller-restarted"},
    {FaultClass::kCameraFrozen, "camera-frozen"},
    {FaultClass::kCameraBlinded, "camera-blinded"},
    {FaultClass::kCameraMoved, "camera-moved"},
    {FaultClass::kCameraUnplugged, "camera-unplugged"},
}};

}  // namespace

const char* to_string(FaultClass fault) {
  for (const auto& [each, name] : kNames) {
    if (each == fault) return name;
  }
  return "unknown";
}

const std::vector<FaultClass>& all_fault_classes() {
  static const std::vector<FaultClass> all = [] {
    std::vector<FaultClass> classes;
    classes.reserve(kNames.size());
    for (const auto& entry : kNames) classes.push_back(entry.first);
    return classes;
  }();
  return all;
}

std::optional<FaultClass> fault_class_named(std::string_view name) {
  for (const auto& [each, each_name] : kNames) {
    if (name == each_name) return each;
  }
  return std::nullopt;
}

FaultSite site_of(FaultClass fault) {
  switch (fault) {
    case FaultClass::kWrongFingerprint:
    case FaultClass::kCoprocessorKilled:
    case FaultClass::kControllerRestarted:
      return FaultSite::kEnds;
    case FaultClass::kCameraFrozen:
    case FaultClass::kCameraBlinded:
    case FaultClass::kCameraMoved:
    case FaultClass::kCameraUnplugged:
      return FaultSite::kCameras;
    default:
      return FaultSite::kLink;
  }
}

bool injected_at_a_rate(FaultClass fault) {
  switch (fault) {
    case FaultClass::kCorruption:
    case FaultClass::kResealedCorruption:
    case FaultClass::kRepetition:
    case FaultClass::kReorder:
    case FaultClass::kLoss:
    case FaultClass::kInsertion:
    case FaultClass::kForeignSession:
      return true;
    default:
      return false;
  }
}

const std::vector<std::string>& expected_causes(FaultClass fault) {
  // Names as the controller's trace writes them (link errors, cycle faults, link blocks, stop
  // request causes). A frame of a stranger fails its CRC before its ids are read: corruption.
  static const std::vector<std::string> watchdog{"no map within the watchdog time", "timeout"};
  static const std::vector<std::string> cameras{"too few healthy cameras", "cameras"};
  static const std::vector<std::string> corruption{"corruption"};
  // Past the CRC: the message does not decode (corruption), or the map it builds is not the
  // sender's (the map hash).
  static const std::vector<std::string> resealed{"corruption", "map hash mismatch",
                                                 "malformed chunk"};
  static const std::vector<std::string> repetition{"repetition"};
  static const std::vector<std::string> reorder{"incorrect sequence", "loss"};
  static const std::vector<std::string> loss{"loss"};
  static const std::vector<std::string> insertion{"insertion", "corruption", "addressing",
                                                  "masquerade"};
  static const std::vector<std::string> masquerade{"masquerade"};
  static const std::vector<std::string> delay{"delay", "no map within the watchdog time"};
  static const std::vector<std::string> refused{"refused"};
  static const std::vector<std::string> restarted{"no session", "no verified map"};
  switch (fault) {
    case FaultClass::kCorruption:
      return corruption;
    case FaultClass::kResealedCorruption:
      return resealed;
    case FaultClass::kRepetition:
      return repetition;
    case FaultClass::kReorder:
      return reorder;
    case FaultClass::kLoss:
      return loss;
    case FaultClass::kInsertion:
      return insertion;
    case FaultClass::kForeignSession:
      return masquerade;
    case FaultClass::kDelay:
      return delay;
    case FaultClass::kLinkCut:
    case FaultClass::kCoprocessorKilled:
      return watchdog;
    case FaultClass::kWrongFingerprint:
      return refused;
    case FaultClass::kControllerRestarted:
      return restarted;
    default:
      return cameras;
  }
}

}  // namespace safecell

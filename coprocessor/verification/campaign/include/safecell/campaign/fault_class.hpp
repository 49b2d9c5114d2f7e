#pragma once
// The fault classes of a fault campaign (../shared/SAFETY.md): what goes wrong, where it is
// injected, and which causes the controller may name when it detects it.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace safecell {

enum class FaultClass {
  // On the link, by the fault-injecting proxy, at a rate while the fault lasts:
  kCorruption,          // bits flipped
  kResealedCorruption,  // payload bits flipped and the CRC made valid again: below the CRC
  kRepetition,          // datagrams sent twice
  kReorder,             // a datagram held back behind the next
  kLoss,                // datagrams dropped
  kInsertion,           // frames of another sender inserted
  kForeignSession,      // valid frames of another session inserted (a masquerade)
  // On the link, all of it while the fault lasts:
  kDelay,    // every datagram held back longer than the maximum data age
  kLinkCut,  // nothing passes
  // The ends:
  kWrongFingerprint,     // the controller commissioned with other LUTs: the session is refused
  kCoprocessorKilled,    // the coprocessor's link falls silent; later a new one (a new session)
  kControllerRestarted,  // safecell-controller killed (SIGKILL) and started again
  // The cameras (enough of them that too few healthy ones are left for the threshold):
  kCameraFrozen,     // the same image again and again
  kCameraBlinded,    // saturated
  kCameraMoved,      // the image shifted: the camera knocked
  kCameraUnplugged,  // no frames
};

// A stable name ("corruption", "camera-frozen", ...).
const char* to_string(FaultClass fault);
// Every class, in the order above.
const std::vector<FaultClass>& all_fault_classes();
std::optional<FaultClass> fault_class_named(std::string_view name);

enum class FaultSite { kLink, kEnds, kCameras };
FaultSite site_of(FaultClass fault);

// Whether the class is injected by the proxy at a rate (its detection latches after a second
// error: SAFETY.md), as opposed to all at once.
bool injected_at_a_rate(FaultClass fault);

// The causes the controller's trace may name for a class (a link error's name, a cycle fault or
// link block), any one of which shows the fault was recognised for what it is.
const std::vector<std::string>& expected_causes(FaultClass fault);

}  // namespace safecell

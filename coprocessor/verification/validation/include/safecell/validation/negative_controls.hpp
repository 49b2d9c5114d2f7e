#pragma once
// Deliberately broken pipelines that `safecell validate` must catch (../shared/VALIDATION.md:
// a check that cannot fail is a defect). Each must end with missed > 0 on a fixed seed; the
// tests make sure they do, and `safecell validate --negative-control NAME` shows it to anyone.
//   empty-masks       every camera's blocked mask is empty: only the static obstacles are
//                     forbidden;
//   dropped-strip     LUT-2 whose entries lose every strip that starts in one band of lines
//                     (the third quarter of each level's lines: a quarter of C-space), read
//                     without its block levels and differences. Sparser damage is not caught
//                     by random scenes: neighbouring pixels and the other cameras cover the same
//                     cells (dropping the largest strip of every entry, every second strip, or
//                     an eighth of the lines left missed at 0 on 60 scenes of the default cell);
//                     the FusionEquivalence test against the dense oracle guards that instead;
//   envelope-removal  robot removal erases every blocked feature cell inside the silhouette of
//                     the robot's whole C-space cell (LUT-1 of the cell), people standing there
//                     included.

#include <optional>
#include <string>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/tables/lut_set.hpp"

namespace safecell {

enum class NegativeControl : std::uint8_t { kNone, kEmptyMasks, kDroppedStrip, kEnvelopeRemoval };

// "none", "empty-masks", "dropped-strip", "envelope-removal".
[[nodiscard]] const char* to_string(NegativeControl control);
[[nodiscard]] std::optional<NegativeControl> negative_control_named(const std::string& name);

// The tables of the dropped-strip control: every camera's LUT-2 entries without the strips that
// start in the dropped band, and no block levels or differences.
[[nodiscard]] LutSet with_strip_dropped(const LutSet& luts, const CspaceGrid& grid);

}  // namespace safecell

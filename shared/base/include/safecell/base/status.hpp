#pragma once
// Status codes returned by freestanding code instead of exceptions.

#include <cstdint>

namespace safecell {

enum class [[nodiscard]] Status : std::uint8_t{
    kOk = 0,
    kInvalidArgument,   // a parameter is NaN, negative, reversed or otherwise meaningless
    kOutOfRange,        // an index, coordinate or angle lies outside the valid domain
    kCapacityExceeded,  // a fixed-capacity container or a fixed limit (such as 8 joints) is full
    kOverflow,          // a derived quantity does not fit its integer type
    kEmpty,             // nothing to take from a container
};

// Stable, human-readable name of a status ("invalid argument", ...). Never returns null.
const char* to_string(Status status) noexcept;

}  // namespace safecell

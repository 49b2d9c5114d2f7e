#include "safecell/errors/input_error.hpp"

namespace safecell {

// Out of line: the class's vtable is emitted here, once.
InputError::~InputError() = default;

}  // namespace safecell

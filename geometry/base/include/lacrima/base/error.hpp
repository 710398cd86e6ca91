#pragma once
// User-facing errors. Every message names what the user can fix: a file, a field, a value.
#include <stdexcept>
#include <string>

namespace lacrima {

// Thrown for bad input (missing or corrupt files, invalid values). The message is complete and
// printed as-is by the command line, which then exits with status 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lacrima

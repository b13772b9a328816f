/// @file
/// @brief The error for bad input: a file or a value the user gave is wrong (exit code 1).
///
/// The message always names the file and the place inside it (line, JSON pointer, frame) and
/// what is wrong, so the command line can print it as is.
#pragma once

#include <stdexcept>
#include <string>

namespace vdfx::io {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace vdfx::io

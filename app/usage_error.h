// A mistake in how the command was called (exit status 2), as opposed to a failure while doing
// what was asked (exit status 1).
#pragma once

#include <stdexcept>

namespace obscura::app {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace obscura::app

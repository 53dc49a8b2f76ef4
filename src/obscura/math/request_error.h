// A value the caller asked for that is malformed or out of range (an option, a keyword argument),
// as opposed to a failure while doing what was asked: the command line exits 2 for it (a usage
// error), Python raises ValueError.
#pragma once

#include "obscura/math/error.h"

namespace obscura {

class RequestError : public Error {
 public:
  using Error::Error;
};

}  // namespace obscura

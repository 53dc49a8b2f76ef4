#include "obscura/math/number_text.h"

#include <cstdio>

namespace obscura {

std::string number_text(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

}  // namespace obscura

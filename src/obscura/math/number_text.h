// Numbers as error messages and reports show them: "-1", "0.5", "39.59775", not "-1.000000".
#pragma once

#include <string>

namespace obscura {

// Up to 10 significant digits, no trailing zeros ("%.10g"); "inf" for infinity.
std::string number_text(double value);

}  // namespace obscura

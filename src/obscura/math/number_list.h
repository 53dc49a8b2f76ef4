// Numbers and lists of numbers in request values (command-line options, Python arguments) ("1/60",
// "0:1/60", "800,800,320,240"), parsed strictly: a malformed value throws RequestError naming the
// option, the expected form and the value.
#pragma once

#include <string>
#include <vector>

namespace obscura {

// A finite number, or a fraction "a/b" (shutter times are written 1/60).
double parse_number(const std::string& text, const std::string& option);

// Exactly `count` numbers separated by `separator`; `form` describes the expected value
// ("OPEN:CLOSE in seconds (0:1/60)").
std::vector<double> parse_list(const std::string& text, char separator, size_t count,
                               const std::string& option, const std::string& form);

// From `min_count` to `max_count` numbers separated by `separator`.
std::vector<double> parse_list(const std::string& text, char separator, size_t min_count,
                               size_t max_count, const std::string& option,
                               const std::string& form);

}  // namespace obscura

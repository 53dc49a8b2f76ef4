// Numbers and lists of numbers in option values ("1/60", "0:1/60", "800,800,320,240"), parsed
// strictly: a malformed value throws UsageError naming the option, the expected form and the
// value.
#pragma once

#include <string>
#include <vector>

namespace obscura::app {

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

}  // namespace obscura::app

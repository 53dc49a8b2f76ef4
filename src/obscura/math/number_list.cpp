#include "obscura/math/number_list.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "obscura/math/error.h"
#include "obscura/math/request_error.h"

namespace obscura {

double parse_number(const std::string& text, const std::string& option) {
  auto fail = [&] { throw RequestError(option + " expects a number; got '" + text + "'"); };
  size_t slash = text.find('/');
  try {
    size_t used = 0;
    if (slash == std::string::npos) {
      double v = std::stod(text, &used);
      if (used != text.size() || !std::isfinite(v)) fail();
      return v;
    }
    std::string numerator = text.substr(0, slash), denominator = text.substr(slash + 1);
    double a = std::stod(numerator, &used);
    if (used != numerator.size()) fail();
    double b = std::stod(denominator, &used);
    if (used != denominator.size() || b == 0 || !std::isfinite(a / b)) fail();
    return a / b;
  } catch (const std::logic_error&) {  // std::invalid_argument, std::out_of_range
    fail();
  }
  return 0;
}

std::vector<double> parse_list(const std::string& text, char separator, size_t min_count,
                               size_t max_count, const std::string& option,
                               const std::string& form) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, separator)) {
    if (values.size() == max_count) break;  // too many: refused below without parsing the rest
    values.push_back(parse_number(item, option));
  }
  if (values.size() < min_count || values.size() > max_count || std::getline(stream, item) ||
      (!text.empty() && text.back() == separator))
    throw RequestError(option + " expects " + form + "; got '" + text + "'");
  return values;
}

std::vector<double> parse_list(const std::string& text, char separator, size_t count,
                               const std::string& option, const std::string& form) {
  return parse_list(text, separator, count, count, option, form);
}

}  // namespace obscura

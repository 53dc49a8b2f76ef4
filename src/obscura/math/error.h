// The project's one error type: what went wrong, where (file, line or JSON path, parameter) and
// what was expected. The command line prints `what()` and exits non-zero.
#pragma once

#include <stdexcept>
#include <string>

namespace obscura {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  // "where: message", e.g. Error("scene.json:12", "unknown key 'fvo'").
  Error(const std::string& where, const std::string& message)
      : std::runtime_error(where + ": " + message), where_(where) {}
  const std::string& where() const { return where_; }

 private:
  std::string where_;
};

}  // namespace obscura

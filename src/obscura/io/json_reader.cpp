#include "obscura/io/json_reader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <sstream>

#include "obscura/math/error.h"

namespace obscura {

namespace {

std::string type_name(const nlohmann::ordered_json& j) {
  return j.type_name();
}

}  // namespace

JsonReader::JsonReader(const nlohmann::ordered_json& value, std::string file, std::string path)
    : value_(value), file_(std::move(file)), path_(std::move(path)) {
  if (!value_.is_object())
    throw Error(file_ + ": " + path_, "expected an object, got " + type_name(value_));
}

std::vector<std::string> JsonReader::keys() const {
  std::vector<std::string> result;
  for (auto it = value_.begin(); it != value_.end(); ++it) result.push_back(it.key());
  return result;
}

const nlohmann::ordered_json& JsonReader::at(const std::string& key) {
  auto it = value_.find(key);
  if (it == value_.end()) throw Error(file_ + ": " + path_of(key), "required key is missing");
  read_.insert(key);
  return *it;
}

JsonReader JsonReader::object(const std::string& key) {
  return JsonReader(at(key), file_, path_of(key));
}

std::vector<JsonReader> JsonReader::objects(const std::string& key) {
  std::vector<JsonReader> result;
  if (!has(key)) return result;
  const nlohmann::ordered_json& array = at(key);
  if (!array.is_array()) fail(key, "expected an array, got " + type_name(array));
  for (size_t i = 0; i < array.size(); ++i)
    result.emplace_back(array[i], file_, path_of(key) + "[" + std::to_string(i) + "]");
  return result;
}

std::string JsonReader::string(const std::string& key) {
  const nlohmann::ordered_json& j = at(key);
  if (!j.is_string()) fail(key, "expected a string, got " + type_name(j));
  return j.get<std::string>();
}

std::string JsonReader::string(const std::string& key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}

double JsonReader::number(const std::string& key) {
  const nlohmann::ordered_json& j = at(key);
  if (!j.is_number()) fail(key, "expected a number, got " + type_name(j));
  double v = j.get<double>();
  if (!std::isfinite(v)) fail(key, "expected a finite number");
  return v;
}

double JsonReader::number(const std::string& key, double fallback) {
  return has(key) ? number(key) : fallback;
}

double JsonReader::number_in(const std::string& key, double fallback, double min, double max) {
  double v = number(key, fallback);
  if (v < min || v > max) {
    std::ostringstream s;
    s << "expected a number in [" << min << ", " << max << "], got " << v;
    fail(key, s.str());
  }
  return v;
}

int JsonReader::integer(const std::string& key, int fallback, int min, int max) {
  if (!has(key)) return fallback;
  const nlohmann::ordered_json& j = at(key);
  if (!j.is_number_integer())
    fail(key, "expected an integer, got " + (j.is_number() ? j.dump() : type_name(j)));
  long long v = j.get<long long>();
  if (v < min || v > max)
    fail(key, "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                  "], got " + std::to_string(v));
  return int(v);
}

bool JsonReader::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const nlohmann::ordered_json& j = at(key);
  if (!j.is_boolean()) fail(key, "expected true or false, got " + type_name(j));
  return j.get<bool>();
}

std::vector<double> JsonReader::numbers(const std::string& key, size_t count) {
  const nlohmann::ordered_json& j = at(key);
  if (!j.is_array() || j.size() != count)
    fail(key, "expected an array of " + std::to_string(count) + " numbers");
  std::vector<double> v;
  for (const nlohmann::ordered_json& e : j) {
    if (!e.is_number()) fail(key, "expected an array of " + std::to_string(count) + " numbers");
    v.push_back(e.get<double>());
    if (!std::isfinite(v.back())) fail(key, "expected finite numbers");
  }
  return v;
}

Vector3d JsonReader::vector3(const std::string& key) {
  std::vector<double> v = numbers(key, 3);
  return {v[0], v[1], v[2]};
}

Vector3d JsonReader::vector3(const std::string& key, Vector3d fallback) {
  return has(key) ? vector3(key) : fallback;
}

Rgb JsonReader::rgb(const std::string& key, Rgb fallback, double max) {
  if (!has(key)) return fallback;
  Rgb c;
  if (at(key).is_number()) {
    c = Rgb(float(number(key)));
  } else {
    std::vector<double> v = numbers(key, 3);
    c = Rgb(float(v[0]), float(v[1]), float(v[2]));
  }
  if (c.r < 0 || c.g < 0 || c.b < 0) fail(key, "colour components must be non-negative");
  if (!(c.r <= max && c.g <= max && c.b <= max)) {
    std::ostringstream s;
    s << "colour components must be at most " << max << "; got " << at(key).dump();
    fail(key, s.str());
  }
  return c;
}

void JsonReader::finish() const {
  for (auto it = value_.begin(); it != value_.end(); ++it)
    if (!read_.count(it.key()))
      throw Error(file_ + ": " + path_of(it.key()),
                  "unknown key '" + it.key() + "' (misspelt, or not valid here)");
}

void JsonReader::fail(const std::string& key, const std::string& message) const {
  throw Error(file_ + ": " + path_of(key), message);
}

namespace {

// "line:column" of a byte offset, counted as editors count them.
std::string line_and_column(const std::string& text, size_t offset) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n')
      ++line, column = 1;
    else
      ++column;
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// No scene is nested deeply; a file that is (hostile or broken) is refused before the parser
// and the readers, whose work and stack grow with the depth, see it.
void check_nesting(const std::string& text, const std::string& name) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw Error(name + ":" + line_and_column(text, i),
                    "JSON nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// The whole file, if it is a regular file of at most kMaxJsonFileBytes. Opened without blocking
// and checked on the open descriptor, so a FIFO, a device (/dev/zero behind a symlink) or a
// directory is refused at once instead of read forever.
std::string read_json_file(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw Error(path, std::string("cannot open the file: ") + std::strerror(errno));
  struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0)
    throw Error(path, std::string("cannot read the file: ") + std::strerror(errno));
  if (!S_ISREG(info.st_mode))
    throw Error(path,
                S_ISDIR(info.st_mode)
                    ? "is a directory; expected a JSON file"
                    : "is not a regular file (a device, pipe or socket); expected a JSON file");
  auto too_large = [&](uintmax_t bytes) {
    return Error(path, "is " + std::to_string(bytes) + " bytes; a JSON file may have at most " +
                           std::to_string(kMaxJsonFileBytes) + " (64 MiB)");
  };
  if (uintmax_t(info.st_size) > kMaxJsonFileBytes) throw too_large(uintmax_t(info.st_size));
  std::string text;
  char buffer[65536];
  for (;;) {
    ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error(path, std::string("cannot read the file: ") + std::strerror(errno));
    if (n == 0) break;
    text.append(buffer, size_t(n));
    if (text.size() > kMaxJsonFileBytes) throw too_large(text.size());  // it grew while read
  }
  return text;
}

}  // namespace

nlohmann::ordered_json parse_json_text(const std::string& text, const std::string& name) {
  if (text.size() > kMaxJsonFileBytes)
    throw Error(
        name, "is " + std::to_string(text.size()) + " bytes; a JSON file may have at most 64 MiB");
  check_nesting(text, name);
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::ordered_json::parse_error& e) {
    // e.byte is one past the offending character.
    size_t offset = std::min<size_t>(e.byte, text.size());
    std::string message = e.what();
    size_t cut = message.find("syntax error");
    throw Error(name + ":" + line_and_column(text, offset > 0 ? offset - 1 : 0),
                "malformed JSON: " + (cut == std::string::npos ? message : message.substr(cut)));
  } catch (const nlohmann::ordered_json::exception& e) {
    // A number too large for a double (1e400) ends here; the message quotes it.
    std::string message = e.what();
    size_t cut = message.find("] ");
    throw Error(
        name, "malformed JSON: " + (cut == std::string::npos ? message : message.substr(cut + 2)));
  }
}

nlohmann::ordered_json parse_json_file(const std::string& path) {
  return parse_json_text(read_json_file(path), path);
}

}  // namespace obscura

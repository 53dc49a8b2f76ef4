#include "obscura/io/json_reader.h"

#include <cmath>
#include <fstream>
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

Rgb JsonReader::rgb(const std::string& key, Rgb fallback) {
  if (!has(key)) return fallback;
  Rgb c;
  if (at(key).is_number()) {
    c = Rgb(float(number(key)));
  } else {
    std::vector<double> v = numbers(key, 3);
    c = Rgb(float(v[0]), float(v[1]), float(v[2]));
  }
  if (c.r < 0 || c.g < 0 || c.b < 0) fail(key, "colour components must be non-negative");
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

nlohmann::ordered_json parse_json_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot open the file (does it exist?)");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    return nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::ordered_json::parse_error& e) {
    // Turn the byte offset into a line and column, as editors show them.
    size_t offset = std::min<size_t>(e.byte, text.size());
    size_t line = 1, column = 1;
    for (size_t i = 0; i + 1 < offset; ++i) {
      if (text[i] == '\n')
        ++line, column = 1;
      else
        ++column;
    }
    std::string message = e.what();
    size_t cut = message.find("syntax error");
    throw Error(path + ":" + std::to_string(line) + ":" + std::to_string(column),
                "malformed JSON: " + (cut == std::string::npos ? message : message.substr(cut)));
  }
}

}  // namespace obscura

// Strict reading of JSON objects for the scene file: every value is type- and range-checked,
// every key that is not read is an error (catches typos), and every message names the file and
// the JSON path ("scene.json: $.objects[2].material.roughness: …").
#pragma once

#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"

namespace obscura {

class JsonReader {
 public:
  // `value` must outlive the reader. Throws when it is not an object.
  JsonReader(const nlohmann::ordered_json& value, std::string file, std::string path);

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  std::string path_of(const std::string& key) const { return path_ + "." + key; }

  bool has(const std::string& key) const { return value_.contains(key); }
  // Every key of the object, in the file's order.
  std::vector<std::string> keys() const;
  // The raw value of a key (marks it as read); throws when it is absent.
  const nlohmann::ordered_json& at(const std::string& key);
  // A nested object.
  JsonReader object(const std::string& key);
  // The elements of an array of objects; an absent key gives none.
  std::vector<JsonReader> objects(const std::string& key);

  std::string string(const std::string& key);  // required
  std::string string(const std::string& key, const std::string& fallback);
  double number(const std::string& key);  // required
  double number(const std::string& key, double fallback);
  // A number within [min, max].
  double number_in(const std::string& key, double fallback, double min, double max);
  int integer(const std::string& key, int fallback, int min, int max);
  bool boolean(const std::string& key, bool fallback);
  Vector3d vector3(const std::string& key, Vector3d fallback);
  Vector3d vector3(const std::string& key);  // required
  // A colour: [r, g, b] with components in [0, max], or one number for grey. Reflectances and
  // albedos pass max = 1 (a surface cannot reflect more light than reaches it).
  Rgb rgb(const std::string& key, Rgb fallback, double max = 1e9);
  std::vector<double> numbers(const std::string& key, size_t count);  // exactly `count`

  // Throws naming the first key that was never read. Call after reading everything.
  void finish() const;
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  const nlohmann::ordered_json& value_;
  std::string file_, path_;
  mutable std::set<std::string> read_;
};

// Limits on a JSON document: its size and how deeply its arrays and objects nest.
inline constexpr uintmax_t kMaxJsonFileBytes = uintmax_t(64) << 20;
inline constexpr int kMaxJsonDepth = 64;

// Parses a JSON document; a syntax error names the file, line and column. The path must name a
// regular file (not a directory, device or pipe) within kMaxJsonFileBytes.
nlohmann::ordered_json parse_json_file(const std::string& path);
// The same for a document in memory; `name` stands for the file in messages.
nlohmann::ordered_json parse_json_text(const std::string& text, const std::string& name);

}  // namespace obscura

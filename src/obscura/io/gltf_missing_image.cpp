#include "obscura/io/gltf_missing_image.h"

#include <tiny_gltf.h>

#include <filesystem>

#include "obscura/io/gltf_loader.h"
#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string percent_decoded(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && hex_digit(text[i + 1]) >= 0 &&
        hex_digit(text[i + 2]) >= 0) {
      out += char(hex_digit(text[i + 1]) * 16 + hex_digit(text[i + 2]));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

// Messages quoted inside a warning stay one readable line.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n') c = ' ';
  if (text.size() > 300) text = text.substr(0, 300) + "…";
  return text;
}

}  // namespace

std::string image_uri_base_name(const std::string& uri) {
  std::string path = percent_decoded(uri);
  size_t slash = path.find_last_of("/\\");
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (name == "." || name == "..") return {};
  return name;
}

std::optional<std::string> find_image_next_to_model(const std::string& uri,
                                                    const std::string& base_dir) {
  std::string name = image_uri_base_name(uri);
  if (name.empty()) return std::nullopt;
  std::filesystem::path candidate = std::filesystem::path(base_dir) / name;
  std::filesystem::path original = std::filesystem::path(base_dir) / percent_decoded(uri);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(candidate, ec)) return std::nullopt;
  if (std::filesystem::equivalent(candidate, original, ec)) return std::nullopt;
  return candidate.string();
}

Texture missing_image_placeholder() {
  // 8 × 8 squares of 16 × 16 texels: crisp under any filter (the rasterizer blends texels).
  constexpr int kSquares = 8, kTexels = 16, kSize = kSquares * kTexels;
  Texture t;
  t.name = "missing-image placeholder";
  t.source = t.name;
  t.width = t.height = kSize;
  t.channels = 3;
  t.texels_8bit.resize(size_t(kSize) * kSize * 3, 0);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      if ((x / kTexels + y / kTexels) % 2 == 0) {
        uint8_t* texel = &t.texels_8bit[size_t(y * kSize + x) * 3];
        texel[0] = 255;  // magenta: red and blue full, green zero
        texel[2] = 255;
      }
  t.encoding = TextureEncoding::kSrgb;
  t.filter = TextureFilter::kNearest;
  return t;
}

void resolve_unusable_gltf_images(const tinygltf::Model& model, std::map<int, Texture>& decoded,
                                  const std::map<int, std::string>& failed, const std::string& file,
                                  const std::string& base_dir, std::vector<std::string>& files_read,
                                  std::vector<std::string>& warnings) {
  for (size_t i = 0; i < model.images.size(); ++i) {
    const int index = int(i);
    if (decoded.count(index)) continue;
    const std::string at = file + ": images[" + std::to_string(i) + "]: ";
    const std::string& uri = model.images[i].uri;
    const bool external = !uri.empty() && uri.rfind("data:", 0) != 0;
    auto reason = failed.find(index);
    std::string why = reason != failed.end() ? reason->second
                      : external             ? "the file does not exist or cannot be read"
                                             : "malformed data URI";
    if (external && reason == failed.end()) {
      const std::string name = image_uri_base_name(uri);
      if (std::optional<std::string> nearby = find_image_next_to_model(uri, base_dir)) {
        try {
          std::vector<unsigned char> bytes = read_gltf_file(*nearby);
          std::string hint = std::filesystem::path(name).extension().string();
          if (!hint.empty()) hint = hint.substr(1);
          decoded[index] = decode_texture(
              bytes, *nearby, model.images[i].mimeType.empty() ? hint : model.images[i].mimeType,
              TextureEncoding::kSrgb, &warnings);
          files_read.push_back(*nearby);
          warnings.push_back(at + "'" + uri + "' was not found; using '" + name +
                             "' found next to the model instead");
          continue;
        } catch (const Error& e) {
          why = "not found; '" + name + "' next to the model cannot be used either: " + e.what();
        }
      } else if (!name.empty() && name != uri) {
        why = "the file does not exist or cannot be read, and there is no '" + name +
              "' next to the model";
      }
    }
    warnings.push_back(at + (external ? "'" + uri + "' " : std::string()) + "cannot be used (" +
                       one_line(why) +
                       "); a base colour texture shows a magenta/black checker instead, other "
                       "textures use their material's factors alone");
  }
}

}  // namespace obscura

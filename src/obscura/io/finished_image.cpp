#include "obscura/io/finished_image.h"

#include <filesystem>
#include <vector>

#include "obscura/io/image_reader.h"
#include "obscura/math/error.h"

namespace obscura {

bool finished_image_exists(const std::string& path, int width, int height) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error) ||
      std::filesystem::file_size(path, error) == 0)
    return false;
  try {
    CheckedImageInput in = CheckedImageInput::open_file(path);
    const ImageHeader& header = in.header();
    if (header.width != width || header.height != height || header.has_attribute("obscura:partial"))
      return false;
    // The header alone does not show a file cut short: every pixel must read back.
    std::vector<float> pixels(size_t(width) * size_t(height) * size_t(header.channels));
    in.read(header.channels, SampleType::kFloat, pixels.data());
    return true;
  } catch (const Error&) {
    return false;  // unreadable: rendered again
  }
}

}  // namespace obscura

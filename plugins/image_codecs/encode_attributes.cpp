#include "encode_attributes.h"

#include "obscura/math/error.h"
#include "sample_conversion.h"

namespace obscura::codecs {

std::vector<unsigned char> request_pixels(const EncodeRequest& request, SampleType type) {
  size_t count = size_t(request.width) * size_t(request.height) * size_t(request.channels);
  std::vector<unsigned char> pixels(count * sample_size(type));
  convert_samples(request.data_type, request.data, type, pixels.data(), count);
  return pixels;
}

void check_request(const EncodeRequest& request, int max_channels) {
  if (request.width <= 0 || request.height <= 0 || request.channels <= 0 ||
      request.channels > max_channels || !request.data || request.data_type == SampleType::kOther)
    throw Error(request.path, "cannot encode an image of " + std::to_string(request.width) + "x" +
                                  std::to_string(request.height) + "x" +
                                  std::to_string(request.channels) + "; expected 1 to " +
                                  std::to_string(max_channels) + " channels");
}

}  // namespace obscura::codecs

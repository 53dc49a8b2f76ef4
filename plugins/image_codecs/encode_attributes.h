// Reading an EncodeRequest's header attributes (image_codecs.h) in the encoders.
#pragma once

#include <string>
#include <vector>

#include "obscura/io/image_codecs.h"

namespace obscura::codecs {

// The text attribute `name`, or nullptr.
inline const std::string* text_attribute(const EncodeRequest& request, const std::string& name) {
  for (const HeaderAttribute& attribute : request.attributes)
    if (attribute.name == name)
      if (const auto* text = std::get_if<std::string>(&attribute.value)) return text;
  return nullptr;
}

// The request's pixels as `type` (converted when data_type differs), all channels.
std::vector<unsigned char> request_pixels(const EncodeRequest& request, SampleType type);

// Checks the request's size and data; throws obscura::Error naming the path.
void check_request(const EncodeRequest& request, int max_channels);

}  // namespace obscura::codecs

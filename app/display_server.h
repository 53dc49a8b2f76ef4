// `obscura render --display-server HOST:PORT`: the finished frame and its AOVs pushed to a running
// tev (the HDR image viewer) over its display-server protocol, as pbrt-v4 and Mitsuba do. tev
// listens on TCP (port 14158 by default); each message is a little-endian uint32 length (the
// whole message's, these four bytes included), a type byte and its fields. Two types are sent:
// "create image" (4: grab focus, name, width, height, channel count, channel names) and "update
// image" (6, v3: grab focus, name, channel count, channel names, x, y, width, height, an int64
// offset and stride per channel, then the floats), in tiles of at most 128 × 128 pixels so that
// no message is large.
#pragma once

#include <string>
#include <vector>

#include "obscura/film/aov_buffers.h"
#include "obscura/film/image.h"

namespace obscura::app {

// The channels pushed: the image's R, G, B, then each AOV's channels as "<aov>.<channel>"
// ("depth.Z", "normal.X", …).
struct DisplayServerImage {
  std::string name;  // what tev lists the image as
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::vector<const Image*> sources;  // per channel: the image it comes from
  std::vector<int> source_channels;   // and which of its channels
};

DisplayServerImage display_image(const std::string& name, const Image& rgb,
                                 const std::vector<AovImage>& aovs);

// Throws UsageError unless `address` is HOST:PORT (checked before rendering).
void check_display_server_address(const std::string& address);

// Connects to HOST:PORT (a name or an IPv4/IPv6 address; [v6]:port), creates the image and sends
// its pixels. Throws obscura::Error naming the address when it is malformed, nothing listens there
// or the connection breaks.
void push_to_display_server(const std::string& address, const DisplayServerImage& image);

}  // namespace obscura::app

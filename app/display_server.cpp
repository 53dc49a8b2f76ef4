#include "display_server.h"

#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>

#include "obscura/math/error.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

constexpr int kTile = 128;
constexpr uint8_t kCreateImage = 4, kUpdateImageV3 = 6;

// One message: its length is filled in by finish(). (A std::string holds the bytes: GCC 12 warns
// falsely of an overflow when a std::vector<uint8_t> grows byte by byte.)
class Message {
 public:
  explicit Message(uint8_t type) {
    put_uint32(0);
    bytes_ += char(type);
  }
  void put_bool(bool v) { bytes_ += char(v ? 1 : 0); }
  void put_string(const std::string& s) {
    bytes_ += s;
    bytes_ += '\0';
  }
  void put_int32(int32_t v) { put_little_endian(uint64_t(uint32_t(v)), 4); }
  void put_uint32(uint32_t v) { put_little_endian(v, 4); }
  void put_int64(int64_t v) { put_little_endian(uint64_t(v), 8); }
  void put_float(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    put_little_endian(bits, 4);
  }
  const std::string& finish() {
    const uint32_t size = uint32_t(bytes_.size());
    for (int i = 0; i < 4; ++i) bytes_[i] = char(uint8_t(size >> (8 * i)));
    return bytes_;
  }

 private:
  void put_little_endian(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) bytes_ += char(uint8_t(v >> (8 * i)));
  }
  std::string bytes_;
};

// "HOST:PORT" or "[V6]:PORT" → host, port; UsageError when malformed.
std::pair<std::string, std::string> split_address(const std::string& address) {
  const size_t colon = address.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == address.size())
    throw UsageError(
        "--display-server: expected HOST:PORT (tev listens on 127.0.0.1:14158); got '" + address +
        "'");
  std::string host = address.substr(0, colon), port = address.substr(colon + 1);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']')
    host = host.substr(1, host.size() - 2);
  if (port.find_first_not_of("0123456789") != std::string::npos || port.size() > 5 ||
      std::stoi(port) < 1 || std::stoi(port) > 65535)
    throw UsageError("--display-server: the port must be 1-65535; got '" + port + "'");
  return {host, port};
}

class Connection {
 public:
  explicit Connection(const std::string& address) : address_(address) {
    const auto [host, port] = split_address(address);
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    if (int e = getaddrinfo(host.c_str(), port.c_str(), &hints, &found); e != 0)
      throw Error("--display-server " + address, gai_strerror(e));
    std::string why = "no address";
    for (addrinfo* a = found; a && fd_ < 0; a = a->ai_next) {
      const int fd = ::socket(a->ai_family, a->ai_socktype, a->ai_protocol);
      if (fd < 0) continue;
      if (::connect(fd, a->ai_addr, a->ai_addrlen) == 0) {
        fd_ = fd;
      } else {
        why = std::strerror(errno);
        ::close(fd);
      }
    }
    freeaddrinfo(found);
    if (fd_ < 0)
      throw Error("--display-server " + address,
                  "cannot connect (" + why + "): is tev running and listening there?");
  }
  ~Connection() {
    if (fd_ >= 0) ::close(fd_);
  }
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  void send(const std::string& bytes) {
    size_t sent = 0;
    while (sent < bytes.size()) {
      const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0)
        throw Error("--display-server " + address_,
                    std::string("the connection broke: ") + std::strerror(errno));
      sent += size_t(n);
    }
  }

 private:
  std::string address_;
  int fd_ = -1;
};

}  // namespace

void check_display_server_address(const std::string& address) {
  split_address(address);
}

DisplayServerImage display_image(const std::string& name, const Image& rgb,
                                 const std::vector<AovImage>& aovs) {
  DisplayServerImage out{.name = name,
                         .width = rgb.width,
                         .height = rgb.height,
                         .channels = {},
                         .sources = {},
                         .source_channels = {}};
  for (int c = 0; c < 3; ++c) {
    out.channels.push_back(std::string(1, "RGB"[c]));
    out.sources.push_back(&rgb);
    out.source_channels.push_back(c);
  }
  for (const AovImage& aov : aovs) {
    for (int c = 0; c < aov.image.channels; ++c) {
      const std::string channel = size_t(c) < aov.image.channel_names.size()
                                      ? aov.image.channel_names[c]
                                      : std::string(1, "RGBA"[std::min(c, 3)]);
      // A one-channel AOV named as its channel ("range", "id") keeps its one name.
      out.channels.push_back(channel == aov.name ? aov.name : aov.name + "." + channel);
      out.sources.push_back(&aov.image);
      out.source_channels.push_back(c);
    }
  }
  return out;
}

void push_to_display_server(const std::string& address, const DisplayServerImage& image) {
  Connection connection(address);
  Message create(kCreateImage);
  create.put_bool(true);  // grab focus: the new render is what the user wants to see
  create.put_string(image.name);
  create.put_int32(image.width);
  create.put_int32(image.height);
  create.put_int32(int32_t(image.channels.size()));
  for (const std::string& channel : image.channels) create.put_string(channel);
  connection.send(create.finish());

  const int channels = int(image.channels.size());
  for (int y0 = 0; y0 < image.height; y0 += kTile) {
    for (int x0 = 0; x0 < image.width; x0 += kTile) {
      const int w = std::min(kTile, image.width - x0), h = std::min(kTile, image.height - y0);
      Message update(kUpdateImageV3);
      update.put_bool(false);
      update.put_string(image.name);
      update.put_int32(channels);
      for (const std::string& channel : image.channels) update.put_string(channel);
      update.put_int32(x0);
      update.put_int32(y0);
      update.put_int32(w);
      update.put_int32(h);
      // Interleaved: channel c of pixel p at p × channels + c.
      for (int c = 0; c < channels; ++c) update.put_int64(c);
      for (int c = 0; c < channels; ++c) update.put_int64(channels);
      for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x)
          for (int c = 0; c < channels; ++c)
            update.put_float(image.sources[c]->at(x, y, image.source_channels[c]));
      connection.send(update.finish());
    }
  }
}

}  // namespace obscura::app

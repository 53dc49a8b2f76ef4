#include "tiff_memory_stream.h"

#include <ctime>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>

namespace obscura::codecs {

namespace {

TiffMemoryStream& stream_of(thandle_t handle) {
  return *static_cast<TiffMemoryStream*>(handle);
}

tmsize_t read_proc(thandle_t handle, void* buffer, tmsize_t size) {
  TiffMemoryStream& s = stream_of(handle);
  if (size <= 0 || s.position >= s.input.size()) return 0;
  size_t n = std::min<uint64_t>(uint64_t(size), s.input.size() - s.position);
  std::memcpy(buffer, s.input.data() + s.position, n);
  s.position += n;
  return tmsize_t(n);
}

tmsize_t write_proc(thandle_t handle, void* buffer, tmsize_t size) {
  TiffMemoryStream& s = stream_of(handle);
  if (!s.output || size < 0) return -1;
  const size_t end = size_t(s.position) + size_t(size);
  const auto* bytes = static_cast<const unsigned char*>(buffer);
  if (s.position == s.output->size()) {
    // Appending, libtiff's usual write: no zero-filling of bytes about to be overwritten.
    s.output->insert(s.output->end(), bytes, bytes + size);
  } else {
    if (end > s.output->size()) s.output->resize(end);
    std::memcpy(s.output->data() + s.position, buffer, size_t(size));
  }
  s.position = end;
  return size;
}

uint64_t size_proc(thandle_t handle) {
  TiffMemoryStream& s = stream_of(handle);
  return s.output ? s.output->size() : s.input.size();
}

toff_t seek_proc(thandle_t handle, toff_t offset, int whence) {
  TiffMemoryStream& s = stream_of(handle);
  uint64_t base = whence == SEEK_CUR ? s.position : whence == SEEK_END ? size_proc(handle) : 0;
  s.position = base + offset;
  return s.position;
}

int close_proc(thandle_t) {
  return 0;
}
int map_proc(thandle_t, void**, toff_t*) {
  return 0;
}
void unmap_proc(thandle_t, void*, toff_t) {}

int on_error(TIFF*, void* user_data, const char* module, const char* format, va_list args) {
  auto& s = *static_cast<TiffMemoryStream*>(user_data);
  char message[512];
  std::vsnprintf(message, sizeof message, format, args);
  if (s.errors.size() < 2048) {
    if (!s.errors.empty()) s.errors += "; ";
    if (module && *module) s.errors += std::string(module) + ": ";
    s.errors += message;
  }
  return 1;  // handled: nothing printed
}

int on_warning(TIFF*, void*, const char*, const char*, va_list) {
  return 1;
}

}  // namespace

TIFF* open_tiff_stream(TiffMemoryStream& stream, const char* mode, const std::string& name) {
  TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
  if (!options) return nullptr;
  TIFFOpenOptionsSetErrorHandlerExtR(options, on_error, &stream);
  TIFFOpenOptionsSetWarningHandlerExtR(options, on_warning, &stream);
  // No single allocation of libtiff's beyond 1 GiB, whatever a hostile directory declares
  // (strip and tile buffers; the pixels themselves are the caller's, size-checked).
  TIFFOpenOptionsSetMaxSingleMemAlloc(options, tmsize_t(1) << 30);
  TIFF* tif = TIFFClientOpenExt(name.c_str(), mode, &stream, read_proc, write_proc, seek_proc,
                                close_proc, size_proc, map_proc, unmap_proc, options);
  TIFFOpenOptionsFree(options);
  return tif;
}

std::string now_as_tiff_date() {
  std::time_t t = std::time(nullptr);
  std::tm local{};
  localtime_r(&t, &local);
  char text[20];
  std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &local);
  return text;
}

}  // namespace obscura::codecs

#include "jpeg_codec.h"

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

// jpeglib.h needs FILE and size_t declared first.
#include <jerror.h>
#include <jpeglib.h>

#include "encode_attributes.h"
#include "obscura/math/error.h"

namespace obscura::codecs {

namespace {

// libjpeg's default error handler prints and calls exit(); this one records the message and
// jumps back to the setjmp of the call that failed, which throws obscura::Error. Warnings are
// kept too: libjpeg decodes a truncated file as grey without an error, which must not pass.
struct JpegErrors {
  jpeg_error_mgr manager{};
  std::jmp_buf jump{};
  char message[JMSG_LENGTH_MAX] = "";
  bool truncated = false;
};

void on_error(j_common_ptr info) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  info->err->format_message(info, errors->message);
  std::longjmp(errors->jump, 1);
}

void on_message(j_common_ptr info, int level) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  if (level < 0 && info->err->msg_code == JWRN_JPEG_EOF) errors->truncated = true;
}

void install(JpegErrors& errors) {
  jpeg_std_error(&errors.manager);
  errors.manager.error_exit = on_error;
  errors.manager.emit_message = on_message;
}

// libjpeg's state, in a member of its own so that it is destroyed even when the decoder's
// constructor throws (a corrupt header): found leaking by fuzz/image_fuzz.cpp.
struct JpegReadState {
  JpegErrors errors;
  jpeg_decompress_struct info{};
  bool created = false;
  ~JpegReadState() {
    if (created) jpeg_destroy_decompress(&info);
  }
};

class JpegDecoder final : public StoredImageDecoder {
 public:
  explicit JpegDecoder(EncodedBytes encoded) : encoded_(std::move(encoded)) {
    install(errors_);
    info_.err = &errors_.manager;
    if (!read_header()) fail();
    header_.format_name = "jpeg";
    header_.format = SampleType::kUint8;
    header_.channel_names = default_channel_names(header_.channels);
    if (!comment_.empty()) header_.text_attributes.emplace_back("ImageDescription", comment_);
  }
  // Whether libjpeg decodes this file's colours itself (not CMYK or YCCK).
  bool supported() const { return supported_; }

 private:
  [[noreturn]] void fail() const {
    throw Error(encoded_.source, std::string("cannot read image as jpeg: ") + errors_.message);
  }

  bool read_header() {
    if (setjmp(errors_.jump)) return false;
    jpeg_create_decompress(&info_);
    state_.created = true;
    jpeg_mem_src(&info_, encoded_.bytes.data(), static_cast<unsigned long>(encoded_.bytes.size()));
    jpeg_save_markers(&info_, JPEG_COM, 0xffff);
    jpeg_read_header(&info_, TRUE);
    if (info_.num_components == 1) {
      info_.out_color_space = JCS_GRAYSCALE;
    } else if (info_.jpeg_color_space == JCS_YCbCr || info_.jpeg_color_space == JCS_RGB) {
      info_.out_color_space = JCS_RGB;
    } else {
      supported_ = false;
    }
    header_.width = int(info_.image_width);
    header_.height = int(info_.image_height);
    header_.channels = info_.out_color_space == JCS_GRAYSCALE ? 1 : 3;
    for (jpeg_saved_marker_ptr m = info_.marker_list; m; m = m->next)
      if (m->marker == JPEG_COM && comment_.empty())
        comment_.assign(reinterpret_cast<const char*>(m->data), m->data_length);
    return true;
  }

  void decode_stored(void* pixels) override {
    if (!decode(static_cast<unsigned char*>(pixels))) fail();
    if (errors_.truncated)
      throw Error(encoded_.source, "cannot read image as jpeg: the file is truncated");
  }

  bool decode(unsigned char* pixels) {
    if (setjmp(errors_.jump)) return false;
    jpeg_start_decompress(&info_);
    const size_t row = size_t(info_.output_width) * size_t(info_.output_components);
    while (info_.output_scanline < info_.output_height) {
      JSAMPROW line = pixels + size_t(info_.output_scanline) * row;
      jpeg_read_scanlines(&info_, &line, 1);
    }
    jpeg_finish_decompress(&info_);
    return true;
  }

  EncodedBytes encoded_;
  JpegReadState state_;
  JpegErrors& errors_ = state_.errors;
  jpeg_decompress_struct& info_ = state_.info;
  bool supported_ = true;
  std::string comment_;
};

// The quality of "Compression" = "jpeg:Q" (OpenImageIO's attribute), else 95.
int quality_of(const EncodeRequest& request) {
  const std::string* compression = text_attribute(request, "Compression");
  if (compression && compression->rfind("jpeg:", 0) == 0) {
    int q = std::atoi(compression->c_str() + 5);
    if (q >= 1 && q <= 100) return q;
  }
  return 95;
}

struct JpegCompressor {
  JpegErrors errors;
  jpeg_compress_struct info{};
  unsigned char* buffer = nullptr;  // jpeg_mem_dest's, malloc'ed by libjpeg
  unsigned long size = 0;
  bool created = false;
  ~JpegCompressor() {
    if (created) jpeg_destroy_compress(&info);
    std::free(buffer);
  }
};

// No object with a destructor lives in this function: libjpeg's errors jump back into it.
bool compress(JpegCompressor& c, const EncodeRequest& request, const unsigned char* pixels,
              int stride_channels, int channels, const std::string* description,
              unsigned char* line) {
  if (setjmp(c.errors.jump)) return false;
  jpeg_create_compress(&c.info);
  c.created = true;
  jpeg_mem_dest(&c.info, &c.buffer, &c.size);
  c.info.image_width = JDIMENSION(request.width);
  c.info.image_height = JDIMENSION(request.height);
  c.info.input_components = channels;
  c.info.in_color_space = channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
  jpeg_set_defaults(&c.info);  // 4:2:0 chroma, as OpenImageIO wrote
  jpeg_set_quality(&c.info, quality_of(request), TRUE);
  c.info.optimize_coding = TRUE;
  jpeg_start_compress(&c.info, TRUE);
  if (description)
    jpeg_write_marker(&c.info, JPEG_COM, reinterpret_cast<const JOCTET*>(description->data()),
                      unsigned(std::min<size_t>(description->size(), 65533)));
  while (c.info.next_scanline < c.info.image_height) {
    const unsigned char* in =
        pixels + size_t(c.info.next_scanline) * size_t(request.width) * size_t(stride_channels);
    for (size_t x = 0; x < size_t(request.width); ++x)
      for (int k = 0; k < channels; ++k)
        line[x * size_t(channels) + size_t(k)] = in[x * size_t(stride_channels) + size_t(k)];
    JSAMPROW row = line;
    jpeg_write_scanlines(&c.info, &row, 1);
  }
  jpeg_finish_compress(&c.info);
  return true;
}

}  // namespace

std::unique_ptr<ImageDecoder> open_jpeg(EncodedBytes encoded) {
  auto decoder = std::make_unique<JpegDecoder>(std::move(encoded));
  if (!decoder->supported()) return nullptr;
  return decoder;
}

std::vector<unsigned char> encode_jpeg(const EncodeRequest& request) {
  check_request(request, 4);
  std::vector<unsigned char> pixels = request_pixels(request, SampleType::kUint8);
  // JPEG holds grey or RGB: alpha is dropped, as OpenImageIO did.
  const int channels = request.channels < 3 ? 1 : 3;
  JpegCompressor c;
  install(c.errors);
  c.info.err = &c.errors.manager;
  std::vector<unsigned char> line(size_t(request.width) * size_t(channels));
  if (!compress(c, request, pixels.data(), request.channels, channels,
                text_attribute(request, "ImageDescription"), line.data()))
    throw Error(request.path, std::string("cannot encode JPEG: ") + c.errors.message);
  return std::vector<unsigned char>(c.buffer, c.buffer + c.size);
}

}  // namespace obscura::codecs

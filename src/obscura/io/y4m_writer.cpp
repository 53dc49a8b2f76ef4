#include "obscura/io/y4m_writer.h"

#include <unistd.h>

#include <filesystem>
#include <vector>

#include "obscura/color/quantize.h"
#include "obscura/math/error.h"

namespace obscura {

Y4mWriter::Y4mWriter(const std::string& path, int width, int height, const Y4mSettings& settings)
    : path_(path), width_(width), height_(height), settings_(settings) {
  if (width <= 0 || height <= 0) throw Error(path, "Y4M frames must have a positive size");
  bool subsampled = settings.subsampling != ChromaSubsampling::k444;
  if (subsampled &&
      (width % 2 != 0 || (settings.subsampling == ChromaSubsampling::k420 && height % 2 != 0)))
    throw Error(path, "Y4M with " + chroma_subsampling_name(settings.subsampling) +
                          " chroma needs even frame sizes; got " + std::to_string(width) + "x" +
                          std::to_string(height));
  if (settings.fps_numerator <= 0 || settings.fps_denominator <= 0)
    throw Error(path, "Y4M frame rate must be positive");
  std::filesystem::path target(path);
  // (Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on `"." + std::string`.)
  std::string name(1, '.');
  name.append(target.filename().string()).append(".tmp-").append(std::to_string(getpid()));
  temporary_ = (target.parent_path() / name).string();
  file_ = std::fopen(temporary_.c_str(), "wb");
  if (!file_) throw Error(path, "cannot open for writing");
  const char* chroma = settings.subsampling == ChromaSubsampling::k444   ? "C444"
                       : settings.subsampling == ChromaSubsampling::k422 ? "C422"
                                                                         : "C420jpeg";
  std::fprintf(file_, "YUV4MPEG2 W%d H%d F%d:%d Ip A1:1 %s XCOLORRANGE=%s\n", width, height,
               settings.fps_numerator, settings.fps_denominator, chroma,
               settings.range == YcbcrRange::kLimited ? "LIMITED" : "FULL");
}

Y4mWriter::~Y4mWriter() {
  if (file_) {
    std::fclose(file_);
    std::remove(temporary_.c_str());
  }
}

void Y4mWriter::write_frame(const DisplayImage& frame) {
  if (!file_) throw Error(path_, "the Y4M writer is closed");
  if (frame.width != width_ || frame.height != height_)
    throw Error(path_, "frame size " + std::to_string(frame.width) + "x" +
                           std::to_string(frame.height) + " differs from the stream's " +
                           std::to_string(width_) + "x" + std::to_string(height_));
  if (frame.bits > 8) throw Error(path_, "Y4M frames are 8-bit; develop with bits ≤ 8");
  std::vector<uint16_t> codes = frame.codes;
  if (frame.bits != 8)
    for (uint16_t& c : codes) c = uint16_t(requantize(c, frame.bits, 8));
  YcbcrPlanes planes = to_ycbcr_planes(codes.data(), width_, height_, frame.channels,
                                       settings_.matrix, settings_.range, settings_.subsampling);
  std::fputs("FRAME\n", file_);
  for (const std::vector<uint8_t>* plane : {&planes.y, &planes.cb, &planes.cr})
    if (std::fwrite(plane->data(), 1, plane->size(), file_) != plane->size())
      throw Error(path_, "write failed");
  ++frames_;
}

void Y4mWriter::close() {
  if (!file_) return;
  bool ok = std::fclose(file_) == 0;
  file_ = nullptr;
  std::error_code ec;
  if (ok) std::filesystem::rename(temporary_, path_, ec);
  if (!ok || ec) {
    std::remove(temporary_.c_str());
    throw Error(path_, "cannot finish the Y4M file");
  }
}

}  // namespace obscura

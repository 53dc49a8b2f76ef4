// A YUV4MPEG2 (.y4m) writer: uncompressed 8-bit Y′CbCr frames that video encoders read directly
// (`ffmpeg -i frames.y4m out.mp4`), so a sequence of renders becomes a video without an
// intermediate image per frame. The file is written to a temporary name and renamed on close().
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "obscura/color/chroma_subsampling.h"
#include "obscura/color/develop.h"
#include "obscura/io/atomic_file.h"

namespace obscura {

struct Y4mSettings {
  int fps_numerator = 24, fps_denominator = 1;
  ChromaSubsampling subsampling = ChromaSubsampling::k420;
  YcbcrMatrix matrix = YcbcrMatrix::kBt709;
  YcbcrRange range = YcbcrRange::kLimited;  // what players assume unless told otherwise
  // Extra X parameters of the stream header (without the X), e.g. "OBSCURA_PARTIAL=interrupted";
  // readers that do not know a tag skip it.
  std::vector<std::string> header_tags;
};

// An X-tag body for a named text value: the name upper-cased with ':' as '_', spaces in the value
// as '_' (a header parameter cannot hold spaces). {"obscura:partial", "time limit"} gives
// "OBSCURA_PARTIAL=time_limit".
std::string y4m_tag(const std::string& name, const std::string& value);

class Y4mWriter {
 public:
  // Preconditions (throw obscura::Error): width, height > 0; even sizes for subsampled chroma;
  // a writable path.
  Y4mWriter(const std::string& path, int width, int height, const Y4mSettings& settings = {});
  ~Y4mWriter();  // an unclosed writer removes its temporary file (see AtomicFile)
  Y4mWriter(const Y4mWriter&) = delete;
  Y4mWriter& operator=(const Y4mWriter&) = delete;

  // Appends one frame of developed 8-bit codes (bits ≤ 8; fewer bits are spread to 8).
  void write_frame(const DisplayImage& frame);
  // Finishes the file and moves it into place.
  void close();
  int frames() const { return frames_; }

 private:
  std::string path_;
  int width_, height_;
  Y4mSettings settings_;
  std::unique_ptr<AtomicFile> file_;  // null once closed
  int frames_ = 0;
};

}  // namespace obscura

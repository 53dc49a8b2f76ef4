#include "obscura/raster/clip_triangles.h"

#include "obscura/color/srgb.h"
#include "obscura/raster/pipeline.h"

namespace obscura::raster {

namespace {

// Passes clip positions through and paints each triangle with its own colour.
struct TriangleColorProgram {
  using Vertex = Vector4f;
  struct Varyings {
    float unused;
  };
  const std::vector<Rgb>* colors;
  VertexOutput<Varyings> vertex(const Vector4f& clip) const { return {clip, {0.f}}; }
  Rgb fragment(const Varyings&, FragmentInfo f) const { return (*colors)[f.primitive]; }
};

Rgb decode_255(Rgb c) {  // PNG stores sRGB-encoded bytes; the film holds linear values
  return {srgb_decode(c.r / 255.f), srgb_decode(c.g / 255.f), srgb_decode(c.b / 255.f)};
}

}  // namespace

ClipTriangleImages draw_clip_triangles(const ClipTriangles& input) {
  std::vector<Rgb> linear;
  for (Rgb c : input.colors) linear.push_back(decode_255(c));
  TriangleColorProgram program{&linear};
  RenderTarget target(input.width, input.height, 1, /*aovs=*/true);
  target.clear(decode_255(input.clear_color), input.clear_depth);
  DrawState state;
  state.depth_func = input.depth_func;
  state.cull = input.cull;
  draw(target, state, program, input.clip);

  // Coverage counts: the same triangles, depth test off, each adding one.
  std::vector<Rgb> ones(input.colors.size(), Rgb(1.f));
  TriangleColorProgram count_program{&ones};
  RenderTarget counts(input.width, input.height);
  counts.clear();
  DrawState count_state;
  count_state.depth_func = DepthFunc::kAlways;
  count_state.depth_write = false;
  count_state.cull = input.cull;
  count_state.blend = BlendMode::kAdd;
  draw(counts, count_state, count_program, input.clip);

  ClipTriangleImages images;
  size_t n = size_t(input.width) * input.height;
  images.ids.resize(n);
  images.count.resize(n);
  for (int y = 0; y < input.height; ++y)
    for (int x = 0; x < input.width; ++x) {
      size_t i = size_t(y) * input.width + x;
      images.ids[i] =
          target.object_id_at(x, y) == kNoObject ? 0 : input.ids[target.primitive_id_at(x, y)];
      images.count[i] = uint32_t(counts.color_at(x, y).r);
    }
  images.color = target.resolve_color();
  images.depth = target.depth_image();
  return images;
}

}  // namespace obscura::raster

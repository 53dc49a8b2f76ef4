// AovBuffers, the one AOV model: sums of samples (the tracer), resolved pixels (the rasterizer,
// another process's part), and the images a frame's parts travel as.
#include "obscura/film/aov_buffers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "obscura/math/error.h"

namespace obscura {
namespace {

TEST(AovBuffers, SamplesAreAveragedAndMissesCountAsBlack) {
  AovBuffers aovs(2, 1);
  aovs.add_sample({0, 0}, true, Rgb(0.5f), {0, 0, 1}, 2.f, 2.5f, 3);
  aovs.add_sample({0, 0}, true, Rgb(0.5f), {0, 0, 1}, 3.f, 3.5f, 3);
  aovs.add_sample({0, 0}, false, Rgb(), {}, 0, 0, 0);
  EXPECT_FLOAT_EQ(aovs.albedo().at(0, 0, 0), 1.f / 3);  // (0.5 + 0.5 + 0) / 3
  EXPECT_FLOAT_EQ(aovs.depth().at(0, 0, 0), 2.5f);      // over the hits only
  EXPECT_FLOAT_EQ(aovs.range().at(0, 0, 0), 3.f);
  EXPECT_FLOAT_EQ(aovs.id().at(0, 0, 0), 3.f);
  EXPECT_FLOAT_EQ(aovs.normal().at(0, 0, 2), 1.f);  // renormalized
  EXPECT_TRUE(std::isinf(aovs.depth().at(1, 0, 0)));
  EXPECT_TRUE(std::isinf(aovs.range().at(1, 0, 0)));
  EXPECT_FLOAT_EQ(aovs.id().at(1, 0, 0), -1.f);
}

TEST(AovBuffers, ResolvedPixelsComeBackUnchanged) {
  AovBuffers aovs(1, 1, false);
  // Not unit length: a resolved normal is not renormalized.
  aovs.set_pixel({0, 0}, Rgb(), {0.f, 0.6f, 0.79f}, 1.25f, 1.5f, 7);
  EXPECT_FLOAT_EQ(aovs.normal().at(0, 0, 2), 0.79f);
  EXPECT_FLOAT_EQ(aovs.depth().at(0, 0, 0), 1.25f);
  EXPECT_FLOAT_EQ(aovs.range().at(0, 0, 0), 1.5f);
  EXPECT_FLOAT_EQ(aovs.id().at(0, 0, 0), 7.f);
  const std::vector<AovImage> images = aovs.images();
  ASSERT_EQ(images.size(), 4u);  // no albedo
  EXPECT_EQ(images[0].name, "normal");
  EXPECT_EQ(images[1].name, "depth");
  EXPECT_EQ(images[1].image.channel_names, std::vector<std::string>{"Z"});
  EXPECT_EQ(images[2].name, "range");
  EXPECT_EQ(images[2].image.channel_names, std::vector<std::string>{"range"});
  EXPECT_EQ(images[3].name, "id");
}

TEST(AovBuffers, ImagesRoundTripBitForBit) {
  AovBuffers aovs(3, 2);
  aovs.add_sample({0, 0}, true, Rgb(0.3f, 0.2f, 0.1f), {0.1f, 0.2f, 0.97f}, 1.7f, 1.8f, 4);
  aovs.add_sample({0, 0}, true, Rgb(0.1f, 0.7f, 0.2f), {0.3f, 0.1f, 0.95f}, 1.9f, 2.1f, 5);
  aovs.add_sample({2, 1}, true, Rgb(0.9f), {1, 0, 0}, 0.3f, 0.4f, 1);
  const std::vector<AovImage> images = aovs.images();
  ASSERT_EQ(images.size(), 5u);
  const std::vector<AovImage> again = AovBuffers::from_images(images).images();
  ASSERT_EQ(again.size(), images.size());
  for (size_t i = 0; i < images.size(); ++i) {
    EXPECT_EQ(again[i].name, images[i].name);
    for (size_t k = 0; k < images[i].image.data.size(); ++k) {
      const float a = images[i].image.data[k], b = again[i].image.data[k];
      EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << images[i].name << " " << k;
    }
  }
}

TEST(AovBuffers, MisshapedImagesAreRefused) {
  AovBuffers aovs(2, 2);
  std::vector<AovImage> images = aovs.images();
  images.pop_back();  // no id
  EXPECT_THROW(AovBuffers::from_images(images), Error);
  images = aovs.images();
  images[1].image = Image(2, 2, 1);  // a one-channel normal
  EXPECT_THROW(AovBuffers::from_images(images), Error);
  images = aovs.images();
  images[2].image = Image(3, 2, 1);  // depth of another size
  EXPECT_THROW(AovBuffers::from_images(images), Error);
  images = aovs.images();
  images.erase(images.begin() + 3);  // no range (a part written before range existed)
  EXPECT_THROW(AovBuffers::from_images(images), Error);
  images = aovs.images();
  images.push_back({"position", Image(2, 2, 3)});
  EXPECT_THROW(AovBuffers::from_images(images), Error);
}

TEST(AovBuffers, IdsThatNoRendererWritesAreRefused) {
  // A shard file's id image is floats: values beyond int32 (found by the shard fuzzer),
  // fractions, NaN and ids below −1 cannot be mesh indices.
  const AovBuffers aovs(2, 1);
  for (const float bad : {3.0e9f, -3.0e9f, 2.5f, -2.0f, std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity(), 16777218.0f}) {
    std::vector<AovImage> images = aovs.images();
    images.back().image.data[1] = bad;
    EXPECT_THROW(AovBuffers::from_images(images), Error) << bad;
  }
  std::vector<AovImage> images = aovs.images();
  images.back().image.data[0] = 16777216.0f;
  images.back().image.data[1] = -1.0f;
  const Image ids = AovBuffers::from_images(images).id();
  EXPECT_EQ(ids.data[0], 16777216.0f);
  EXPECT_EQ(ids.data[1], -1.0f);
}

}  // namespace
}  // namespace obscura

// The fill rule: exact coverage of pixel centres, the top-left rule as the conformance format
// states it, and watertight meshes (every pixel written exactly once).
#include "obscura/raster/fill_rule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "raster/raster_test_util.h"

namespace obscura::raster {
namespace {

using test::classify;
using test::coverage_counts;
using test::pixel_to_clip;

constexpr int kW = 64, kH = 64;

void add_triangle(std::vector<Vector4f>& clip, double ax, double ay, double bx, double by,
                  double cx, double cy) {
  clip.push_back(pixel_to_clip(ax, ay, kW, kH));
  clip.push_back(pixel_to_clip(bx, by, kW, kH));
  clip.push_back(pixel_to_clip(cx, cy, kW, kH));
}

TEST(FillRule, SnapsToNearest256thOfAPixel) {
  EXPECT_EQ(snap_to_subpixel(1.0), 256);
  EXPECT_EQ(snap_to_subpixel(1.0 + 1.0 / 512), 257);  // a tie rounds up
  EXPECT_EQ(snap_to_subpixel(1.0 + 1.0 / 513), 256);
  EXPECT_EQ(snap_to_subpixel(-0.5), -128);
}

TEST(FillRule, CentreOnHorizontalEdgeBelongsToTheTriangleBelow) {
  // Two triangles sharing the horizontal line y = 10.5, which passes through pixel centres.
  std::vector<Vector4f> upper, lower;
  add_triangle(upper, 4.2, 3.1, 20.7, 10.5, 4.2, 10.5);
  add_triangle(lower, 4.2, 10.5, 20.7, 10.5, 4.2, 17.3);
  std::vector<int> up = coverage_counts(kW, kH, upper), down = coverage_counts(kW, kH, lower);
  for (int x = 5; x < 20; ++x) {
    EXPECT_EQ(up[10 * kW + x], 0) << "x=" << x;    // the bottom edge of the upper triangle
    EXPECT_EQ(down[10 * kW + x], 1) << "x=" << x;  // the top edge of the lower one
  }
}

TEST(FillRule, CentreOnOtherEdgeBelongsToTheTriangleOnItsRight) {
  // A vertical edge x = 30.5 and a sloped edge through centres (30.5, 20.5) … (40.5, 40.5).
  std::vector<Vector4f> left, right, sloped_left, sloped_right;
  add_triangle(left, 30.5, 5.2, 30.5, 25.9, 21.3, 15.1);
  add_triangle(right, 30.5, 5.2, 39.8, 15.1, 30.5, 25.9);
  add_triangle(sloped_left, 30.5, 20.5, 40.5, 40.5, 25.0, 40.5);
  add_triangle(sloped_right, 30.5, 20.5, 50.0, 20.5, 40.5, 40.5);
  std::vector<int> l = coverage_counts(kW, kH, left), r = coverage_counts(kW, kH, right);
  for (int y = 6; y < 25; ++y) {
    EXPECT_EQ(l[y * kW + 30], 0) << "y=" << y;
    EXPECT_EQ(r[y * kW + 30], 1) << "y=" << y;
  }
  std::vector<int> sl = coverage_counts(kW, kH, sloped_left),
                   sr = coverage_counts(kW, kH, sloped_right);
  // The shared edge is the line Y = 2X − 40.5 (X, Y in pixels), through centres (x + ½, 2x − 39½).
  for (int k = 2; k < 10; k += 2) {
    int x = 30 + k / 2, y = 20 + k;
    EXPECT_EQ(sl[y * kW + x], 0) << x << "," << y;
    EXPECT_EQ(sr[y * kW + x], 1) << x << "," << y;
  }
}

TEST(FillRule, RectangleWithCornersOnCentresKeepsTopAndLeftEdges) {
  // Corners at centres (2.5, 2.5) and (6.5, 5.5), split along either diagonal, either winding.
  for (int split = 0; split < 2; ++split)
    for (int winding = 0; winding < 2; ++winding) {
      std::vector<Vector4f> clip;
      double x0 = 2.5, y0 = 2.5, x1 = 6.5, y1 = 5.5;
      if (split == 0) {
        add_triangle(clip, x0, y0, x1, y0, x1, y1);
        add_triangle(clip, x0, y0, x1, y1, x0, y1);
      } else {
        add_triangle(clip, x1, y0, x1, y1, x0, y1);
        add_triangle(clip, x0, y0, x1, y0, x0, y1);
      }
      if (winding) std::swap(clip[1], clip[2]), std::swap(clip[4], clip[5]);
      std::vector<int> counts = coverage_counts(kW, kH, clip);
      for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x) {
          int expected = (x >= 2 && x <= 5 && y >= 2 && y <= 4) ? 1 : 0;
          EXPECT_EQ(counts[y * kW + x], expected) << x << "," << y << " split " << split;
        }
    }
}

// A jittered grid mesh covering more than the whole image, vertices at odd 1/256 offsets.
TEST(FillRule, ClosedMeshWritesEveryPixelExactlyOnce) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> jitter(-300, 300);
  const int n = 9;
  const double step = 80.0 / (n - 1);
  double px[n][n], py[n][n];
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      bool border = i == 0 || j == 0 || i == n - 1 || j == n - 1;
      px[j][i] = -8 + i * step + (border ? 0 : (2 * jitter(rng) + 1) / 256.0);
      py[j][i] = -8 + j * step + (border ? 0 : (2 * jitter(rng) + 1) / 256.0);
    }
  std::vector<Vector4f> clip;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      // Alternate the diagonal and the winding so that both orientations of shared edges occur.
      if ((i + j) % 2) {
        add_triangle(clip, px[j][i], py[j][i], px[j][i + 1], py[j][i + 1], px[j + 1][i + 1],
                     py[j + 1][i + 1]);
        add_triangle(clip, px[j][i], py[j][i], px[j + 1][i], py[j + 1][i], px[j + 1][i + 1],
                     py[j + 1][i + 1]);
      } else {
        add_triangle(clip, px[j][i + 1], py[j][i + 1], px[j + 1][i], py[j + 1][i], px[j][i],
                     py[j][i]);
        add_triangle(clip, px[j][i + 1], py[j][i + 1], px[j + 1][i + 1], py[j + 1][i + 1],
                     px[j + 1][i], py[j + 1][i]);
      }
    }
  std::vector<int> counts = coverage_counts(kW, kH, clip);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) ASSERT_EQ(counts[y * kW + x], 1) << x << "," << y;
}

// A fan of 13 triangles around a shared centre: inside the polygon exactly once, outside never.
TEST(FillRule, FanSharingACentreVertexIsWatertight) {
  const double cx = 31.0 + 77 / 256.0, cy = 30.0 + 129 / 256.0, radius = 25;
  const int n = 13;
  std::vector<std::array<double, 2>> rim;
  for (int i = 0; i < n; ++i) {
    double a = 2 * M_PI * i / n + 0.1;
    // Snapped to odd 1/256 offsets so that the test's reference sees the same vertices.
    rim.push_back({(2 * std::floor((cx + radius * std::cos(a)) * 128) + 1) / 256,
                   (2 * std::floor((cy + radius * std::sin(a)) * 128) + 1) / 256});
  }
  std::vector<Vector4f> clip;
  for (int i = 0; i < n; ++i) {
    const auto& a = rim[i];
    const auto& b = rim[(i + 1) % n];
    add_triangle(clip, cx, cy, a[0], a[1], b[0], b[1]);
  }
  std::vector<int> counts = coverage_counts(kW, kH, clip);
  int inside = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      int count = counts[y * kW + x];
      ASSERT_LE(count, 1) << x << "," << y;
      // Reference: the convex polygon's own edges, in double.
      int sign = 1;
      for (int i = 0; i < n; ++i) {
        const auto& a = rim[i];
        const auto& b = rim[(i + 1) % n];
        double d = test::orient(a[0], a[1], b[0], b[1], x + 0.5, y + 0.5);
        if (d < 0) sign = -1;
        if (d == 0 && sign == 1) sign = 0;
      }
      if (sign == 1) {
        EXPECT_EQ(count, 1) << x << "," << y;
        ++inside;
      } else if (sign == -1) {
        EXPECT_EQ(count, 0) << x << "," << y;
      }
    }
  EXPECT_GT(inside, 1500);  // about π·25² ≈ 1963 pixels
}

TEST(FillRule, SliversCoverExactlyTheCentresInside) {
  std::vector<Vector4f> clip;
  // A long needle 0.3 pixels wide, and a triangle too small to contain any centre.
  double a[2] = {3.1, 4.27}, b[2] = {60.2, 50.9}, c[2] = {60.5, 50.9};
  add_triangle(clip, a[0], a[1], b[0], b[1], c[0], c[1]);
  add_triangle(clip, 40.6, 10.6, 40.9, 10.6, 40.7, 10.9);
  std::vector<int> counts = coverage_counts(kW, kH, clip);
  int covered = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      double sa[2] = {std::round(a[0] * 256) / 256, std::round(a[1] * 256) / 256};
      double sb[2] = {std::round(b[0] * 256) / 256, std::round(b[1] * 256) / 256};
      double sc[2] = {std::round(c[0] * 256) / 256, std::round(c[1] * 256) / 256};
      int inside = classify(sa, sb, sc, x + 0.5, y + 0.5);
      if (inside != 0) {
        EXPECT_EQ(counts[y * kW + x], inside > 0 ? 1 : 0) << x << "," << y;
      }
      covered += counts[y * kW + x];
    }
  EXPECT_GT(covered, 5);
}

TEST(FillRule, PartlyOffScreenAndBeyondTheGuardBand) {
  // One triangle reaching thousands of pixels outside, one millions (clipped to the guard band).
  for (double reach : {5000.0, 3e7}) {
    double a[2] = {-reach, 20.25}, b[2] = {50.75, -reach * 0.5}, c[2] = {40.5, 61.25};
    std::vector<Vector4f> clip;
    add_triangle(clip, a[0], a[1], b[0], b[1], c[0], c[1]);
    std::vector<int> counts = coverage_counts(kW, kH, clip);
    int mismatches = 0, covered = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        int inside = classify(a, b, c, x + 0.5, y + 0.5);
        if (inside != 0) mismatches += counts[y * kW + x] != (inside > 0 ? 1 : 0);
        covered += counts[y * kW + x];
      }
    EXPECT_EQ(mismatches, 0) << "reach " << reach;
    EXPECT_GT(covered, 500);
  }
}

TEST(FillRule, ZeroAreaTrianglesDrawNothing) {
  std::vector<Vector4f> clip;
  add_triangle(clip, 1.5, 1.5, 30.5, 30.5, 60.5, 60.5);  // collinear, through centres
  add_triangle(clip, 10.5, 5.5, 10.5, 5.5, 40.5, 20.5);  // two equal vertices
  std::vector<int> counts = coverage_counts(kW, kH, clip);
  for (int c : counts) ASSERT_EQ(c, 0);
}

}  // namespace
}  // namespace obscura::raster

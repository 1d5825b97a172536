// guDrawTriangleWithClip against grDrawTriangle (which only has the scissor of the clip window):
// coverage and Gouraud colour of a triangle crossing every side of the window, a triangle inside
// the window (bit-identical), and triangles outside it (nothing drawn, no error).
#include "glide_window.h"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr int kClipWidth = 64;  // GlideWindowTest's window
constexpr int kClipHeight = 64;
constexpr std::size_t kClipPixels = static_cast<std::size_t>(kClipWidth) * kClipHeight;

// The clip window, max exclusive: 32x32 pixels.
constexpr int kMinX = 16, kMinY = 12, kMaxX = 48, kMaxY = 44;
constexpr int kWindowPixels = (kMaxX - kMinX) * (kMaxY - kMinY);

bool in_window(int x, int y) { return x >= kMinX && x < kMaxX && y >= kMinY && y < kMaxY; }

std::string clip_hex(unsigned value) {
  std::ostringstream s;
  s << "0x" << std::hex << std::uppercase << std::setw(4) << std::setfill('0') << value;
  return s.str();
}

std::string rgb565(FxU16 p) {
  return "(" + std::to_string(red5(p)) + "," + std::to_string(green6(p)) + "," +
         std::to_string(blue5(p)) + ")";
}

GrVertex at(float x, float y, float r, float g, float b) {
  GrVertex v{};
  v.oow = 1.0f;
  v.x = x, v.y = y;
  v.r = r, v.g = g, v.b = b, v.a = 255.0f;
  return v;
}

// A triangle that crosses all four sides of the window: A is left of it, B above it, C below and
// right of it. Edge AB crosses the left and top sides, BC the top and right, CA the bottom and
// left. Every channel of the colour changes by several levels per pixel.
const GrVertex kCrossA = at(8.0f, 28.0f, 250.0f, 20.0f, 130.0f);
const GrVertex kCrossB = at(36.0f, 2.0f, 20.0f, 240.0f, 30.0f);
const GrVertex kCrossC = at(60.0f, 58.0f, 120.0f, 60.0f, 250.0f);

class ClipTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    grDitherMode(GR_DITHER_DISABLE);
    grClipWindow(kMinX, kMinY, kMaxX, kMaxY);
    expect_no_error();
  }

  static void flat_white() {
    grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                   GR_COMBINE_OTHER_NONE, FXFALSE);
    grConstantColorValue(0xFFFFFFFFu);
  }

  static void gouraud() {
    grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED,
                   GR_COMBINE_OTHER_NONE, FXFALSE);
  }

  static void put_background(std::vector<FxU16> &words) {
    ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, kClipWidth, kClipHeight, kClipWidth * 2,
                                 words.data()))
        << glideShimGetLastErrorMessage();
  }

  // The frame after drawing a, b, c over `background` with guDrawTriangleWithClip (clipped) or
  // grDrawTriangle (scissored only).
  std::vector<FxU16> render(std::vector<FxU16> &background, bool clipped, const GrVertex &a,
                            const GrVertex &b, const GrVertex &c) {
    put_background(background);
    if (clipped) {
      guDrawTriangleWithClip(&a, &b, &c);
    } else {
      grDrawTriangle(&a, &b, &c);
    }
    return read_buffer();
  }
};

TEST_F(ClipTest, CrossingTriangleStaysInsideAndMatchesScissoredCoverage) {
  // Random background without 0xFFFF, so the white triangle is told apart from it.
  std::mt19937 random(3001);
  std::uniform_int_distribution<int> word(0, 0xFFFE);
  std::vector<FxU16> background(kClipPixels);
  for (FxU16 &w : background) w = static_cast<FxU16>(word(random));
  flat_white();
  const std::vector<FxU16> clipped = render(background, true, kCrossA, kCrossB, kCrossC);
  const std::vector<FxU16> scissored = render(background, false, kCrossA, kCrossB, kCrossC);
  expect_no_error();

  int changed_outside = 0, covered_clipped = 0, covered_scissored = 0, disagree = 0;
  std::ostringstream where;
  for (int y = 0; y < kClipHeight; ++y) {
    for (int x = 0; x < kClipWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kClipWidth + x);
      if (!in_window(x, y)) {
        if (clipped[i] != background[i] && changed_outside++ < 3) {
          ADD_FAILURE() << "clipped draw changed (" << x << "," << y << ") outside the window "
                        << "from " << clip_hex(background[i]) << " to " << clip_hex(clipped[i]);
        }
        continue;
      }
      const bool in_clipped = clipped[i] == 0xFFFF, in_scissored = scissored[i] == 0xFFFF;
      covered_clipped += in_clipped;
      covered_scissored += in_scissored;
      if (in_clipped != in_scissored && disagree++ < 8) {
        where << " (" << x << "," << y << ": " << (in_clipped ? "clipped only" : "scissored only")
              << ")";
      }
    }
  }
  EXPECT_EQ(changed_outside, 0) << "pixels outside the clip window changed";
  // The triangle covers most of the window (about 800 of its 1024 pixels), so the comparison
  // below is not vacuous.
  EXPECT_GT(covered_scissored, kWindowPixels / 2) << "the scissored triangle covers too little";
  EXPECT_GT(covered_clipped, kWindowPixels / 2) << "the clipped triangle covers too little";
  // Tolerance: 1% of the window's pixels may differ. The clipped fan's new vertices (where the
  // edges meet the window's sides) are re-snapped to 1/16 pixel, which moves a clipped edge by
  // up to 1/32 pixel, so a pixel centre that close to an original edge may change side.
  EXPECT_LE(disagree, kWindowPixels / 100)
      << disagree << " of " << kWindowPixels << " window pixels differ in coverage (clipped "
      << covered_clipped << ", scissored " << covered_scissored << "); first:" << where.str();
}

TEST_F(ClipTest, TriangleInsideTheWindowIsDrawnBitIdentically) {
  // Fractional vertices (snapped to 1/16 by both paths) and Gouraud colour, all inside.
  gouraud();
  const GrVertex a = at(17.3f, 13.9f, 255.0f, 0.0f, 37.0f);
  const GrVertex b = at(46.7f, 20.2f, 3.0f, 201.0f, 90.0f);
  const GrVertex c = at(24.55f, 43.4f, 140.0f, 77.0f, 255.0f);
  std::vector<FxU16> background(kClipPixels, 0x0000);
  const std::vector<FxU16> clipped = render(background, true, a, b, c);
  const std::vector<FxU16> direct = render(background, false, a, b, c);
  expect_no_error();
  int covered = 0, differ = 0;
  for (std::size_t i = 0; i < kClipPixels; ++i) {
    covered += direct[i] != 0;
    if (clipped[i] != direct[i] && differ++ < 5) {
      ADD_FAILURE() << "pixel (" << i % kClipWidth << "," << i / kClipWidth << "): guDrawTriangleWithClip wrote "
                    << rgb565(clipped[i]) << ", grDrawTriangle " << rgb565(direct[i]);
    }
  }
  EXPECT_EQ(differ, 0) << "pixels that differ between the two draws of an inside triangle";
  EXPECT_GT(covered, 300) << "the triangle should cover about 450 pixels";
}

// The exact Gouraud colour of the triangle a, b, c at a point: screen-linear, as the iterators.
double plane_value(const GrVertex &a, const GrVertex &b, const GrVertex &c, float GrVertex::*field,
                   double x, double y) {
  const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  const double la = ((b.x - x) * (c.y - y) - (c.x - x) * (b.y - y)) / area;
  const double lb = ((c.x - x) * (a.y - y) - (a.x - x) * (c.y - y)) / area;
  const double lc = 1.0 - la - lb;
  return la * a.*field + lb * b.*field + lc * c.*field;
}

// True when a 565 channel `level` (of `bits` bits) is the truncation of some 8-bit value within
// `tolerance` of `exact`.
bool truncation_within(int level, int bits, double exact, double tolerance) {
  const int shift = 8 - bits;
  const double low = level << shift, high = ((level + 1) << shift) - 1;
  return high >= exact - tolerance && low <= exact + tolerance;
}

TEST_F(ClipTest, GouraudColourSurvivesClipping) {
  // Black background; every vertex channel is at least 20, so a covered pixel is never 0.
  gouraud();
  std::vector<FxU16> background(kClipPixels, 0x0000);
  const std::vector<FxU16> clipped = render(background, true, kCrossA, kCrossB, kCrossC);
  const std::vector<FxU16> scissored = render(background, false, kCrossA, kCrossB, kCrossC);
  expect_no_error();
  // Tolerance 2 levels of 255 per channel (the clipped vertices' colours are interpolated in
  // float at re-snapped positions: a 1/32-pixel shift moves a colour by under 0.3 levels here).
  // Against the unclipped frame this means the two 565 levels are equal or adjacent (two 8-bit
  // values 2 apart may truncate either side of a 565 step); against the exact plane of the
  // unclipped triangle the clipped level must be the truncation of a value within 2 levels.
  int compared = 0, bad = 0;
  for (int y = kMinY; y < kMaxY; ++y) {
    for (int x = kMinX; x < kMaxX; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kClipWidth + x);
      if (clipped[i] == 0 || scissored[i] == 0) continue;
      ++compared;
      const FxU16 got = clipped[i], ref = scissored[i];
      const double cx = x + 0.5, cy = y + 0.5;
      const double r = plane_value(kCrossA, kCrossB, kCrossC, &GrVertex::r, cx, cy);
      const double g = plane_value(kCrossA, kCrossB, kCrossC, &GrVertex::g, cx, cy);
      const double b = plane_value(kCrossA, kCrossB, kCrossC, &GrVertex::b, cx, cy);
      const bool near_reference = std::abs(red5(got) - red5(ref)) <= 1 &&
                                  std::abs(green6(got) - green6(ref)) <= 1 &&
                                  std::abs(blue5(got) - blue5(ref)) <= 1;
      const bool near_exact = truncation_within(red5(got), 5, r, 2.0) &&
                              truncation_within(green6(got), 6, g, 2.0) &&
                              truncation_within(blue5(got), 5, b, 2.0);
      if ((!near_reference || !near_exact) && bad++ < 5) {
        ADD_FAILURE() << "pixel (" << x << "," << y << "): clipped 565 " << rgb565(got)
                      << ", unclipped " << rgb565(ref) << ", exact colour (" << r << "," << g
                      << "," << b << ")";
      }
    }
  }
  EXPECT_EQ(bad, 0) << "of " << compared << " pixels covered by both draws";
  EXPECT_GT(compared, kWindowPixels / 2) << "too few pixels covered by both draws to compare";
}

TEST_F(ClipTest, TrianglesOutsideTheWindowDrawNothing) {
  flat_white();
  std::mt19937 random(3004);
  std::uniform_int_distribution<int> word(0, 0xFFFE);
  std::vector<FxU16> background(kClipPixels);
  for (FxU16 &w : background) w = static_cast<FxU16>(word(random));
  put_background(background);
  struct Case {
    const char *name;
    GrVertex a, b, c;
  };
  const Case cases[] = {
      // Its bounding box overlaps the window, but x + y <= 27 misses the corner (16,12).
      {"corner miss", at(0, 0, 0, 0, 0), at(27, 0, 0, 0, 0), at(0, 27, 0, 0, 0)},
      // Touches the left side x = 16 along an edge from outside: a zero-area remainder.
      {"touching the left side", at(2, 20, 0, 0, 0), at(16, 20, 0, 0, 0), at(16, 30, 0, 0, 0)},
      {"right of the window", at(50, 0, 0, 0, 0), at(63, 30, 0, 0, 0), at(52, 63, 0, 0, 0)},
      {"below the window", at(0, 45, 0, 0, 0), at(64, 50, 0, 0, 0), at(30, 64, 0, 0, 0)},
      {"off the screen", at(-40, -30, 0, 0, 0), at(-5, -30, 0, 0, 0), at(-5, -2, 0, 0, 0)},
  };
  for (const Case &t : cases) {
    glideShimClearError();
    glideShimResetPixelsWritten();
    guDrawTriangleWithClip(&t.a, &t.b, &t.c);
    EXPECT_EQ(glideShimPixelsWritten(), 0u) << t.name;
    EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK)
        << t.name << ": " << glideShimGetLastErrorMessage();
  }
  const std::vector<FxU16> frame = read_buffer();
  int changed = 0;
  for (std::size_t i = 0; i < kClipPixels; ++i) {
    if (frame[i] != background[i] && changed++ < 3) {
      ADD_FAILURE() << "pixel (" << i % kClipWidth << "," << i / kClipWidth << ") changed from "
                    << clip_hex(background[i]) << " to " << clip_hex(frame[i]);
    }
  }
  EXPECT_EQ(changed, 0) << "pixels changed by triangles outside the clip window";
  // The counter does count: a triangle inside the window writes pixels.
  glideShimResetPixelsWritten();
  const GrVertex a = at(20, 20, 0, 0, 0), b = at(40, 20, 0, 0, 0), c = at(20, 40, 0, 0, 0);
  guDrawTriangleWithClip(&a, &b, &c);
  // 190 pixel centres lie strictly inside; the 20 on the diagonal go to one side or the other
  // by the fill rule.
  const FxU32 written = glideShimPixelsWritten();
  EXPECT_TRUE(written >= 190u && written <= 210u)
      << written << " pixels written by a 20x20 half-square inside the window";
  expect_no_error();
}

}  // namespace

namespace {

TEST_F(GlideWindowTest, FarOffScreenVerticesAreClippedNotRefused) {
  // guclip.c clips in floating point, so a vertex far beyond the 12.4 range still draws the
  // visible part (grDrawTriangle, which does not clip, refuses it).
  grDitherMode(GR_DITHER_DISABLE);
  GrVertex a = vertex(), b = vertex(), c = vertex();
  a.x = 4, a.y = 4;
  b.x = 50000, b.y = 20;
  c.x = 4, c.y = 60;
  a.r = b.r = c.r = 255;
  guDrawTriangleWithClip(&a, &b, &c);
  expect_no_error();
  EXPECT_EQ(pixel(30, 30), 0xF800);
  grDrawTriangle(&a, &b, &c);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_VALUE);
}

}  // namespace

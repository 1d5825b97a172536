// The error metrics on small PNGs written to the test's temporary directory: mean, max and PSNR,
// the heat map, in-memory comparisons, masks read from files, and reading errors. Written and
// read back with OpenImageIO directly, independently of the module the metrics use.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "measure/metrics.h"

namespace {

using namespace gs;

std::string temp_path(const std::string &name) { return testing::TempDir() + "metrics_" + name; }

// Writes 8-bit pixels (row-major, `channels` per pixel) as a PNG.
void write_png(const std::string &path, int w, int h, int channels,
               std::vector<unsigned char> pixels) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(w, h, channels, OIIO::TypeDesc::UINT8), pixels.data());
  ASSERT_TRUE(buf.write(path)) << buf.geterror();
}

TEST(CompareImages, MeanMaxPsnrAndHeatMap) {
  const int w = 4, h = 2;
  std::vector<unsigned char> black(w * h * 3, 0);
  // Pixel (1,0) green: one level, not over the threshold. 191 → 192 is a pair whose difference
  // as float comes out above 1/255.
  black[4] = 191;
  std::vector<unsigned char> changed = black;
  changed[0] = 255;  // pixel (0,0) red: difference 1
  changed[4] = 192;
  changed[6] = 2;    // pixel (2,0) red: two levels, over it
  const std::string a = temp_path("a.png"), b = temp_path("b.png"), heat = temp_path("heat.png");
  std::remove(heat.c_str());
  write_png(a, w, h, 3, black);
  write_png(b, w, h, 3, changed);

  ImageErrors e;
  std::string error;
  ASSERT_TRUE(compare_images(a, b, heat, e, error)) << error;
  const double values = w * h * 3;
  EXPECT_NEAR(e.mean, (1.0 + 3.0 / 255) / values, 1e-6);
  EXPECT_NEAR(e.max, 1.0, 1e-6);
  EXPECT_EQ(e.pixels_over_threshold, 2);
  const double rms = std::sqrt((1.0 + 5.0 / (255.0 * 255.0)) / values);
  EXPECT_NEAR(e.psnr, 20.0 * std::log10(1.0 / rms), 1e-3);

  OIIO::ImageBuf map(heat);
  ASSERT_TRUE(map.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << map.geterror();
  EXPECT_EQ(map.spec().width, w);
  EXPECT_EQ(map.spec().height, h);
  float rgb[3];
  map.getpixel(0, 0, rgb, 3);  // the largest difference: white
  EXPECT_FLOAT_EQ(rgb[0] + rgb[1] + rgb[2], 3.0f);
  map.getpixel(3, 1, rgb, 3);  // no difference: black
  EXPECT_FLOAT_EQ(rgb[0] + rgb[1] + rgb[2], 0.0f);
  map.getpixel(2, 0, rgb, 3);  // 2/255 of the largest: dark red
  EXPECT_GT(rgb[0], 0.0f);
  EXPECT_LT(rgb[0], 0.1f);
  EXPECT_EQ(rgb[1] + rgb[2], 0.0f);
}

// OIIO gives +inf for identical images; compare_images reports a finite 999 dB instead.
TEST(CompareImages, IdenticalImagesHaveFiniteDocumentedPsnr) {
  const std::string a = temp_path("same.png");
  write_png(a, 3, 3, 3, std::vector<unsigned char>(27, 77));
  ImageErrors e;
  std::string error;
  ASSERT_TRUE(compare_images(a, a, "", e, error)) << error;
  EXPECT_EQ(e.mean, 0.0);
  EXPECT_EQ(e.max, 0.0);
  EXPECT_EQ(e.pixels_over_threshold, 0);
  EXPECT_TRUE(std::isfinite(e.psnr));
  EXPECT_EQ(e.psnr, 999.0);
}

// Frames in memory (the bench's whole-image error) are compared as the files are.
TEST(CompareImages, InMemoryRgbMatchesTheFileComparison) {
  const int w = 4, h = 2;
  std::vector<unsigned char> black(w * h * 3, 0), changed(w * h * 3, 0);
  changed[0] = 255;
  changed[6] = 2;
  const std::string a = temp_path("mem_a.png"), b = temp_path("mem_b.png");
  write_png(a, w, h, 3, black);
  write_png(b, w, h, 3, changed);
  ImageErrors from_files;
  std::string error;
  ASSERT_TRUE(compare_images(a, b, "", from_files, error)) << error;
  ImageErrors in_memory, identical;
  ASSERT_TRUE(compare_rgb(black, changed, w, h, in_memory, error)) << error;
  EXPECT_DOUBLE_EQ(in_memory.mean, from_files.mean);
  EXPECT_DOUBLE_EQ(in_memory.max, from_files.max);
  EXPECT_DOUBLE_EQ(in_memory.psnr, from_files.psnr);
  EXPECT_EQ(in_memory.pixels_over_threshold, 2);
  EXPECT_NEAR(in_memory.mean, (1.0 + 2.0 / 255) / (w * h * 3), 1e-6);
  ASSERT_TRUE(compare_rgb(changed, changed, w, h, identical, error)) << error;
  EXPECT_EQ(identical.psnr, 999.0);
}

// Pixels that do not make the size given are refused by name, never scored.
TEST(CompareImages, InMemoryRgbOfTheWrongSizeIsAnError) {
  const std::vector<unsigned char> six(6, 0), eight(8, 0);
  ImageErrors errors;
  std::string error;
  EXPECT_FALSE(compare_rgb(six, eight, 1, 2, errors, error));
  EXPECT_NE(error.find("6 and 8 bytes"), std::string::npos) << error;
}

TEST(CompareImages, ReportsMissingFileAndSizeMismatchByName) {
  const std::string a = temp_path("small.png"), b = temp_path("large.png");
  const std::string missing = temp_path("does_not_exist.png");
  write_png(a, 2, 2, 3, std::vector<unsigned char>(12, 0));
  write_png(b, 3, 2, 3, std::vector<unsigned char>(18, 0));
  ImageErrors e;
  std::string error;
  EXPECT_FALSE(compare_images(a, missing, "", e, error));
  EXPECT_NE(error.find(missing), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(compare_images(missing, a, "", e, error));
  EXPECT_NE(error.find(missing), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(compare_images(a, b, "", e, error));
  EXPECT_NE(error.find(a), std::string::npos) << error;
  EXPECT_NE(error.find(b), std::string::npos) << error;
}

TEST(ReadMask, ChannelAboveHalfIsShadowAlphaIgnored) {
  const std::string path = temp_path("mask.png");
  // RGBA, opaque: (0,0) black, (1,0) blue 128, (0,1) green 127, (1,1) white.
  write_png(path, 2, 2, 4,
            {0, 0, 0, 255, 0, 0, 128, 255, 0, 127, 0, 255, 255, 255, 255, 255});
  std::vector<std::uint8_t> mask;
  int w = 0, h = 0;
  std::string error;
  ASSERT_TRUE(read_mask(path, mask, w, h, error)) << error;
  EXPECT_EQ(w, 2);
  EXPECT_EQ(h, 2);
  EXPECT_EQ(mask, (std::vector<std::uint8_t>{0, 1, 0, 1}));
}

// What `glideshadows compare` treats as a mask: black and one grey above half, shared.
TEST(ReadMask, BlackAndWhiteIsBlackAndOneSharedGreyAboveHalf) {
  struct Case {
    const char *name;
    std::vector<std::uint8_t> rgb;  // 2x1 pixels
    bool black_and_white;
  };
  const Case cases[] = {
      {"truth's 0/255", {0, 0, 0, 255, 255, 255}, true},
      {"render's 0/254", {254, 254, 254, 0, 0, 0}, true},
      {"all black", {0, 0, 0, 0, 0, 0}, true},
      {"two greys", {254, 254, 254, 255, 255, 255}, false},
      {"a colour", {0, 0, 0, 255, 0, 0}, false},
      {"a dark grey", {0, 0, 0, 100, 100, 100}, false},
  };
  for (const Case &c : cases) {
    const std::string path = temp_path("two_levels.png");
    write_png(path, 2, 1, 3, c.rgb);
    std::vector<std::uint8_t> mask;
    int w = 0, h = 0;
    bool black_and_white = !c.black_and_white;
    std::string error;
    ASSERT_TRUE(read_mask(path, mask, w, h, error, &black_and_white)) << error;
    EXPECT_EQ(black_and_white, c.black_and_white) << c.name;
  }
}

TEST(ReadMask, ReportsMissingFileByName) {
  const std::string missing = temp_path("no_mask.png");
  std::vector<std::uint8_t> mask;
  int w = 0, h = 0;
  std::string error;
  EXPECT_FALSE(read_mask(missing, mask, w, h, error));
  EXPECT_NE(error.find(missing), std::string::npos) << error;
}

}  // namespace

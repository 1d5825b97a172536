// The gu utilities: byte and word swaps, the RLE16 encoder (decoded here from the format's
// description: one 32-bit word per run, length high, 565 pixel low), and the colour-per-level
// test mip map. None needs a window.
#include <glide.h>
#include <glide_shim.h>
#include <glideutl.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

namespace {

// Decodes RLE16 words back to pixels, checking every run is 1..32767 long.
std::vector<FxU16> decode_rle16(const std::vector<std::uint8_t> &bytes) {
  std::vector<FxU16> pixels;
  for (std::size_t at = 0; at + 4 <= bytes.size(); at += 4) {
    FxU32 word;
    std::memcpy(&word, bytes.data() + at, 4);
    const FxU32 run = word >> 16;
    EXPECT_GE(run, 1u);
    EXPECT_LE(run, 32767u);
    pixels.insert(pixels.end(), run, static_cast<FxU16>(word & 0xFFFF));
  }
  return pixels;
}

std::vector<std::uint8_t> encode(std::vector<FxU16> pixels, FxU32 width, FxU32 height) {
  const int bytes = guEncodeRLE16(nullptr, pixels.data(), width, height);
  std::vector<std::uint8_t> out(static_cast<std::size_t>(bytes) + 8, 0xAB);
  EXPECT_EQ(guEncodeRLE16(out.data(), pixels.data(), width, height), bytes)
      << "counting and encoding disagree";
  // Nothing is written past the returned byte count.
  EXPECT_EQ(out[static_cast<std::size_t>(bytes)], 0xAB);
  out.resize(static_cast<std::size_t>(bytes));
  return out;
}

TEST(GuUtilities, EndianSwapsExchangeHalves) {
  EXPECT_EQ(guEndianSwapWords(0x12345678u), 0x56781234u);
  EXPECT_EQ(guEndianSwapWords(0xFFFF0000u), 0x0000FFFFu);
  EXPECT_EQ(guEndianSwapBytes(0x1234), 0x3412);
  EXPECT_EQ(guEndianSwapBytes(0xFF00), 0x00FF);
  std::mt19937 random(5);
  for (int i = 0; i < 1000; ++i) {
    const FxU32 word = static_cast<FxU32>(random());
    EXPECT_EQ(guEndianSwapWords(guEndianSwapWords(word)), word);
    const auto half = static_cast<FxU16>(word);
    EXPECT_EQ(guEndianSwapBytes(guEndianSwapBytes(half)), half);
  }
}

TEST(GuUtilities, EncodeRle16WritesOneWordPerRun) {
  // 3 x A, B, 2 x C over two rows of three: runs continue across the row end.
  std::vector<FxU16> pixels = {0xF800, 0xF800, 0xF800, 0x07E0, 0x001F, 0x001F};
  const std::vector<std::uint8_t> bytes = encode(pixels, 3, 2);
  ASSERT_EQ(bytes.size(), 12u);
  FxU32 words[3];
  std::memcpy(words, bytes.data(), sizeof words);
  EXPECT_EQ(words[0], (3u << 16) | 0xF800u);
  EXPECT_EQ(words[1], (1u << 16) | 0x07E0u);
  EXPECT_EQ(words[2], (2u << 16) | 0x001Fu);
}

TEST(GuUtilities, EncodeRle16RoundTripsRandomImages) {
  std::mt19937 random(17);
  for (int image = 0; image < 20; ++image) {
    const auto width = static_cast<FxU32>(1 + random() % 200);
    const auto height = static_cast<FxU32>(1 + random() % 50);
    std::vector<FxU16> pixels(width * height);
    // Runs of random length and colour, some as long as the image.
    std::size_t at = 0;
    while (at < pixels.size()) {
      const std::size_t run = 1 + random() % (image % 2 == 0 ? 4 : 3000);
      const auto color = static_cast<FxU16>(random() % 4);  // few colours: neighbours repeat
      for (std::size_t k = 0; k < run && at < pixels.size(); ++k) pixels[at++] = color;
    }
    EXPECT_EQ(decode_rle16(encode(pixels, width, height)), pixels) << "image " << image;
  }
}

TEST(GuUtilities, EncodeRle16SplitsRunsLongerThanAShort) {
  std::vector<FxU16> pixels(40000, 0x1234);
  const std::vector<std::uint8_t> bytes = encode(pixels, 40000, 1);
  ASSERT_EQ(bytes.size(), 8u);
  FxU32 words[2];
  std::memcpy(words, bytes.data(), sizeof words);
  EXPECT_EQ(words[0], (32767u << 16) | 0x1234u);
  EXPECT_EQ(words[1], (7233u << 16) | 0x1234u);
}

TEST(GuUtilities, EncodeRle16OfNothingIsNoBytes) {
  FxU16 pixel = 0;
  EXPECT_EQ(guEncodeRLE16(nullptr, &pixel, 0, 7), 0);
  EXPECT_EQ(guEncodeRLE16(nullptr, &pixel, 7, 0), 0);
}

TEST(GuUtilities, EncodeRle16RefusesBadArguments) {
  glideShimClearError();
  EXPECT_EQ(guEncodeRLE16(nullptr, nullptr, 4, 4), 0);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  glideShimClearError();
  FxU16 pixel = 0;
  // 65536 x 65536 pixels could need 16 GB of runs: more than the int result can count.
  EXPECT_EQ(guEncodeRLE16(nullptr, &pixel, 65536, 65536), 0);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  EXPECT_NE(std::strstr(glideShimGetLastErrorMessage(), "guEncodeRLE16"), nullptr);
  glideShimClearError();
}

TEST(GuUtilities, ColorMipMapHasOneColourPerLevel) {
  FxU16 *data = guTexCreateColorMipMap();
  ASSERT_NE(data, nullptr);
  const FxU16 expected[9] = {0xF800, 0x07E0, 0x001F, 0xFFFF, 0x0000,
                             0xF800, 0x07E0, 0x001F, 0xFFFF};
  std::size_t at = 0;
  int level = 0;
  for (int side = 256; side >= 1; side /= 2, ++level) {
    int wrong = 0;
    for (int texel = 0; texel < side * side; ++texel) wrong += data[at++] != expected[level];
    EXPECT_EQ(wrong, 0) << "level " << level << " (" << side << "x" << side << ")";
  }
  EXPECT_EQ(at, 87381u);  // 256^2 + 128^2 + ... + 1: one whole 256..1 chain
  std::free(data);
}

}  // namespace

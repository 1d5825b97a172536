// What the LFB tests share: the window's size, hex words for messages, frames compared word for
// word, the 565 words the Voodoo stores for a truncated colour and for a 555 source word, and
// LfbTest, a Glide window with helpers to fill, write and check whole colour buffers.
#pragma once

#include "glide_window.h"
#include "voodoo_reference.h"

#include <cstring>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace lfb_checks {

constexpr int kW = 64;  // GlideWindowTest's window
constexpr int kH = 64;
constexpr std::size_t kPixels = static_cast<std::size_t>(kW) * kH;

inline std::string hex(unsigned value) {
  std::ostringstream s;
  s << "0x" << std::hex << std::uppercase << std::setw(4) << std::setfill('0') << value;
  return s.str();
}

inline std::vector<FxU16> random_words(std::mt19937 &random, std::size_t count) {
  std::uniform_int_distribution<int> word(0, 0xFFFF);
  std::vector<FxU16> words(count);
  for (FxU16 &w : words) w = static_cast<FxU16>(word(random));
  return words;
}

// Number of pixels where two whole frames differ; reports the first few with coordinates.
inline int count_differences(const std::vector<FxU16> &got, const std::vector<FxU16> &want,
                      const std::string &what) {
  if (got.size() != want.size()) {
    ADD_FAILURE() << what << ": " << got.size() << " pixels, want " << want.size();
    return static_cast<int>(want.size());
  }
  int differences = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (got[i] == want[i]) continue;
    if (differences++ < 3) {
      ADD_FAILURE() << what << ": pixel (" << i % kW << "," << i / kW << ") is " << hex(got[i])
                    << ", want " << hex(want[i]);
    }
  }
  return differences;
}

// The 565 word that the pipeline, with dither off, writes for an 8-bit colour: truncation.
inline FxU16 truncated_565(int r, int g, int b) {
  return static_cast<FxU16>((r >> 3) << 11 | (g >> 2) << 5 | (b >> 3));
}

// The 565 word grLfbWriteRegion stores for a 555 or 1555 source word: red and blue keep their
// 5 bits, green widens to 6 by replicating its top bit (g5 << 1 | g5 >> 4), bit 15 is ignored.
inline FxU16 from_555(FxU16 word) {
  const int r5 = word >> 10 & 0x1F, g5 = word >> 5 & 0x1F, b5 = word & 0x1F;
  const int g6 = g5 << 1 | g5 >> 4;
  return static_cast<FxU16>(r5 << 11 | g6 << 5 | b5);
}

class LfbTest : public GlideWindowTest {
 protected:
  // Writes a whole colour buffer through the LFB (565 words, no conversion).
  static void fill(GrBuffer_t buffer, std::vector<FxU16> &words) {
    ASSERT_EQ(words.size(), kPixels);
    ASSERT_TRUE(grLfbWriteRegion(buffer, 0, 0, GR_LFB_SRC_FMT_565, kW, kH, kW * 2, words.data()))
        << glideShimGetLastErrorMessage();
  }

  // Flat colour from the constant colour register, written without dither.
  static void use_constant_colour(GrColor_t argb) {
    grDitherMode(GR_DITHER_DISABLE);
    grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                   GR_COMBINE_OTHER_NONE, FXFALSE);
    grConstantColorValue(argb);
  }

  // Writes `words` (16-bit source pixels in `format`) in full-screen batches and checks every
  // stored word against from_555.
  void check_555_family(GrLfbSrcFmt_t format, const std::vector<FxU16> &words,
                        const std::string &name) {
    int bad = 0;
    for (std::size_t start = 0; start < words.size(); start += kPixels) {
      std::vector<FxU16> batch(words.begin() + static_cast<std::ptrdiff_t>(start),
                               words.begin() + static_cast<std::ptrdiff_t>(start + kPixels));
      ASSERT_TRUE(
          grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, format, kW, kH, kW * 2, batch.data()))
          << name << ": " << glideShimGetLastErrorMessage();
      const std::vector<FxU16> got = read_buffer();
      for (std::size_t i = 0; i < kPixels; ++i) {
        const FxU16 want = from_555(batch[i]);
        if (got[i] != want && bad++ < 5) {
          ADD_FAILURE() << name << " source word " << hex(batch[i]) << " stored as "
                        << hex(got[i]) << ", want " << hex(want);
        }
      }
    }
    EXPECT_EQ(bad, 0) << name << ": source words converted wrongly (of " << words.size() << ")";
  }

  // Pixel i has r = i, g = 7i + 3, b = 13i + 5 (mod 256), so every level of every channel
  // occurs, in varied combinations; the top byte (888's pad, 8888's alpha) is random and must
  // not matter. Each channel truncates: r >> 3, g >> 2, b >> 3.
  void check_32bit_format(GrLfbSrcFmt_t format, const std::string &name) {
    std::mt19937 random(static_cast<unsigned>(format) + 17u);
    std::uniform_int_distribution<unsigned> top(0, 255);
    std::vector<FxU32> source(kPixels);
    std::vector<FxU16> want(kPixels);
    for (std::size_t i = 0; i < kPixels; ++i) {
      const int r = static_cast<int>(i & 0xFF), g = static_cast<int>((7 * i + 3) & 0xFF),
                b = static_cast<int>((13 * i + 5) & 0xFF);
      source[i] = top(random) << 24 | static_cast<FxU32>(r) << 16 | static_cast<FxU32>(g) << 8 |
                  static_cast<FxU32>(b);
      want[i] = truncated_565(r, g, b);
    }
    ASSERT_TRUE(
        grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, format, kW, kH, kW * 4, source.data()))
        << name << ": " << glideShimGetLastErrorMessage();
    EXPECT_EQ(count_differences(read_buffer(), want, name + " from 0xAARRGGBB words"), 0);
  }
};


}  // namespace lfb_checks

// The W-buffer depth code (glide_shim::w_code) against the independent CPU Voodoo reference
// (voodoo_ref::w_buffer_code), its inverse (oow_from_w_code), and the GL depth the shim draws
// with (vertex_depth): affine in 1/w as the hardware iterates it, larger 1/w (nearer) larger.
#include "depth.h"
#include "voodoo_reference.h"

#include <glide.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

// Compares w_code with the reference at `oow`; returns false (after one failure) on a mismatch.
bool same_code(double oow) {
  const int want = voodoo_ref::w_buffer_code(oow);
  const int got = glide_shim::w_code(oow);
  if (want == got) return true;
  ADD_FAILURE() << "w_code(" << oow << ") (w = " << 1.0 / oow << ") = 0x" << std::hex << got
                << ", reference 0x" << want;
  return false;
}

// The 1/w of `count` points on a geometric grid of w from 1 to 65536.
std::vector<double> geometric_oows(int count) {
  std::vector<double> oows;
  oows.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double w = std::pow(65536.0, static_cast<double>(i) / (count - 1));
    oows.push_back(1.0 / w);
  }
  return oows;
}

TEST(DepthCode, WCodeMatchesTheReferenceOnADenseSweepOfW) {
  int mismatches = 0;
  for (double oow : geometric_oows(100000)) {
    if (!same_code(oow) && ++mismatches > 10) break;
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(DepthCode, WCodeMatchesTheReferenceAroundEveryPowerOfTwo) {
  // Each octave of w starts a new exponent: check 2^-k and the doubles next to it, and the
  // .32 fixed-point steps around it (where the truncation of the iterator changes).
  int mismatches = 0;
  for (int k = 0; k <= 20; ++k) {
    const double p = std::ldexp(1.0, -k);
    const double step = std::ldexp(1.0, -32);
    const double around[] = {p,
                             std::nextafter(p, 0.0),
                             std::nextafter(p, 2.0),
                             p - step,
                             p + step,
                             p - 0.5 * step,
                             p + 0.5 * step,
                             p - 16 * step,
                             p + 16 * step,
                             p * (1.0 - 1.0 / 8192.0),
                             p * (1.0 + 1.0 / 8192.0)};
    for (double oow : around) {
      if (oow >= 0.0 && !same_code(oow)) ++mismatches;
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(DepthCode, WCodeMatchesTheReferenceAtEveryMantissaStepOfOneOctave) {
  // w in [2, 4): oow in (1/4, 1/2]; the 12-bit mantissa steps every 2^-14 of oow.
  int mismatches = 0;
  for (int m = 0; m <= 4096 * 2; ++m) {
    const double oow = 0.25 + m * std::ldexp(1.0, -15);
    if (!same_code(oow) && ++mismatches > 10) break;
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(DepthCode, WCodeOfSpecialValues) {
  // oow = 0 (w infinite): the top 16 fraction bits are zero, code 0xFFFF (farthest).
  EXPECT_EQ(glide_shim::w_code(0.0), 0xFFFF);
  EXPECT_EQ(voodoo_ref::w_buffer_code(0.0), 0xFFFF);
  // Below 2^-16 the top bits are still zero: 0xFFFF.
  EXPECT_EQ(glide_shim::w_code(std::ldexp(1.0, -17)), 0xFFFF);
  // oow = 1 (w = 1) and above saturate to 0 (nearest).
  for (double oow : {1.0, 1.5, 2.0, 1e6}) {
    EXPECT_EQ(glide_shim::w_code(oow), 0) << "oow " << oow;
    EXPECT_TRUE(same_code(oow));
  }
  // Just below 1: exponent 0, mantissa 0xFFF -> (0 << 12) + 0 + 1 = 1.
  EXPECT_EQ(glide_shim::w_code(std::nextafter(1.0, 0.0)), 1);
  // oow = 0.5 (w = 2): .32 fraction 0x80000000, no leading zeros, mantissa 0
  // -> (0 << 12) + 0xFFF + 1 = 0x1000.
  EXPECT_EQ(glide_shim::w_code(0.5), 0x1000);
  EXPECT_TRUE(same_code(0.5));
  // oow = 0.25 (w = 4): one leading zero, mantissa 0 -> (1 << 12) + 0xFFF + 1 = 0x2000.
  EXPECT_EQ(glide_shim::w_code(0.25), 0x2000);
  // oow = 0.75 (w = 4/3): 0xC0000000, no leading zeros, mantissa 0x800
  // -> 0 + (~0x800 & 0xFFF) + 1 = 0x7FF + 1 = 0x800.
  EXPECT_EQ(glide_shim::w_code(0.75), 0x800);
  EXPECT_TRUE(same_code(0.75));
  // Negative oow (w behind the eye): the hardware's 16.32 iterator has its integer bits set, which
  // saturates the code to 0 like oow >= 1 (voodoo_ref: "oow >= 1 (or negative) -> 0").
  for (double oow : {-1e-9, -0.25, -1.0, -3.0}) {
    EXPECT_TRUE(same_code(oow)) << "negative oow " << oow;
  }
}

TEST(DepthCode, WCodeIsMonotonicNonDecreasingInW) {
  // The geometric grid runs w upwards, so 1/w downwards.
  const std::vector<double> oows = geometric_oows(100000);
  int previous = glide_shim::w_code(oows.front());
  int violations = 0;
  for (std::size_t i = 1; i < oows.size(); ++i) {
    const int code = glide_shim::w_code(oows[i]);
    if (code < previous) {
      if (++violations <= 5) {
        ADD_FAILURE() << "w_code fell from 0x" << std::hex << previous << " to 0x" << code
                      << std::dec << " as w grew to " << 1.0 / oows[i];
      }
    }
    previous = code;
  }
  EXPECT_EQ(violations, 0);
  // The sweep covers the whole range of codes it should: w = 1 gives 0, w = 65536 gives the
  // largest finite code (2^-16: 15 leading zeros, mantissa 0 -> 0xFFFF after the clamp).
  EXPECT_EQ(glide_shim::w_code(oows.front()), 0);
  EXPECT_EQ(glide_shim::w_code(oows.back()), 0xFFFF);
}

TEST(DepthCode, OowFromWCodeIsAnExactInverse) {
  int mismatches = 0;
  for (int c = 0; c <= 0xFFFF; ++c) {
    const auto code = static_cast<FxU16>(c);
    const double oow = glide_shim::oow_from_w_code(code);
    const FxU16 back = glide_shim::w_code(oow);
    if (back != code && ++mismatches <= 10) {
      ADD_FAILURE() << "w_code(oow_from_w_code(0x" << std::hex << c << ")) = 0x" << back
                    << " (oow " << std::dec << oow << ")";
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(DepthCode, OowFromWCodeLiesInsideTheReferenceIntervalOfTheCode) {
  // The hardware itself maps the shim's representative 1/w of every code back to that code.
  int mismatches = 0;
  for (int c = 0; c <= 0xFFFF; ++c) {
    const double oow = glide_shim::oow_from_w_code(static_cast<FxU16>(c));
    const int back = voodoo_ref::w_buffer_code(oow);
    if (back != c && ++mismatches <= 10) {
      ADD_FAILURE() << "reference code of oow_from_w_code(0x" << std::hex << c << ") is 0x" << back;
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(DepthCode, OowFromWCodeDecreasesAsTheCodeGrows) {
  double previous = glide_shim::oow_from_w_code(0);
  EXPECT_EQ(previous, 1.0);
  for (int c = 1; c <= 0xFFFF; ++c) {
    const double oow = glide_shim::oow_from_w_code(static_cast<FxU16>(c));
    ASSERT_LT(oow, previous) << "code 0x" << std::hex << c;
    previous = oow;
  }
}

TEST(DepthCode, DepthCodesSurviveTheRoundTripThroughGlDepth) {
  // grBufferClear(depth code) writes gl_depth_from_code; an aux-buffer LFB read converts back
  // with code_from_gl_depth from a float: every code must come back unchanged.
  int mismatches = 0;
  for (bool w_buffer : {false, true}) {
    for (int c = 0; c <= 0xFFFF; ++c) {
      const auto code = static_cast<FxU16>(c);
      const auto depth = static_cast<float>(glide_shim::gl_depth_from_code(code, w_buffer));
      const FxU16 back = glide_shim::code_from_gl_depth(depth, w_buffer);
      if (back != code && ++mismatches <= 10) {
        ADD_FAILURE() << (w_buffer ? "W" : "Z") << " code 0x" << std::hex << c << " came back 0x"
                      << back;
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
}

glide_shim::DepthState w_buffer_state(FxI16 bias) {
  return {GR_DEPTHBUFFER_WBUFFER, GR_CMP_LESS, true, bias};
}

TEST(DepthCode, WBufferVertexDepthIsAffineInOow) {
  // Equal steps in oow give equal steps in GL depth (second differences vanish), with and
  // without a bias, over the range where nothing clamps.
  for (FxI16 bias : {FxI16{0}, FxI16{100}, FxI16{-100}, FxI16{4096}}) {
    const glide_shim::DepthState state = w_buffer_state(bias);
    const float start = 0.001f, step = 0.0004f;
    const int count = 1000;  // oow up to 0.401
    std::vector<double> depth(count);
    for (int i = 0; i < count; ++i) {
      const float oow = start + step * static_cast<float>(i);
      depth[static_cast<std::size_t>(i)] = glide_shim::vertex_depth(state, 0.0f, oow);
    }
    const double slope = (depth[count - 1] - depth[0]) / (count - 1);
    EXPECT_GT(slope, 0.0) << "bias " << bias;
    for (int i = 0; i < count; ++i) {
      const double line = depth[0] + slope * i;
      ASSERT_NEAR(depth[static_cast<std::size_t>(i)], line, 2e-6)
          << "bias " << bias << ": depth is not affine in oow at oow = " << start + step * static_cast<float>(i);
    }
    for (int i = 1; i + 1 < count; ++i) {
      const double second = depth[static_cast<std::size_t>(i + 1)] - 2 * depth[static_cast<std::size_t>(i)] +
                            depth[static_cast<std::size_t>(i - 1)];
      ASSERT_NEAR(second, 0.0, 1e-6) << "bias " << bias << " at step " << i;
    }
  }
}

TEST(DepthCode, WBufferVertexDepthGrowsWithOow) {
  // Larger oow is nearer (smaller w, smaller code) and must give a larger GL depth, over the
  // whole range of w the W-buffer covers.
  const glide_shim::DepthState state = w_buffer_state(0);
  const std::vector<double> oows = geometric_oows(100000);  // oow falling from 1 to 2^-16
  float previous = glide_shim::vertex_depth(state, 0.0f, static_cast<float>(oows.front()));
  for (std::size_t i = 1; i < oows.size(); ++i) {
    const float oow = static_cast<float>(oows[i]);
    const float depth = glide_shim::vertex_depth(state, 0.0f, oow);
    ASSERT_LT(depth, previous) << "GL depth did not fall as oow fell to " << oow;
    previous = depth;
  }
  // And it orders the same way as the hardware codes: nearer = smaller code = larger depth.
  for (std::size_t i = 1; i < oows.size(); i += 997) {
    const auto near_oow = static_cast<float>(oows[i - 1]), far_oow = static_cast<float>(oows[i]);
    EXPECT_LE(glide_shim::w_code(near_oow), glide_shim::w_code(far_oow));
    EXPECT_GT(glide_shim::vertex_depth(state, 0.0f, near_oow),
              glide_shim::vertex_depth(state, 0.0f, far_oow));
  }
  // Beyond oow = 1 the code saturates at nearest (0), and so does the depth.
  EXPECT_EQ(glide_shim::vertex_depth(state, 0.0f, 2.0f), glide_shim::vertex_depth(state, 0.0f, 1.0f));
}

}  // namespace

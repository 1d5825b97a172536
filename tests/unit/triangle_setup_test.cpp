// grDrawTriangle's whole-triangle vertex work (triangle_setup.cpp) against the per-vertex
// functions every other primitive uses: convert_triangle gives write_vertex's bits and
// triangle_is_valid check_vertex's verdict, for every combination of the state fields_read reads
// (colour and alpha sources, delta0, fog source, depth mode and bias, the STW hint), on random
// vertices, half-way coordinates, the snap offset's window and NaN, infinity or out-of-range
// values in each float; and the context's cached fields_read stays equal to a fresh one across
// the state changes an open window goes through; queue_checked_triangle, which grDrawTriangle
// calls, queues exactly the triangles triangle_is_valid passes, converted as write_vertex does.
#include "draw.h"

#include <glide.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace {

using glide_shim::GlideContext;
using glide_shim::ShimVertex;

std::uint32_t float_bits(float v) {
  std::uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

void ignore_error(const char *, FxBool) {}

// Every combination of the state fields_read depends on, applied to `context` in turn.
template <typename Visit>
void for_each_state(GlideContext &context, Visit visit) {
  const GrCombineLocal_t locals[] = {GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_LOCAL_CONSTANT};
  const GrCombineOther_t others[] = {GR_COMBINE_OTHER_ITERATED, GR_COMBINE_OTHER_TEXTURE,
                                     GR_COMBINE_OTHER_CONSTANT};
  const GrFogMode_t fogs[] = {GR_FOG_DISABLE, GR_FOG_WITH_TABLE, GR_FOG_WITH_ITERATED_Z,
                              GR_FOG_WITH_ITERATED_ALPHA};
  const GrDepthBufferMode_t depths[] = {GR_DEPTHBUFFER_DISABLE, GR_DEPTHBUFFER_ZBUFFER,
                                        GR_DEPTHBUFFER_WBUFFER,
                                        GR_DEPTHBUFFER_ZBUFFER_COMPARE_TO_BIAS};
  for (GrCombineLocal_t local : locals) {
    for (GrCombineOther_t other : others) {
      for (GrCombineLocal_t alpha_local : {GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_LOCAL_NONE}) {
        for (bool delta0 : {false, true}) {
          for (GrFogMode_t fog : fogs) {
            for (GrDepthBufferMode_t depth : depths) {
              for (FxI16 bias : {FxI16{0}, FxI16{300}}) {
                for (FxU32 hint : {0u, FxU32{GR_STWHINT_W_DIFF_TMU0}}) {
                  context.color_path.color = {GR_COMBINE_FUNCTION_SCALE_OTHER,
                                              GR_COMBINE_FACTOR_ONE, local, other, false};
                  context.color_path.alpha = {GR_COMBINE_FUNCTION_SCALE_OTHER,
                                              GR_COMBINE_FACTOR_ONE, alpha_local,
                                              GR_COMBINE_OTHER_CONSTANT, false};
                  context.color_path.delta0 = delta0;
                  const float iterated4[4] = {17.5f, 3.25f, 200.75f, 99.0f};
                  std::memcpy(context.color_path.iterated4, iterated4, sizeof iterated4);
                  context.fog.mode = fog;
                  context.depth.mode = depth;
                  context.depth.bias_level = bias;
                  context.raster.stw_hint = hint;
                  visit(glide_shim::fields_read(context));
                }
              }
            }
          }
        }
      }
    }
  }
}

// Coordinates the snap treats specially: half-way 1/32 steps, signed zeros, the setup range's
// edges, and values a program left the 3<<18 snap offset on.
float special_coordinate(std::mt19937 &random) {
  std::uniform_int_distribution<int> pick(0, 7), step(-600000, 600000);
  std::uniform_real_distribution<float> in_window(-4095.0f, 4095.0f);
  switch (pick(random)) {
    case 0: return static_cast<float>(step(random)) / 32.0f + 0.03125f;  // a half-way case
    case 1: return -0.0f;
    case 2: return glide_shim::kSnapOffset + in_window(random);
    case 3: return -glide_shim::kMaxScreenCoordinate;
    default: return std::uniform_real_distribution<float>(-32700.0f, 32700.0f)(random);
  }
}

GrVertex random_vertex(std::mt19937 &random) {
  std::uniform_real_distribution<float> colour(0.0f, 255.0f), ooz(0.0f, 70000.0f),
      oow(-0.5f, 3.0f), st(-300.0f, 300.0f);
  GrVertex v;
  std::memset(&v, 0, sizeof v);
  v.x = special_coordinate(random), v.y = special_coordinate(random);
  v.z = std::numeric_limits<float>::quiet_NaN();  // never read
  v.r = colour(random), v.g = colour(random), v.b = colour(random), v.a = colour(random);
  v.ooz = ooz(random), v.oow = oow(random);
  v.tmuvtx[0].sow = st(random), v.tmuvtx[0].tow = st(random), v.tmuvtx[0].oow = oow(random);
  v.tmuvtx[1].sow = std::numeric_limits<float>::infinity();  // never read
  return v;
}

TEST(TriangleSetup, ConvertsAsWriteVertexDoesForEveryState) {
  GlideContext context;
  std::mt19937 random(13);
  int triangles = 0;
  for_each_state(context, [&](const glide_shim::VertexFields &fields) {
    for (int t = 0; t < 20; ++t, ++triangles) {
      const GrVertex in[3] = {random_vertex(random), random_vertex(random), random_vertex(random)};
      ASSERT_TRUE(glide_shim::triangle_is_valid(fields, in[0], in[1], in[2]));
      ShimVertex whole[3], alone[3];
      glide_shim::convert_triangle(fields, in[0], in[1], in[2], whole);
      for (int k = 0; k < 3; ++k) {
        glide_shim::write_vertex(fields, in[k], alone[k]);
        const float *w = &whole[k].x, *a = &alone[k].x;
        for (std::size_t i = 0; i < sizeof(ShimVertex) / sizeof(float); ++i) {
          ASSERT_EQ(float_bits(w[i]), float_bits(a[i])) << "vertex " << k << ", float " << i << " of triangle "
                                            << triangles;
        }
      }
    }
  });
  EXPECT_EQ(triangles, 2 * 3 * 2 * 2 * 4 * 4 * 2 * 2 * 20);
}

TEST(TriangleSetup, RefusesWhatCheckVertexRefuses) {
  GlideContext context;
  context.errors.callback = ignore_error;
  std::mt19937 random(7);
  const float big = glide_shim::kMaxScreenCoordinate;
  const float bad_values[] = {std::numeric_limits<float>::quiet_NaN(),
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              std::nextafter(big, 2.0f * big), -std::nextafter(big, 2.0f * big),
                              big, 1.0e30f, glide_shim::kSnapOffset - 4096.0f,
                              std::nextafter(glide_shim::kSnapOffset - 4096.0f, 0.0f),
                              glide_shim::kSnapOffset + 4096.0f,
                              std::nextafter(glide_shim::kSnapOffset + 4096.0f, 0.0f)};
  int refused = 0, cases = 0;
  for_each_state(context, [&](const glide_shim::VertexFields &fields) {
    for (int corner = 0; corner < 3; ++corner) {
      for (int index = 0; index < glide_shim::kCheckedVertexFloats; ++index) {
        for (float bad : bad_values) {
          GrVertex in[3] = {random_vertex(random), random_vertex(random), random_vertex(random)};
          (&in[corner].x)[index] = bad;
          bool each = true;
          for (const GrVertex &v : in) each = each && glide_shim::check_vertex(context, fields, v, "test");
          ASSERT_EQ(glide_shim::triangle_is_valid(fields, in[0], in[1], in[2]), each)
              << "value " << bad << " at float " << index << " of vertex " << corner;
          refused += each ? 0 : 1;
          ++cases;
        }
      }
    }
  });
  EXPECT_GT(refused, cases / 10);  // both verdicts were exercised
  EXPECT_LT(refused, cases);
}

// grDrawTriangle's own call, queue_checked_triangle, on an open window's renderer: a triangle
// that passes triangle_is_valid's checks is queued at the end of the queue with write_vertex's
// bits, and one that fails them (a NaN, an infinity or an out-of-range value in a float the
// state reads) returns null and queues nothing.
TEST(TriangleSetup, QueuesWhatItChecksAsWriteVertexConverts) {
  grGlideInit();
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1));
  GlideContext &context = glide_shim::current();
  glide_shim::GlRenderer &renderer = *context.renderer;
  const auto queue_end = [&renderer] {
    return renderer.queue_space(glide_shim::Primitive::Triangles, 0);
  };
  const float bad_values[] = {std::numeric_limits<float>::quiet_NaN(),
                              -std::numeric_limits<float>::infinity(), 1.0e30f};
  std::mt19937 random(29);
  std::uniform_int_distribution<int> corner(0, 2), index(0, glide_shim::kCheckedVertexFloats - 1),
      value(0, 2);
  int queued = 0, refused = 0;
  for_each_state(context, [&](const glide_shim::VertexFields &fields) {
    for (int t = 0; t < 4; ++t) {
      GrVertex in[3] = {random_vertex(random), random_vertex(random), random_vertex(random)};
      if (t >= 2) (&in[corner(random)].x)[index(random)] = bad_values[value(random)];
      const ShimVertex *end = queue_end();
      const ShimVertex *out = glide_shim::queue_checked_triangle(renderer, fields, in[0], in[1], in[2]);
      if (!glide_shim::triangle_is_valid(fields, in[0], in[1], in[2])) {
        ASSERT_EQ(out, nullptr);
        ASSERT_EQ(queue_end(), end) << "a refused triangle was queued";
        ++refused;
        continue;
      }
      ASSERT_NE(out, nullptr);
      ASSERT_EQ(queue_end(), out + 3) << "the triangle is not the queue's last three vertices";
      for (int k = 0; k < 3; ++k) {
        ShimVertex alone;
        glide_shim::write_vertex(fields, in[k], alone);
        const float *q = &out[k].x, *a = &alone.x;
        for (std::size_t i = 0; i < sizeof(ShimVertex) / sizeof(float); ++i) {
          ASSERT_EQ(float_bits(q[i]), float_bits(a[i])) << "vertex " << k << ", float " << i;
        }
      }
      renderer.unqueue(3);  // nothing is drawn at the window's close
      ++queued;
    }
  });
  EXPECT_GT(queued, 1536 * 2);  // every state's two clean triangles, and some of the others
  EXPECT_GT(refused, 1536 / 4);
  grSstWinClose();
  grGlideShutdown();
}

void expect_same_fields(const glide_shim::VertexFields &fresh,
                        const glide_shim::VertexFields &cached, std::size_t change) {
  EXPECT_EQ(fresh.rgb, cached.rgb) << "after change " << change;
  EXPECT_EQ(fresh.alpha, cached.alpha) << "after change " << change;
  EXPECT_EQ(fresh.ooz, cached.ooz) << "after change " << change;
  EXPECT_EQ(fresh.oow, cached.oow) << "after change " << change;
  EXPECT_EQ(fresh.texture, cached.texture) << "after change " << change;
  EXPECT_EQ(fresh.fog, cached.fog) << "after change " << change;
  EXPECT_EQ(fresh.delta0, cached.delta0) << "after change " << change;
  for (int i = 0; i < 3; ++i) EXPECT_EQ(fresh.delta0_rgb[i], cached.delta0_rgb[i]) << change;
  EXPECT_EQ(fresh.q_from_tmu, cached.q_from_tmu) << "after change " << change;
  EXPECT_EQ(fresh.depth_source, cached.depth_source) << "after change " << change;
  EXPECT_EQ(fresh.depth, cached.depth) << "after change " << change;
  for (int i = 0; i < glide_shim::kCheckedVertexFloats; ++i) {
    EXPECT_EQ(fresh.checked_exponents[i], cached.checked_exponents[i]) << "after change " << change;
  }
}

// The context's copy of fields_read is recomputed after every state change an entry point makes.
TEST(TriangleSetup, CachedFieldsFollowTheState) {
  grGlideInit();
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1));
  GlideContext &context = glide_shim::current();
  GrVertex v[3];
  std::memset(v, 0, sizeof v);
  v[1].x = 10.0f, v[2].y = 10.0f;
  for (GrVertex &vertex : v) vertex.oow = vertex.tmuvtx[0].oow = 1.0f;
  const std::vector<void (*)()> changes = {
      [] { grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER); },
      [] { grDepthBiasLevel(100); },
      [] { grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER); },
      [] { grFogMode(GR_FOG_WITH_ITERATED_Z); },
      [] { grHints(GR_HINT_STWHINT, GR_STWHINT_W_DIFF_TMU0); },
      [] { guColorCombineFunction(GR_COLORCOMBINE_TEXTURE_TIMES_ITRGB_DELTA0); },
      [] { grConstantColorValue4(10.0f, 20.5f, 30.0f, 40.0f); },
      [] { grAlphaCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE,
                          GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_NONE, FXFALSE); },
      [] { guColorCombineFunction(GR_COLORCOMBINE_CCRGB); },
      [] { grAlphaControlsITRGBLighting(FXTRUE); },
      [] { grFogMode(GR_FOG_DISABLE); },
  };
  for (std::size_t i = 0; i < changes.size(); ++i) {
    grDrawTriangle(&v[0], &v[1], &v[2]);
    changes[i]();
    grDrawTriangle(&v[0], &v[1], &v[2]);
    expect_same_fields(glide_shim::fields_read(context), glide_shim::current_vertex_fields(context),
                       i);
  }
  grSstWinClose();
  grGlideShutdown();
}

}  // namespace

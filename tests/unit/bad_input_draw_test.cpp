// Bad input, chapter "drawing primitives": NaN, infinite or absurd values in a vertex field the
// state reads are INVALID_VALUE and draw nothing; in a field it does not read they draw; and
// degenerate triangles are dropped without an error, as Glide drops them.
#include "bad_input_fixture.h"

#include <string>
#include <utility>
#include <vector>

namespace {

using namespace bad_input;

using Spoil = std::function<void(GrVertex &)>;

// Every draw entry point, with `spoil` applied to the vertex at each position in turn.
std::vector<BadCall> draws_with(const Spoil &spoil) {
  std::vector<BadCall> calls;
  for (int position = 0; position < 3; ++position) {
    GrVertex v[3] = {kA, kB, kC};
    spoil(v[position]);
    calls.push_back({"grDrawTriangle", [=] { grDrawTriangle(&v[0], &v[1], &v[2]); }});
    calls.push_back({"guDrawTriangleWithClip", [=] { guDrawTriangleWithClip(&v[0], &v[1], &v[2]); }});
  }
  for (int position = 0; position < 2; ++position) {
    GrVertex v[2] = {make_vertex(2.0f, 16.5f), make_vertex(60.0f, 16.5f)};
    spoil(v[position]);
    calls.push_back({"grDrawLine", [=] { grDrawLine(&v[0], &v[1]); }});
  }
  GrVertex p = make_vertex(16.25f, 16.25f);
  spoil(p);
  calls.push_back({"grDrawPoint", [=] { grDrawPoint(&p); }});
  return calls;
}

// ---- vertex values -----------------------------------------------------------------------------

TEST_F(BadInputTest, NanOrInfinityInThePositionIsInvalidValueAndDrawsNothing) {
  const std::pair<const char *, Spoil> spoils[] = {
      {"x NaN", [](GrVertex &v) { v.x = kNaN; }},   {"y NaN", [](GrVertex &v) { v.y = kNaN; }},
      {"x +Inf", [](GrVertex &v) { v.x = kInf; }},  {"x -Inf", [](GrVertex &v) { v.x = -kInf; }},
      {"y +Inf", [](GrVertex &v) { v.y = kInf; }},  {"y -Inf", [](GrVertex &v) { v.y = -kInf; }},
  };
  for (const auto &spoil : spoils) {
    expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with(spoil.second), spoil.first);
  }
}

TEST_F(BadInputTest, AbsurdCoordinatesAreInvalidValueAndDrawNothing) {
  const std::pair<const char *, Spoil> spoils[] = {
      {"x 1e9", [](GrVertex &v) { v.x = 1e9f; }},
      {"y 1e9", [](GrVertex &v) { v.y = 1e9f; }},
      {"x -1e9", [](GrVertex &v) { v.x = -1e9f; }},
      {"y -1e9", [](GrVertex &v) { v.y = -1e9f; }},
      // guDrawTriangleWithClip clips vertices out to 1e7 (as guclip.c would); 1e8 is refused by all.
      {"x 1e8", [](GrVertex &v) { v.x = 1e8f; }},
  };
  for (const auto &spoil : spoils) {
    expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with(spoil.second), spoil.first);
  }
}

TEST_F(BadInputTest, NanInAColourTheStateReadsIsInvalidValue) {
  // Default colour combine: SCALE_OTHER with other = ITERATED, so r, g, b are read.
  ASSERT_EQ(current().color_path.color.other, GR_COMBINE_OTHER_ITERATED);
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.r = kNaN; }), "r NaN");
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.g = kInf; }), "g +Inf");
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.b = -kInf; }), "b -Inf");
  // Iterated alpha makes a read.
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
  expect_no_error();
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.a = kNaN; }), "a NaN, iterated alpha");
}

TEST_F(BadInputTest, NanInADepthOrTextureFieldTheStateReadsIsInvalidValue) {
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  expect_no_error();
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.oow = kNaN; }), "oow NaN, W-buffer");
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.oow = kInf; }), "oow +Inf, W-buffer");
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  expect_no_error();
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.ooz = kNaN; }), "ooz NaN, Z-buffer");
  grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
  // A texture source in the colour path reads s, t and w.
  static std::vector<FxU16> texels(8 * 8, 0x07E0);
  GrTexInfo info{GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  expect_no_error();
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.tmuvtx[0].sow = kNaN; }), "sow NaN, textured");
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.tmuvtx[0].tow = -kInf; }), "tow -Inf, textured");
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.oow = kNaN; }), "oow NaN, textured");
}

TEST_F(BadInputTest, NanInAFieldTheStateDoesNotReadIsAcceptedAndDraws) {
  const FxU16 white = 0xFFFF;
  auto spoil_all = [](const Spoil &spoil) {
    // Spoil every vertex of every call, not just one.
    std::vector<BadCall> calls;
    GrVertex t[3] = {kA, kB, kC};
    for (GrVertex &v : t) spoil(v);
    calls.push_back({"grDrawTriangle", [=] { grDrawTriangle(&t[0], &t[1], &t[2]); }});
    calls.push_back({"guDrawTriangleWithClip", [=] { guDrawTriangleWithClip(&t[0], &t[1], &t[2]); }});
    GrVertex l[2] = {make_vertex(2.0f, 16.5f), make_vertex(60.0f, 16.5f)};
    for (GrVertex &v : l) spoil(v);
    calls.push_back({"grDrawLine", [=] { grDrawLine(&l[0], &l[1]); }});
    GrVertex p = make_vertex(16.25f, 16.25f);
    spoil(p);
    calls.push_back({"grDrawPoint", [=] { grDrawPoint(&p); }});
    return calls;
  };
  // Depth disabled, no texturing, constant alpha: ooz, oow, tmuvtx, a and z are not read.
  const std::pair<const char *, Spoil> unread[] = {
      {"ooz NaN, depth off", [](GrVertex &v) { v.ooz = kNaN; }},
      {"oow NaN, depth off, no texture", [](GrVertex &v) { v.oow = kNaN; }},
      {"tmuvtx NaN/Inf, no texture",
       [](GrVertex &v) {
         v.tmuvtx[0].sow = kNaN, v.tmuvtx[0].tow = kInf, v.tmuvtx[0].oow = -kInf;
         v.tmuvtx[1].sow = kNaN, v.tmuvtx[1].tow = kNaN, v.tmuvtx[1].oow = kNaN;
       }},
      {"a NaN, constant alpha", [](GrVertex &v) { v.a = kNaN; }},
      {"z NaN (never read)", [](GrVertex &v) { v.z = kNaN; }},
  };
  for (const auto &case_ : unread) {
    for (const BadCall &call : spoil_all(case_.second)) expect_drawn(call, white, case_.first);
  }
  // A constant colour path does not read r, g, b (the constant is white).
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  expect_no_error();
  for (const BadCall &call : spoil_all([](GrVertex &v) { v.r = kNaN, v.g = kInf, v.b = -kInf; })) {
    expect_drawn(call, white, "r,g,b NaN/Inf, constant colour");
  }
  // Z-buffer mode reads ooz but not oow.
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthBufferFunction(GR_CMP_ALWAYS);
  expect_no_error();
  for (const BadCall &call : spoil_all([](GrVertex &v) { v.oow = kNaN; })) {
    expect_drawn(call, white, "oow NaN, Z-buffer");
  }
}

TEST_F(BadInputTest, ZeroAreaAndCollinearTrianglesAreDroppedSilently) {
  const std::vector<FxU16> front = read_buffer(GR_BUFFER_FRONTBUFFER);
  const std::vector<FxU16> back = read_buffer(GR_BUFFER_BACKBUFFER);
  const GrVertex same[3] = {make_vertex(20, 20), make_vertex(20, 20), make_vertex(20, 20)};
  const GrVertex line[3] = {make_vertex(10, 10), make_vertex(30, 30), make_vertex(50, 50)};
  const GrVertex flat[3] = {make_vertex(4, 32), make_vertex(60, 32), make_vertex(30, 32)};
  const GrVertex two_same[3] = {make_vertex(10, 10), make_vertex(50, 40), make_vertex(10, 10)};
  // Collinear only after snapping to 1/16 pixel: 20.01 snaps to 20.
  const GrVertex snapped[3] = {make_vertex(10, 10), make_vertex(20, 20.01f), make_vertex(40, 40)};
  for (const GrVertex *t : {same, line, flat, two_same, snapped}) {
    for (GrCullMode_t cull : {GR_CULL_DISABLE, GR_CULL_NEGATIVE, GR_CULL_POSITIVE}) {
      grCullMode(cull);
      glideShimResetPixelsWritten();
      reset_errors();
      grDrawTriangle(&t[0], &t[1], &t[2]);
      guDrawTriangleWithClip(&t[0], &t[1], &t[2]);
      guDrawTriangleWithClip(&t[2], &t[1], &t[0]);
      EXPECT_EQ(glideShimPixelsWritten(), 0u)
          << "degenerate triangle (" << t[0].x << "," << t[0].y << ") (" << t[1].x << "," << t[1].y
          << ") (" << t[2].x << "," << t[2].y << ") drew pixels, cull " << cull;
      expect_no_error_reported();
    }
  }
  EXPECT_TRUE(read_buffer(GR_BUFFER_FRONTBUFFER) == front);
  EXPECT_TRUE(read_buffer(GR_BUFFER_BACKBUFFER) == back);
}

}  // namespace

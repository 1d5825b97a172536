// The shim's benchmark workloads: the SDK-style frames, as 3dfx's test programs draw them
// (640x480, the driver's defaults: 4x4 dither, no fog; a W-buffer with LESS, grBufferClear, a
// few triangles, grBufferSwap), and shim_bench's stream of 100,000 small Gouraud-textured
// triangles. Shared by shim_bench (timed against the same work in plain GL) and by the test that
// renders them with the shim's fast paths allowed and forced off (GLIDESHIM_EXACT=1).
#pragma once

#include <glide.h>

#include <cstring>
#include <random>
#include <vector>

namespace shim_workloads {

constexpr int kWidth = 640, kHeight = 480;
constexpr GrColor_t kClearColor = 0x00302010;  // dark brown in the ARGB window
constexpr FxU32 kTextureAddress = 0;

enum class Workload { Gouraud, Textured, Blended };

inline const char *name(Workload w) {
  return w == Workload::Gouraud ? "gouraud" : w == Workload::Textured ? "textured" : "blended";
}

// A vertex in screen pixels (upper-left origin), its w, colour and texture position in texels.
struct Point {
  float x, y, w;
  float r, g, b, a;
  float s, t;  // 0..256 over the texture
};

inline GrVertex to_glide(const Point &p) {
  GrVertex v;
  std::memset(&v, 0, sizeof v);
  v.x = p.x, v.y = p.y;
  v.r = p.r, v.g = p.g, v.b = p.b, v.a = p.a;
  v.oow = 1.0f / p.w;
  v.tmuvtx[0].sow = p.s * v.oow, v.tmuvtx[0].tow = p.t * v.oow, v.tmuvtx[0].oow = v.oow;
  return v;
}

// Two large overlapping Gouraud triangles at different depths (about 97,600 pixels).
inline std::vector<Point> two_triangles() {
  return {
      {160, 120, 1.0f, 255, 0, 0, 255, 0, 0},     {480, 120, 2.0f, 0, 255, 0, 255, 255, 0},
      {320, 400, 3.0f, 0, 0, 255, 255, 128, 255}, {100, 300, 2.5f, 255, 255, 0, 255, 0, 255},
      {540, 300, 1.5f, 0, 255, 255, 255, 255, 255}, {320, 60, 1.0f, 255, 0, 255, 255, 128, 0},
  };
}

// 50 small textured triangles (about 24 pixels on a side), alpha 96..255, scattered.
inline std::vector<Point> fifty_small_triangles() {
  std::mt19937 random(13);
  std::uniform_real_distribution<float> x(20.0f, 590.0f), y(20.0f, 430.0f), jitter(-4.0f, 4.0f),
      c(0.0f, 255.0f), a(96.0f, 255.0f), w(1.0f, 8.0f), s(0.0f, 224.0f);
  std::vector<Point> points;
  for (int i = 0; i < 50; ++i) {
    const float x0 = x(random), y0 = y(random), s0 = s(random), t0 = s(random), w0 = w(random);
    points.push_back({x0 + jitter(random), y0 + jitter(random), w0, c(random), c(random), c(random),
                      a(random), s0, t0});
    points.push_back({x0 + 24.0f + jitter(random), y0 + jitter(random), w0, c(random), c(random),
                      c(random), a(random), s0 + 32.0f, t0});
    points.push_back({x0 + jitter(random), y0 + 24.0f + jitter(random), w0, c(random), c(random),
                      c(random), a(random), s0, t0 + 32.0f});
  }
  return points;
}

// A 256x256 RGB565 texture with structure at every scale (bilinear weights show).
inline std::vector<FxU16> texture_565() {
  std::vector<FxU16> texels(256 * 256);
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      const int r = (x ^ y) & 31, g = ((x * 3 + y) >> 2) & 63, b = ((x >> 3) + (y >> 3) * 5) & 31;
      texels[static_cast<std::size_t>(y) * 256 + x] = static_cast<FxU16>((r << 11) | (g << 5) | b);
    }
  }
  return texels;
}

inline GrTexInfo texture_info(std::vector<FxU16> &texels) {
  return {GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
}

// What the SDK programs do once after grSstWinOpen: the depth buffer and, for the textured
// workloads, the texture download, its filter and the combine.
inline void set_up(Workload workload, std::vector<FxU16> &texels) {
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  if (workload == Workload::Gouraud) {
    guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
    return;
  }
  GrTexInfo info = texture_info(texels);
  grTexDownloadMipMap(GR_TMU0, kTextureAddress, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, kTextureAddress, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_TEXTURE_TIMES_ITRGB);
  if (workload == Workload::Blended) {
    guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
    grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                         GR_BLEND_ZERO);
  }
}

// The stream: `count` small triangles (about 6 pixels on a side) with random colours and
// texture positions, oow 1, scattered over the 640x480 screen.
struct Triangle {
  GrVertex v[3];
};

inline std::vector<Triangle> stream_triangles(int count) {
  std::mt19937 random(1);
  std::uniform_real_distribution<float> x(0.0f, 630.0f), y(0.0f, 470.0f), d(0.0f, 6.0f),
      c(0.0f, 255.0f), s(0.0f, 256.0f);
  std::vector<Triangle> triangles(static_cast<std::size_t>(count));
  for (Triangle &t : triangles) {
    const float x0 = x(random), y0 = y(random);
    for (int k = 0; k < 3; ++k) {
      GrVertex &v = t.v[k];
      std::memset(&v, 0, sizeof v);
      v.x = x0 + (k == 1 ? 6.0f : d(random));
      v.y = y0 + (k == 2 ? 6.0f : d(random));
      v.r = c(random), v.g = c(random), v.b = c(random), v.a = 255.0f;
      v.oow = 1.0f;
      v.tmuvtx[0].sow = s(random), v.tmuvtx[0].tow = s(random);
    }
  }
  return triangles;
}

// The stream's texture: 256x256 random 565 words.
inline std::vector<FxU16> stream_texture() {
  std::vector<FxU16> texels(256 * 256);
  std::mt19937 random(2);
  for (FxU16 &t : texels) t = static_cast<FxU16>(random());
  return texels;
}

// The stream's state on top of the window's defaults, and its frame: a 565 texture at
// `address`, bilinear, DECAL, TEXTURE_TIMES_ITRGB; a clear, the triangles, an idle.
inline void stream_frame(const std::vector<Triangle> &triangles, GrTexInfo &info, FxU32 address) {
  grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_TEXTURE_TIMES_ITRGB);
  grBufferClear(0, 0, 0);
  for (const Triangle &t : triangles) grDrawTriangle(&t.v[0], &t.v[1], &t.v[2]);
  grSstIdle();
}

inline const std::vector<Point> &points(Workload workload) {
  static const std::vector<Point> two = two_triangles(), fifty = fifty_small_triangles();
  return workload == Workload::Blended ? fifty : two;
}

// One frame: clear, the triangles, swap. The caller idles (grSstIdle) when it times the frame.
inline void glide_frame(Workload workload) {
  grBufferClear(kClearColor, 0, GR_WDEPTHVALUE_FARTHEST);
  const std::vector<Point> &p = points(workload);
  for (std::size_t i = 0; i + 2 < p.size(); i += 3) {
    const GrVertex a = to_glide(p[i]), b = to_glide(p[i + 1]), c = to_glide(p[i + 2]);
    grDrawTriangle(&a, &b, &c);
  }
  grBufferSwap(1);
}

}  // namespace shim_workloads

// glide_api_fuzz: decodes its input into a sequence of Glide 2.x calls with random arguments
// (state setters, texture downloads, LFB locks and region copies, draws with random vertices
// including NaN and infinities, clears, swaps, window close and reopen) on a small window, and
// after every call checks what must hold whatever the arguments were:
//   - a call that reported an error left every state group of the context as it was;
//   - an error is never reported without a message, and the callback saw the same message;
//   - the open window's groups stay in range (clip inside the target, TMU memory whole, LFB
//     copies the screen's size);
//   - round trips: 565 words written with grLfbWriteRegion read back unchanged,
//     grTexTextureMemRequired agrees with grTexCalcMemRequired for the same texture, restoring
//     grGlideGetState's block changes nothing, and grSstScreenWidth/Height give the window's size;
//   - a polygon with a vertex count far beyond its array (over 65,536) is refused unread.
// Any violation aborts, which libFuzzer reports as a crash with the input that caused it.
#include "context.h"

#include <fuzzer/FuzzedDataProvider.h>
#include <glide.h>
#include <glide_shim.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using glide_shim::GlideContext;

[[noreturn]] void violated(const char *call, const char *what) {
  std::fprintf(stderr, "glide_api_fuzz: after %s: %s\n", call, what);
  std::abort();
}

// ---- the context's state, to compare before and after a rejected call ---------------------

// Field by field: whole-struct byte comparisons would also compare padding, which an assignment
// of the same values may change.
bool same(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }  // NaN equals NaN
bool same(const glide_shim::ColorPathState &a, const glide_shim::ColorPathState &b) {
  return a.color == b.color && a.alpha == b.alpha && a.constant_color == b.constant_color &&
         a.alpha_controls_itrgb == b.alpha_controls_itrgb && a.delta0 == b.delta0 &&
         same(a.iterated4[0], b.iterated4[0]) && same(a.iterated4[1], b.iterated4[1]) &&
         same(a.iterated4[2], b.iterated4[2]) && same(a.iterated4[3], b.iterated4[3]);
}
bool same(const glide_shim::BlendState &a, const glide_shim::BlendState &b) {
  return a.rgb_src == b.rgb_src && a.rgb_dst == b.rgb_dst && a.alpha_src == b.alpha_src &&
         a.alpha_dst == b.alpha_dst && a.alpha_test_function == b.alpha_test_function &&
         a.alpha_test_reference == b.alpha_test_reference;
}
bool same(const glide_shim::ChromaKeyState &a, const glide_shim::ChromaKeyState &b) {
  return a.mode == b.mode && a.value == b.value;
}
bool same(const glide_shim::DepthState &a, const glide_shim::DepthState &b) {
  return a.mode == b.mode && a.function == b.function && a.mask == b.mask &&
         a.bias_level == b.bias_level;
}
bool same(const glide_shim::ClipRect &a, const glide_shim::ClipRect &b) {
  return a.min_x == b.min_x && a.min_y == b.min_y && a.max_x == b.max_x && a.max_y == b.max_y;
}
bool same(const glide_shim::RasterState &a, const glide_shim::RasterState &b) {
  return a.cull == b.cull && a.dither == b.dither && same(a.clip, b.clip) &&
         a.rgb_mask == b.rgb_mask && a.alpha_mask == b.alpha_mask &&
         a.render_buffer == b.render_buffer && a.origin == b.origin && a.stw_hint == b.stw_hint;
}
bool same(const glide_shim::DisplayState &a, const glide_shim::DisplayState &b) {
  return a.open == b.open && a.width == b.width && a.height == b.height &&
         a.color_format == b.color_format && same(a.gamma, b.gamma) && a.swaps == b.swaps &&
         a.none_width == b.none_width && a.none_height == b.none_height;
}
bool same(const glide_shim::TextureTarget &a, const glide_shim::TextureTarget &b) {
  return a.active == b.active && a.address == b.address && a.side == b.side &&
         same(a.saved_clip, b.saved_clip);
}
bool same(const glide_shim::TextureSource &a, const glide_shim::TextureSource &b) {
  return a.valid == b.valid && a.address == b.address && a.small_lod == b.small_lod &&
         a.large_lod == b.large_lod && a.aspect == b.aspect && a.format == b.format;
}
bool same(const glide_shim::TmuState &a, const glide_shim::TmuState &b) {
  return a.clamp_s == b.clamp_s && a.clamp_t == b.clamp_t && a.min_filter == b.min_filter &&
         a.mag_filter == b.mag_filter && a.mipmap_mode == b.mipmap_mode &&
         a.lod_blend == b.lod_blend && same(a.lod_bias, b.lod_bias) && a.combine == b.combine &&
         a.detail_bias == b.detail_bias && a.detail_scale == b.detail_scale &&
         a.detail_max == b.detail_max && same(a.source, b.source);
}

struct Snapshot {
  bool initialized, plain_gl;
  glide_shim::ColorPathState color_path;
  glide_shim::BlendState blend;
  glide_shim::ChromaKeyState chroma;
  glide_shim::DepthState depth;
  glide_shim::RasterState raster;
  glide_shim::DisplayState display;
  glide_shim::TextureTarget texture_target;
  glide_shim::TmuState tmu;  // memory included
  bool read_locked, write_locked;
  GrBuffer_t write_buffer;
  GrOriginLocation_t write_origin;
  decltype(glide_shim::LfbLockState::write_pixels) write_pixels;

  void take(const GlideContext &ctx) {
    initialized = ctx.initialized;
    plain_gl = ctx.plain_gl;
    color_path = ctx.color_path;
    blend = ctx.blend;
    chroma = ctx.chroma;
    depth = ctx.depth;
    raster = ctx.raster;
    display = ctx.display;
    texture_target = ctx.texture_target;
    tmu = ctx.tmu;
    read_locked = ctx.lfb.read_locked, write_locked = ctx.lfb.write_locked;
    write_buffer = ctx.lfb.write_buffer, write_origin = ctx.lfb.write_origin;
    write_pixels = ctx.lfb.write_pixels;
  }

  // The name of the first group that differs from `ctx`, or nullptr.
  const char *differs(const GlideContext &ctx) const {
    if (initialized != ctx.initialized || plain_gl != ctx.plain_gl) return "library state";
    if (!same(color_path, ctx.color_path)) return "colour path";
    if (!same(blend, ctx.blend)) return "blend";
    if (!same(chroma, ctx.chroma)) return "chroma key";
    if (!same(depth, ctx.depth)) return "depth";
    if (!same(raster, ctx.raster)) return "raster";
    if (!same(display, ctx.display)) return "display";
    if (!same(texture_target, ctx.texture_target)) return "texture target";
    if (!same(tmu, ctx.tmu)) return "texture modes";
    if (tmu.memory != ctx.tmu.memory) return "TMU memory";
    if (read_locked != ctx.lfb.read_locked || write_locked != ctx.lfb.write_locked ||
        write_buffer != ctx.lfb.write_buffer || write_origin != ctx.lfb.write_origin)
      return "LFB locks";
    if (write_pixels != ctx.lfb.write_pixels) return "LFB write copy";
    return nullptr;
  }
};

// ---- the error callback ------------------------------------------------------------------

std::string g_callback_message;
int g_callback_count = 0;

void on_error(const char *message, FxBool fatal) {
  (void)fatal;
  if (message == nullptr) violated("an error", "the callback was given a NULL message");
  g_callback_message = message;
  ++g_callback_count;
}

// ---- arguments ---------------------------------------------------------------------------

// Mostly values near a valid range [lo, hi] (one past each end included), sometimes any int.
int enum_value(FuzzedDataProvider &in, int lo, int hi) {
  if (in.ConsumeIntegralInRange(0, 15) == 0) return in.ConsumeIntegral<int>();
  return in.ConsumeIntegralInRange(lo - 1, hi + 1);
}

FxU32 small_or_any(FuzzedDataProvider &in, FxU32 hi) {
  if (in.ConsumeIntegralInRange(0, 7) == 0) return in.ConsumeIntegral<FxU32>();
  return in.ConsumeIntegralInRange<FxU32>(0, hi);
}

FxBool boolean(FuzzedDataProvider &in) {
  // FxBool is an int: Glide programs pass 0 and 1, a careless one anything.
  return in.ConsumeIntegralInRange(0, 7) == 0 ? in.ConsumeIntegral<FxBool>() : in.ConsumeBool();
}

// A float for a vertex field: on-screen values most of the time, then the edges of float.
float coordinate(FuzzedDataProvider &in, float span) {
  switch (in.ConsumeIntegralInRange(0, 11)) {
    case 0: return std::numeric_limits<float>::quiet_NaN();
    case 1: return std::numeric_limits<float>::infinity();
    case 2: return -std::numeric_limits<float>::infinity();
    case 3: return std::numeric_limits<float>::max();
    case 4: return std::numeric_limits<float>::denorm_min();
    case 5: return 786432.0f + in.ConsumeFloatingPointInRange(-8.0f, 8.0f);  // the 3<<18 snap
    case 6: return in.ConsumeFloatingPoint<float>();
    default: return in.ConsumeFloatingPointInRange(-0.5f * span, 1.5f * span);
  }
}

GrVertex vertex(FuzzedDataProvider &in, float span) {
  GrVertex v{};
  v.x = coordinate(in, span);
  v.y = coordinate(in, span);
  v.r = coordinate(in, 255.0f), v.g = coordinate(in, 255.0f), v.b = coordinate(in, 255.0f);
  v.a = coordinate(in, 255.0f);
  v.ooz = coordinate(in, 65535.0f);
  v.oow = coordinate(in, 1.0f);
  for (GrTmuVertex &t : v.tmuvtx) {
    t.sow = coordinate(in, 256.0f), t.tow = coordinate(in, 256.0f), t.oow = coordinate(in, 1.0f);
  }
  return v;
}

// Host bytes of a mip-map chain large_lod..small_lod as GrTexInfo.data holds it (every level at
// its plain texel count), computed here from the Glide 2.x tables, independently of the shim;
// 0 when the arguments are not a valid texture.
std::size_t host_chain_bytes(GrLOD_t small_lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
                             GrTextureFormat_t format) {
  if (large_lod < GR_LOD_256 || small_lod > GR_LOD_1 || large_lod > small_lod) return 0;
  if (aspect < GR_ASPECT_8x1 || aspect > GR_ASPECT_1x8) return 0;
  if (format < GR_TEXFMT_8BIT || format > GR_TEXFMT_RSVD2) return 0;
  // The reserved codes name no format: the shim refuses them and sizes them as 0.
  if (format == GR_TEXFMT_RSVD0 || format == GR_TEXFMT_RSVD1 || format == GR_TEXFMT_RSVD2) return 0;
  const int texel_bytes = format >= GR_TEXFMT_16BIT ? 2 : 1;
  const int wide = GR_ASPECT_1x1 - aspect;  // log2(width / height)
  std::size_t bytes = 0;
  for (GrLOD_t lod = large_lod; lod <= small_lod; ++lod) {
    const int side = 256 >> lod;
    const int width = wide >= 0 ? side : std::max(side >> -wide, 1);
    const int height = wide <= 0 ? side : std::max(side >> wide, 1);
    bytes += static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
             static_cast<std::size_t>(texel_bytes);
  }
  return bytes;
}

// A data buffer for a download: exactly the chain's size when the arguments are valid (ASan
// catches any read past it), else a few bytes that a correct shim never reads.
std::vector<std::uint8_t> texel_data(FuzzedDataProvider &in, std::size_t bytes) {
  std::vector<std::uint8_t> data(bytes > 0 ? bytes : 8);
  const std::vector<std::uint8_t> pattern = in.ConsumeBytes<std::uint8_t>(16);
  for (std::size_t i = 0; i < data.size(); ++i)
    data[i] = pattern.empty() ? static_cast<std::uint8_t>(i) : pattern[i % pattern.size()];
  return data;
}

GrTexInfo texture_info(FuzzedDataProvider &in) {
  GrTexInfo info{};
  info.largeLod = enum_value(in, GR_LOD_256, GR_LOD_1);
  info.smallLod = enum_value(in, GR_LOD_256, GR_LOD_1);
  info.aspectRatio = enum_value(in, GR_ASPECT_8x1, GR_ASPECT_1x8);
  info.format = enum_value(in, GR_TEXFMT_8BIT, GR_TEXFMT_RSVD2);
  return info;
}

// ---- the window --------------------------------------------------------------------------

bool open_window(FuzzedDataProvider &in) {
  const int width = in.ConsumeIntegralInRange(1, 96);
  const int height = in.ConsumeIntegralInRange(1, 96);
  if (!glideShimSetWindowSize(width, height)) violated("glideShimSetWindowSize", "a valid size was refused");
  // Valid arguments seven times in eight, so that most inputs get to their calls.
  const bool careless = in.ConsumeIntegralInRange(0, 7) == 0;
  const GrColorFormat_t format = careless ? enum_value(in, GR_COLORFORMAT_ARGB, GR_COLORFORMAT_BGRA)
                                          : in.ConsumeIntegralInRange(GR_COLORFORMAT_ARGB, GR_COLORFORMAT_BGRA);
  const GrOriginLocation_t origin = careless ? enum_value(in, GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT)
                                             : in.ConsumeIntegralInRange(GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT);
  const int color_buffers = careless ? in.ConsumeIntegralInRange(1, 4) : in.ConsumeIntegralInRange(2, 3);
  const int aux_buffers = careless ? in.ConsumeIntegralInRange(-1, 2) : in.ConsumeIntegralInRange(0, 1);
  const bool valid = format >= GR_COLORFORMAT_ARGB && format <= GR_COLORFORMAT_BGRA &&
                     (origin == GR_ORIGIN_UPPER_LEFT || origin == GR_ORIGIN_LOWER_LEFT) &&
                     color_buffers >= 2 && color_buffers <= 3 && aux_buffers >= 0 &&
                     aux_buffers <= 1;
  const bool already_open = glide_shim::current().display.open;
  const FxBool opened = grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, format, origin,
                                     color_buffers, aux_buffers);
  if (opened && (!valid || already_open)) violated("grSstWinOpen", "bad arguments were accepted");
  if (!opened && valid && !already_open && glide_shim::current().initialized)
    violated("grSstWinOpen", glideShimGetLastErrorMessage());
  if (opened && (grTexMinAddress(GR_TMU0) != 0 || glide_shim::current().display.width != width ||
                 glide_shim::current().display.height != height))
    violated("grSstWinOpen", "the window is not the size asked for");
  return opened != FXFALSE;
}

// ---- invariants --------------------------------------------------------------------------

void check_open_window(const GlideContext &ctx, const char *call) {
  const auto width = static_cast<std::size_t>(ctx.display.width);
  const auto height = static_cast<std::size_t>(ctx.display.height);
  if (width < 1 || height < 1 || width > glide_shim::kMaxScreenSide ||
      height > glide_shim::kMaxScreenSide)
    violated(call, "the window size is out of range");
  if (ctx.tmu.memory.size() != glide_shim::kTmuMemoryBytes) violated(call, "TMU memory is not whole");
  const glide_shim::ClipRect &clip = ctx.raster.clip;
  const std::size_t target_width = ctx.texture_target.active ? ctx.texture_target.side : width;
  const std::size_t target_height = ctx.texture_target.active ? ctx.texture_target.side : height;
  if (clip.min_x > clip.max_x || clip.min_y > clip.max_y || clip.max_x > target_width ||
      clip.max_y > target_height)
    violated(call, "the clip window is not inside the render target");
  if (ctx.lfb.read_locked && ctx.lfb.read_pixels.size() != width * height)
    violated(call, "the read lock's copy is not the screen's size");
  // A whole screen of pixels in the lock's format: a multiple of the pixel count.
  if (ctx.lfb.write_locked &&
      (ctx.lfb.write_pixels.empty() || ctx.lfb.write_pixels.size() % (width * height) != 0 ||
       ctx.lfb.write_original.size() != ctx.lfb.write_pixels.size()))
    violated(call, "the write lock's copy is not the screen's size");
  if (grSstScreenWidth() != width || grSstScreenHeight() != height)
    violated(call, "grSstScreenWidth/Height disagree with the window");
  if (grTexMinAddress(GR_TMU0) > grTexMaxAddress(GR_TMU0) ||
      grTexMaxAddress(GR_TMU0) >= glide_shim::kTmuMemoryBytes)
    violated(call, "the TMU's address range is wrong");
}

// Runs one call: clears the last error, snapshots the state, calls, then checks.
template <typename Call>
void checked(const char *name, Call &&call) {
  GlideContext &ctx = glide_shim::current();
  glideShimClearError();
  g_callback_count = 0;
  Snapshot before;
  before.take(ctx);
  call();
  const GlideShimError error = glideShimGetLastError();
  const std::string message = glideShimGetLastErrorMessage();
  if (error != GLIDESHIM_OK) {
    if (message.empty()) violated(name, "an error was reported without a message");
    if (g_callback_count == 0 || g_callback_message != message)
      violated(name, "the error callback did not get the error's message");
    if (const char *group = before.differs(ctx)) {
      std::fprintf(stderr, "glide_api_fuzz: %s was rejected (%s) but changed: %s\n", name,
                   message.c_str(), group);
      std::abort();
    }
  } else if (!message.empty()) {
    violated(name, "a message was left without an error");
  }
  // Getters report no error of their own while a window is open, so these do not disturb
  // the check above for the next call.
  if (ctx.display.open && !ctx.plain_gl) check_open_window(ctx, name);
}

// ---- the calls ---------------------------------------------------------------------------

void lfb_round_trip(FuzzedDataProvider &in) {
  const GlideContext &ctx = glide_shim::current();
  if (!ctx.display.open || ctx.plain_gl || ctx.lfb.write_locked || ctx.texture_target.active) return;
  const auto width = static_cast<FxU32>(ctx.display.width);
  const auto height = static_cast<FxU32>(ctx.display.height);
  const FxU32 x = in.ConsumeIntegralInRange<FxU32>(0, width - 1);
  const FxU32 y = in.ConsumeIntegralInRange<FxU32>(0, height - 1);
  const FxU32 w = in.ConsumeIntegralInRange<FxU32>(1, width - x);
  const FxU32 h = in.ConsumeIntegralInRange<FxU32>(1, height - y);
  const GrBuffer_t buffer = in.ConsumeBool() ? GR_BUFFER_BACKBUFFER : GR_BUFFER_FRONTBUFFER;
  std::vector<FxU16> written(static_cast<std::size_t>(w) * h), read(written.size());
  const FxU16 seed = in.ConsumeIntegral<FxU16>();
  for (std::size_t i = 0; i < written.size(); ++i)
    written[i] = static_cast<FxU16>(seed * 31u + i * 2654435761u);
  bool ok = false;
  checked("grLfbWriteRegion", [&] {
    ok = grLfbWriteRegion(buffer, x, y, GR_LFB_SRC_FMT_565, w, h, static_cast<FxI32>(w * 2),
                          written.data()) != FXFALSE;
  });
  if (!ok) violated("grLfbWriteRegion", "a region inside the screen was refused");
  checked("grLfbReadRegion", [&] {
    ok = grLfbReadRegion(buffer, x, y, w, h, w * 2, read.data()) != FXFALSE;
  });
  if (!ok) violated("grLfbReadRegion", "a region inside the screen was refused");
  if (read != written) violated("grLfbReadRegion", "565 words written did not read back unchanged");
}

void texture_memory_round_trip(FuzzedDataProvider &in) {
  GrTexInfo info = texture_info(in);
  const std::size_t host = host_chain_bytes(info.smallLod, info.largeLod, info.aspectRatio,
                                            info.format);
  FxU32 calculated = 0, required = 0;
  checked("grTexCalcMemRequired", [&] {
    calculated = grTexCalcMemRequired(info.smallLod, info.largeLod, info.aspectRatio, info.format);
  });
  checked("grTexTextureMemRequired", [&] {
    required = grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &info);
  });
  if (host > 0 && (calculated != required || calculated < host || calculated > 2 * host + 64)) {
    std::fprintf(stderr, "lods %d..%d aspect %d format %d: calc %u, required %u, host %zu\n",
                 static_cast<int>(info.largeLod), static_cast<int>(info.smallLod),
                 static_cast<int>(info.aspectRatio), static_cast<int>(info.format), calculated,
                 required, host);
    violated("grTexTextureMemRequired", "disagrees with grTexCalcMemRequired or the chain's size");
  }
}

// grGlideGetState then grGlideSetState of what it returned changes nothing, and a second
// grGlideGetState returns the same bytes.
void state_round_trip() {
  const GlideContext &ctx = glide_shim::current();
  if (!ctx.display.open || ctx.plain_gl) return;
  GrState first{}, second{};
  checked("grGlideGetState", [&] { grGlideGetState(&first); });
  Snapshot before;
  before.take(ctx);
  checked("grGlideSetState", [&] { grGlideSetState(&first); });
  if (const char *group = before.differs(ctx))
    violated("grGlideSetState", (std::string("restoring the saved state changed ") + group).c_str());
  checked("grGlideGetState", [&] { grGlideGetState(&second); });
  if (std::memcmp(&first, &second, sizeof first) != 0)
    violated("grGlideGetState", "the state saved again differs from the state restored");
}

// A polygon of `count` vertices from an array of exactly that many (indices inside it, or -1
// that the shim must refuse), or a count far beyond the array that the shim must refuse unread.
void polygon(FuzzedDataProvider &in, float span) {
  const bool absurd = in.ConsumeIntegralInRange(0, 15) == 0;
  const int count = in.ConsumeIntegralInRange(0, 8);
  std::vector<GrVertex> vertices;
  for (int i = 0; i < count; ++i) vertices.push_back(vertex(in, span));
  std::vector<int> indices;
  for (int i = 0; i < count; ++i) indices.push_back(in.ConsumeIntegralInRange(-1, count - 1));
  const int nverts = absurd ? in.ConsumeIntegralInRange(65537, std::numeric_limits<int>::max()) : count;
  const GrVertex *list = vertices.empty() ? nullptr : vertices.data();
  const int *ilist = indices.empty() ? nullptr : indices.data();
  switch (in.ConsumeIntegralInRange(0, 6)) {
    case 0: checked("grDrawPolygonVertexList", [&] { grDrawPolygonVertexList(nverts, list); }); break;
    case 1: checked("grDrawPolygon", [&] { grDrawPolygon(nverts, ilist, list); }); break;
    case 2: checked("grDrawPlanarPolygonVertexList", [&] { grDrawPlanarPolygonVertexList(nverts, list); }); break;
    case 3: checked("grDrawPlanarPolygon", [&] { grDrawPlanarPolygon(nverts, ilist, list); }); break;
    case 4: checked("grAADrawPolygonVertexList", [&] { grAADrawPolygonVertexList(nverts, list); }); break;
    case 5: checked("grAADrawPolygon", [&] { grAADrawPolygon(nverts, ilist, list); }); break;
    default:
      checked("guDrawPolygonVertexListWithClip", [&] { guDrawPolygonVertexListWithClip(nverts, list); });
      break;
  }
  const GlideShimError error = glideShimGetLastError();
  if (absurd && glide_shim::current().display.open && !glide_shim::current().plain_gl &&
      error != GLIDESHIM_ERR_OUT_OF_RANGE && error != GLIDESHIM_ERR_NULL_POINTER)
    violated("a polygon call", "an absurd vertex count was not refused");
}

void one_call(FuzzedDataProvider &in, float span) {
  switch (in.ConsumeIntegralInRange(0, 59)) {
    case 0: {
      const int f = enum_value(in, 0, 0x10), k = enum_value(in, 0, 0xd);
      const int l = enum_value(in, 0, 2), o = enum_value(in, 0, 2);
      const FxBool invert = boolean(in);
      checked("grColorCombine", [&] { grColorCombine(f, k, l, o, invert); });
      break;
    }
    case 1: {
      const int f = enum_value(in, 0, 0x10), k = enum_value(in, 0, 0xd);
      const int l = enum_value(in, 0, 2), o = enum_value(in, 0, 2);
      const FxBool invert = boolean(in);
      checked("grAlphaCombine", [&] { grAlphaCombine(f, k, l, o, invert); });
      break;
    }
    case 2: {
      const int a = enum_value(in, 0, 0xf), b = enum_value(in, 0, 0xf);
      const int c = enum_value(in, 0, 0xf), d = enum_value(in, 0, 0xf);
      checked("grAlphaBlendFunction", [&] { grAlphaBlendFunction(a, b, c, d); });
      break;
    }
    case 3: {
      const int function = enum_value(in, GR_CMP_NEVER, GR_CMP_ALWAYS);
      checked("grAlphaTestFunction", [&] { grAlphaTestFunction(function); });
      const GrAlpha_t reference = in.ConsumeIntegral<GrAlpha_t>();
      checked("grAlphaTestReferenceValue", [&] { grAlphaTestReferenceValue(reference); });
      break;
    }
    case 4: {
      const int mode = enum_value(in, GR_CHROMAKEY_DISABLE, GR_CHROMAKEY_ENABLE);
      checked("grChromakeyMode", [&] { grChromakeyMode(mode); });
      const GrColor_t value = in.ConsumeIntegral<GrColor_t>();
      checked("grChromakeyValue", [&] { grChromakeyValue(value); });
      break;
    }
    case 5: {
      const auto side = static_cast<FxU32>(span);
      const FxU32 a = small_or_any(in, side + 2), b = small_or_any(in, side + 2);
      const FxU32 c = small_or_any(in, side + 2), d = small_or_any(in, side + 2);
      checked("grClipWindow", [&] { grClipWindow(a, b, c, d); });
      break;
    }
    case 6: {
      const FxBool rgb = boolean(in), alpha = boolean(in);
      checked("grColorMask", [&] { grColorMask(rgb, alpha); });
      break;
    }
    case 7: {
      const GrColor_t value = in.ConsumeIntegral<GrColor_t>();
      checked("grConstantColorValue", [&] { grConstantColorValue(value); });
      break;
    }
    case 8: {
      const int mode = enum_value(in, GR_CULL_DISABLE, GR_CULL_POSITIVE);
      checked("grCullMode", [&] { grCullMode(mode); });
      break;
    }
    case 9: {
      const auto level = in.ConsumeIntegral<FxI16>();
      checked("grDepthBiasLevel", [&] { grDepthBiasLevel(level); });
      break;
    }
    case 10: {
      const int function = enum_value(in, GR_CMP_NEVER, GR_CMP_ALWAYS);
      checked("grDepthBufferFunction", [&] { grDepthBufferFunction(function); });
      break;
    }
    case 11: {
      const int mode = enum_value(in, GR_DEPTHBUFFER_DISABLE, GR_DEPTHBUFFER_WBUFFER_COMPARE_TO_BIAS);
      checked("grDepthBufferMode", [&] { grDepthBufferMode(mode); });
      break;
    }
    case 12: {
      const FxBool mask = boolean(in);
      checked("grDepthMask", [&] { grDepthMask(mask); });
      break;
    }
    case 13: {
      const int mode = enum_value(in, GR_DITHER_DISABLE, GR_DITHER_4x4);
      checked("grDitherMode", [&] { grDitherMode(mode); });
      break;
    }
    case 14: {
      const float gamma = coordinate(in, 3.0f);
      checked("grGammaCorrectionValue", [&] { grGammaCorrectionValue(gamma); });
      break;
    }
    case 15: {
      const int type = enum_value(in, GR_HINT_STWHINT, GR_HINT_ALLOW_MIPMAP_DITHER);
      const FxU32 mask = small_or_any(in, 0x7f);
      checked("grHints", [&] { grHints(type, mask); });
      break;
    }
    case 16: {
      const int origin = enum_value(in, GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT);
      checked("grSstOrigin", [&] { grSstOrigin(origin); });
      break;
    }
    case 17: {
      const int buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_TRIPLEBUFFER);
      checked("grRenderBuffer", [&] { grRenderBuffer(buffer); });
      break;
    }
    case 18: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int s = enum_value(in, 0, 1), t = enum_value(in, 0, 1);
      checked("grTexClampMode", [&] { grTexClampMode(tmu, s, t); });
      break;
    }
    case 19: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int min = enum_value(in, 0, 1), mag = enum_value(in, 0, 1);
      checked("grTexFilterMode", [&] { grTexFilterMode(tmu, min, mag); });
      break;
    }
    case 20: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int mode = enum_value(in, GR_MIPMAP_DISABLE, GR_MIPMAP_NEAREST_DITHER);
      const FxBool blend = boolean(in);
      checked("grTexMipMapMode", [&] { grTexMipMapMode(tmu, mode, blend); });
      break;
    }
    case 21: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const float bias = coordinate(in, 8.0f);
      checked("grTexLodBiasValue", [&] { grTexLodBiasValue(tmu, bias); });
      break;
    }
    case 22: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int rf = enum_value(in, 0, 0x10), rk = enum_value(in, 0, 0xd);
      const int af = enum_value(in, 0, 0x10), ak = enum_value(in, 0, 0xd);
      const FxBool ri = boolean(in), ai = boolean(in);
      checked("grTexCombine", [&] { grTexCombine(tmu, rf, rk, af, ak, ri, ai); });
      break;
    }
    case 23: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int function = enum_value(in, GR_TEXTURECOMBINE_ZERO, GR_TEXTURECOMBINE_ONE);
      checked("guTexCombineFunction", [&] { guTexCombineFunction(tmu, function); });
      break;
    }
    case 24: {
      const int function = enum_value(in, GR_COLORCOMBINE_ZERO, GR_COLORCOMBINE_ONE);
      checked("guColorCombineFunction", [&] { guColorCombineFunction(function); });
      break;
    }
    case 25: {
      const int source = enum_value(in, GR_ALPHASOURCE_CC_ALPHA,
                                    GR_ALPHASOURCE_TEXTURE_ALPHA_TIMES_ITERATED_ALPHA);
      checked("guAlphaSource", [&] { guAlphaSource(source); });
      break;
    }
    case 26: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8) & ~7u;
      const FxU32 even_odd = small_or_any(in, 4);
      GrTexInfo info = texture_info(in);
      const bool null_info = in.ConsumeIntegralInRange(0, 15) == 0;
      checked("grTexSource",
              [&] { grTexSource(tmu, address, even_odd, null_info ? nullptr : &info); });
      break;
    }
    case 27: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8);
      const FxU32 even_odd = small_or_any(in, 4);
      GrTexInfo info = texture_info(in);
      std::vector<std::uint8_t> data =
          texel_data(in, host_chain_bytes(info.smallLod, info.largeLod, info.aspectRatio, info.format));
      info.data = in.ConsumeIntegralInRange(0, 15) == 0 ? nullptr : data.data();
      checked("grTexDownloadMipMap", [&] { grTexDownloadMipMap(tmu, address, even_odd, &info); });
      break;
    }
    case 28: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8);
      const GrLOD_t this_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrLOD_t large_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrAspectRatio_t aspect = enum_value(in, GR_ASPECT_8x1, GR_ASPECT_1x8);
      const GrTextureFormat_t format = enum_value(in, GR_TEXFMT_8BIT, GR_TEXFMT_RSVD2);
      const FxU32 even_odd = small_or_any(in, 4);
      std::vector<std::uint8_t> data =
          texel_data(in, host_chain_bytes(this_lod, this_lod, aspect, format));
      checked("grTexDownloadMipMapLevel", [&] {
        grTexDownloadMipMapLevel(tmu, address, this_lod, large_lod, aspect, format, even_odd,
                                 data.data());
      });
      break;
    }
    case 29: {
      const GrVertex v = vertex(in, span);
      checked("grDrawPoint", [&] { grDrawPoint(&v); });
      break;
    }
    case 30: {
      const GrVertex a = vertex(in, span), b = vertex(in, span);
      checked("grDrawLine", [&] { grDrawLine(&a, &b); });
      break;
    }
    case 31:
    case 32: {
      const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
      checked("grDrawTriangle", [&] { grDrawTriangle(&a, &b, &c); });
      break;
    }
    case 33: {
      const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
      checked("guDrawTriangleWithClip", [&] { guDrawTriangleWithClip(&a, &b, &c); });
      break;
    }
    case 34: {
      const GrColor_t color = in.ConsumeIntegral<GrColor_t>();
      const GrAlpha_t alpha = in.ConsumeIntegral<GrAlpha_t>();
      const FxU16 depth = in.ConsumeIntegral<FxU16>();
      checked("grBufferClear", [&] { grBufferClear(color, alpha, depth); });
      break;
    }
    case 35: {
      const int interval = enum_value(in, 0, 2);
      checked("grBufferSwap", [&] { grBufferSwap(interval); });
      break;
    }
    case 36: {
      const GrLock_t type = enum_value(in, GR_LFB_READ_ONLY, GR_LFB_WRITE_ONLY) |
                            (in.ConsumeBool() ? GR_LFB_NOIDLE : 0);
      const GrBuffer_t buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_AUXBUFFER);
      const GrLfbWriteMode_t mode = in.ConsumeBool() ? GR_LFBWRITEMODE_565 : enum_value(in, 0, 0xff);
      const GrOriginLocation_t origin = enum_value(in, GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT);
      const FxBool pipeline = in.ConsumeIntegralInRange(0, 3) == 0;
      GrLfbInfo_t info{};
      info.size = in.ConsumeIntegralInRange(0, 15) == 0 ? 0 : static_cast<int>(sizeof info);
      FxBool locked = FXFALSE;
      checked("grLfbLock", [&] { locked = grLfbLock(type, buffer, mode, origin, pipeline, &info); });
      if (locked && (type & GR_LFB_WRITE_ONLY) != 0) {
        // Write as the program would: anywhere inside stride x height, through the pointer.
        const GlideContext &ctx = glide_shim::current();
        auto *words = static_cast<FxU16 *>(info.lfbPtr);
        const std::size_t stride = info.strideInBytes / 2;
        const std::size_t count = stride * static_cast<std::size_t>(ctx.display.height);
        const int writes = in.ConsumeIntegralInRange(0, 64);
        for (int i = 0; i < writes && count > 0; ++i)
          words[in.ConsumeIntegralInRange<std::size_t>(0, count - 1)] = in.ConsumeIntegral<FxU16>();
      } else if (locked) {
        const GlideContext &ctx = glide_shim::current();
        const auto *words = static_cast<const FxU16 *>(info.lfbPtr);
        const std::size_t count =
            info.strideInBytes / 2 * static_cast<std::size_t>(ctx.display.height);
        unsigned sum = 0;
        for (std::size_t i = 0; i < count; ++i) sum += words[i];  // every word must be readable
        (void)sum;
      }
      break;
    }
    case 37: {
      const GrLock_t type = enum_value(in, GR_LFB_READ_ONLY, GR_LFB_WRITE_ONLY);
      const GrBuffer_t buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_AUXBUFFER);
      checked("grLfbUnlock", [&] { grLfbUnlock(type, buffer); });
      break;
    }
    case 38: {
      // Any region, with a buffer of exactly stride x height: a correct shim refuses what does
      // not fit the screen before it writes a byte.
      const GrBuffer_t buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_AUXBUFFER);
      const auto side = static_cast<FxU32>(span);
      const FxU32 x = small_or_any(in, side), y = small_or_any(in, side);
      const FxU32 w = small_or_any(in, side + 1), h = small_or_any(in, side + 1);
      const FxU32 stride = in.ConsumeIntegralInRange<FxU32>(0, 2 * side + 8);
      std::vector<std::uint8_t> data(std::min<std::size_t>(
          static_cast<std::size_t>(stride) * std::min<FxU32>(h, 2 * side + 8), 1u << 20) + 1);
      checked("grLfbReadRegion", [&] { grLfbReadRegion(buffer, x, y, w, h, stride, data.data()); });
      break;
    }
    case 39: {
      const GrBuffer_t buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_AUXBUFFER);
      const GrLfbSrcFmt_t format = enum_value(in, GR_LFB_SRC_FMT_565, GR_LFB_SRC_FMT_ZA16);
      const auto side = static_cast<FxU32>(span);
      const FxU32 x = small_or_any(in, side), y = small_or_any(in, side);
      const FxU32 w = small_or_any(in, side + 1), h = small_or_any(in, side + 1);
      const FxI32 stride = in.ConsumeIntegralInRange<FxI32>(-4, static_cast<FxI32>(4 * side + 8));
      std::vector<std::uint8_t> data(std::min<std::size_t>(
          static_cast<std::size_t>(std::max<FxI32>(stride, 0)) * std::min<FxU32>(h, 2 * side + 8),
          1u << 20) + 1);
      checked("grLfbWriteRegion",
              [&] { grLfbWriteRegion(buffer, x, y, format, w, h, stride, data.data()); });
      break;
    }
    case 40:
      lfb_round_trip(in);
      break;
    case 41:
      texture_memory_round_trip(in);
      break;
    case 42: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8);
      const GrLOD_t lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      checked("glideShimRenderToTexture", [&] { glideShimRenderToTexture(tmu, address, lod); });
      break;
    }
    case 43:
      checked("glideShimRenderToFrameBuffer", [] { glideShimRenderToFrameBuffer(); });
      break;
    case 44:
      checked("glideShimBeginGL", [] { glideShimBeginGL(); });
      break;
    case 45:
      checked("glideShimEndGL", [] { glideShimEndGL(); });
      break;
    case 46:
      checked("grSstIdle", [] { grSstIdle(); });
      break;
    case 47:
    case 48:
      polygon(in, span);
      break;
    case 49: {
      const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
      const FxBool ab = boolean(in), bc = boolean(in), ca = boolean(in);
      checked("grAADrawTriangle", [&] { grAADrawTriangle(&a, &b, &c, ab, bc, ca); });
      break;
    }
    case 50: {
      const int mode = in.ConsumeBool() ? enum_value(in, GR_FOG_DISABLE, GR_FOG_WITH_ITERATED_Z)
                                        : in.ConsumeIntegral<int>();
      checked("grFogMode", [&] { grFogMode(mode); });
      const GrColor_t color = in.ConsumeIntegral<GrColor_t>();
      checked("grFogColorValue", [&] { grFogColorValue(color); });
      break;
    }
    case 51: {
      std::vector<GrFog_t> table = in.ConsumeBytes<GrFog_t>(GR_FOG_TABLE_SIZE);
      table.resize(GR_FOG_TABLE_SIZE);
      checked("grFogTable", [&] { grFogTable(table.data()); });
      break;
    }
    case 52: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const GrTexTable_t type = enum_value(in, GR_TEXTABLE_NCC0, GR_TEXTABLE_PALETTE);
      GuTexTable table{};  // the larger of a palette and an NCC table
      const std::vector<std::uint8_t> bytes = in.ConsumeBytes<std::uint8_t>(sizeof table);
      std::memcpy(&table, bytes.data(), bytes.size());
      checked("grTexDownloadTable", [&] { grTexDownloadTable(tmu, type, &table); });
      const GrNCCTable_t ncc = enum_value(in, GR_NCCTABLE_NCC0, GR_NCCTABLE_NCC1);
      checked("grTexNCCTable", [&] { grTexNCCTable(tmu, ncc); });
      break;
    }
    case 53: {
      const GrAlpha_t alpha = in.ConsumeIntegral<GrAlpha_t>();
      checked("grLfbConstantAlpha", [&] { grLfbConstantAlpha(alpha); });
      const FxU16 depth = in.ConsumeIntegral<FxU16>();
      checked("grLfbConstantDepth", [&] { grLfbConstantDepth(depth); });
      break;
    }
    case 54:
      state_round_trip();
      break;
    case 55: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int bias = enum_value(in, -32, 31);
      const FxU8 scale = in.ConsumeIntegral<FxU8>();
      const float max = coordinate(in, 1.0f);
      checked("grTexDetailControl", [&] { grTexDetailControl(tmu, bias, scale, max); });
      break;
    }
    case 56: {
      const FxBool enable = boolean(in);
      checked("grAlphaControlsITRGBLighting", [&] { grAlphaControlsITRGBLighting(enable); });
      break;
    }
    case 57: {
      const float a = coordinate(in, 255.0f), r = coordinate(in, 255.0f),
                  g = coordinate(in, 255.0f), b = coordinate(in, 255.0f);
      checked("grConstantColorValue4", [&] { grConstantColorValue4(a, r, g, b); });
      break;
    }
    case 58: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int function = enum_value(in, GR_TEXTURECOMBINE_ZERO, GR_TEXTURECOMBINE_ONE);
      checked("grTexCombineFunction", [&] { grTexCombineFunction(tmu, function); });
      break;
    }
    default:
      // Closing and reopening: every group goes back to grSstWinOpen's defaults.
      checked("grSstWinClose", [] { grSstWinClose(); });
      if (glide_shim::current().display.open) violated("grSstWinClose", "the window is still open");
      if (in.ConsumeBool()) open_window(in);
      break;
  }
}

bool g_started = false;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (!g_started) {
    grErrorSetCallback(on_error);
    g_started = true;
  }
  FuzzedDataProvider in(data, size);
  grGlideInit();
  glideShimClearError();
  if (!open_window(in)) {
    grGlideShutdown();
    return 0;
  }
  // Sides of the drawable area, for arguments near the screen's edges.
  const float span = static_cast<float>(std::max(glide_shim::current().display.width,
                                                 glide_shim::current().display.height));
  for (int calls = 0; calls < 32 && in.remaining_bytes() > 0; ++calls) one_call(in, span);
  grGlideShutdown();
  if (glide_shim::current().display.open || glide_shim::current().initialized)
    violated("grGlideShutdown", "the library is still open");
  return 0;
}

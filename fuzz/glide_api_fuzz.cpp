// glide_api_fuzz: decodes its input into a sequence of Glide 2.x calls with random arguments
// and after every call checks what must hold whatever the arguments were:
//   - a call that reported an error left every state group of the context as it was;
//   - an error is never reported without a message, and the callback saw the same message;
//   - the open window's groups stay in range (clip inside the target, TMU memory whole, LFB
//     copies the screen's size);
//   - round trips: 565 words written with grLfbWriteRegion read back unchanged,
//     grTexTextureMemRequired agrees with grTexCalcMemRequired for the same texture, restoring
//     grGlideGetState's block changes nothing, and grSstScreenWidth/Height give the window's size;
//   - a polygon with a vertex count far beyond its array (over 65,536) is refused unread;
//   - the gu texture manager never hands out memory past the TMU's end or an id twice.
// Any violation aborts, which libFuzzer reports as a crash with the input that caused it.
//
// Speed: one window (GL context) serves the whole run. Between inputs the context is reset to
// what grSstWinOpen loads (reset_window below), so the renderer and its compiled shaders are
// kept; only an input that asks for another window size, or that closes the window, pays for a
// new GL context. Every public entry point of glide.h, glideutl.h and glide_shim.h is called
// (entry point table in fuzz/README.md).
#include "context.h"
#include "gl/gl_renderer.h"

#include <fuzzer/FuzzedDataProvider.h>
#include <glide.h>
#include <glide_shim.h>
#include <glideutl.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
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
         a.large_lod == b.large_lod && a.aspect == b.aspect && a.format == b.format &&
         a.even_odd == b.even_odd;
}
bool same(const glide_shim::TextureTables &a, const glide_shim::TextureTables &b) {
  return std::memcmp(a.palette, b.palette, sizeof a.palette) == 0 &&
         std::memcmp(a.ncc, b.ncc, sizeof a.ncc) == 0 && a.ncc_select == b.ncc_select;
}
bool same(const glide_shim::TmuState &a, const glide_shim::TmuState &b) {
  return a.clamp_s == b.clamp_s && a.clamp_t == b.clamp_t && a.min_filter == b.min_filter &&
         a.mag_filter == b.mag_filter && a.mipmap_mode == b.mipmap_mode &&
         a.lod_blend == b.lod_blend && same(a.lod_bias, b.lod_bias) && a.combine == b.combine &&
         a.detail_bias == b.detail_bias && a.detail_scale == b.detail_scale &&
         a.detail_max == b.detail_max && same(a.source, b.source) &&
         a.allow_lod_dither == b.allow_lod_dither && a.lod_dither == b.lod_dither &&
         a.multibase == b.multibase && std::memcmp(a.base, b.base, sizeof a.base) == 0;
}
bool same(const glide_shim::FogState &a, const glide_shim::FogState &b) {
  return a.mode == b.mode && a.color == b.color &&
         std::memcmp(a.table, b.table, sizeof a.table) == 0;
}
bool same(const glide_shim::LfbWriteLayout &a, const glide_shim::LfbWriteLayout &b) {
  return a.color_format == b.color_format && a.swizzle_bytes == b.swizzle_bytes &&
         a.swap_words == b.swap_words;
}
bool same_bookkeeping(const glide_shim::GuTextureManager &a, const glide_shim::GuTextureManager &b) {
  return a.next_id == b.next_id && a.free_base == b.free_base && a.current == b.current &&
         a.ncc_owner[0] == b.ncc_owner[0] && a.ncc_owner[1] == b.ncc_owner[1] &&
         a.next_ncc_table == b.next_ncc_table;
}

// What a call may touch beyond the small groups, which every snapshot holds: TMU memory (2 MB)
// and the gu manager's records (1024 of them) are copied only before the calls that write
// them, and before every call of a "thorough" input (one in eight), to keep the run fast.
enum Touches : unsigned { kSmall = 0, kMemory = 1, kGuRecords = 2, kAll = 3 };
unsigned g_thorough = 0;  // kAll for a thorough input

struct Snapshot {
  bool initialized, plain_gl;
  glide_shim::ColorPathState color_path;
  glide_shim::BlendState blend;
  glide_shim::ChromaKeyState chroma;
  glide_shim::DepthState depth;
  glide_shim::RasterState raster;
  glide_shim::DisplayState display;
  glide_shim::TextureTarget texture_target;
  glide_shim::TmuState tmu;  // without its memory, which is `memory` below
  glide_shim::FogState fog;
  glide_shim::GuTextureManager gu;  // records only when kGuRecords
  GrMPState multipass;
  bool read_locked, write_locked;
  GrBuffer_t write_buffer;
  GrOriginLocation_t write_origin;
  GrLfbWriteMode_t write_mode;
  bool write_pipeline;
  glide_shim::LfbWriteLayout layout;
  GrAlpha_t constant_alpha;
  FxU16 constant_depth;
  std::vector<std::uint8_t> write_pixels;
  std::vector<std::uint8_t> memory;
  unsigned touches = kSmall;

  void take(GlideContext &ctx, unsigned what) {
    touches = what;
    initialized = ctx.initialized;
    plain_gl = ctx.plain_gl;
    color_path = ctx.color_path;
    blend = ctx.blend;
    chroma = ctx.chroma;
    depth = ctx.depth;
    raster = ctx.raster;
    display = ctx.display;
    texture_target = ctx.texture_target;
    // Every TMU field but the memory (swapped out and back: no copy).
    std::vector<std::uint8_t> held;
    held.swap(ctx.tmu.memory);
    tmu = ctx.tmu;
    ctx.tmu.memory.swap(held);
    if ((what & kMemory) != 0) memory.assign(ctx.tmu.memory.begin(), ctx.tmu.memory.end());
    fog = ctx.fog;
    std::vector<GrMipMapInfo> records;
    records.swap(ctx.gu_textures.records);
    gu = ctx.gu_textures;
    ctx.gu_textures.records.swap(records);
    if ((what & kGuRecords) != 0) gu.records = ctx.gu_textures.records;
    multipass = ctx.multipass;
    read_locked = ctx.lfb.read_locked, write_locked = ctx.lfb.write_locked;
    write_buffer = ctx.lfb.write_buffer, write_origin = ctx.lfb.write_origin;
    write_mode = ctx.lfb.write_mode, write_pipeline = ctx.lfb.write_pipeline;
    layout = ctx.lfb.layout;
    constant_alpha = ctx.lfb.constant_alpha, constant_depth = ctx.lfb.constant_depth;
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
    if (!same(tmu.tables, ctx.tmu.tables)) return "texture tables";
    if ((touches & kMemory) != 0 && memory != ctx.tmu.memory) return "TMU memory";
    if (!same(fog, ctx.fog)) return "fog";
    if (!same_bookkeeping(gu, ctx.gu_textures)) return "gu texture manager";
    if ((touches & kGuRecords) != 0 &&
        (gu.records.size() != ctx.gu_textures.records.size() ||
         (!gu.records.empty() && std::memcmp(gu.records.data(), ctx.gu_textures.records.data(),
                                             gu.records.size() * sizeof(GrMipMapInfo)) != 0)))
      return "gu mip map records";
    if (multipass.mmid[0] != ctx.multipass.mmid[0] || multipass.mmid[1] != ctx.multipass.mmid[1] ||
        multipass.tc_fnc != ctx.multipass.tc_fnc)
      return "multipass";
    if (read_locked != ctx.lfb.read_locked || write_locked != ctx.lfb.write_locked ||
        write_buffer != ctx.lfb.write_buffer || write_origin != ctx.lfb.write_origin ||
        write_mode != ctx.lfb.write_mode || write_pipeline != ctx.lfb.write_pipeline)
      return "LFB locks";
    if (!same(layout, ctx.lfb.layout) || constant_alpha != ctx.lfb.constant_alpha ||
        constant_depth != ctx.lfb.constant_depth)
      return "LFB write layout";
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

// Set when an input started the renderer's pixel counting (glideShimResetPixelsWritten), which
// nothing turns off: the next input then opens a new window instead of resetting this one.
bool g_renderer_counts = false;

// The size most inputs use, so that their GL context (and its compiled shaders) is the run's.
constexpr int kUsualWidth = 64, kUsualHeight = 48;

struct WindowRequest {
  int width, height;
  GrColorFormat_t format;
  GrOriginLocation_t origin;
  int color_buffers, aux_buffers;
  bool valid;
};

WindowRequest window_request(FuzzedDataProvider &in) {
  WindowRequest r{};
  // One input in 32 asks for a size of its own (a new GL context); the others share the run's.
  const bool own_size = in.ConsumeIntegralInRange(0, 31) == 0;
  r.width = own_size ? in.ConsumeIntegralInRange(1, 96) : kUsualWidth;
  r.height = own_size ? in.ConsumeIntegralInRange(1, 96) : kUsualHeight;
  // Valid arguments seven times in eight, so that most inputs get to their calls.
  const bool careless = in.ConsumeIntegralInRange(0, 7) == 0;
  r.format = careless ? enum_value(in, GR_COLORFORMAT_ARGB, GR_COLORFORMAT_BGRA)
                      : in.ConsumeIntegralInRange(GR_COLORFORMAT_ARGB, GR_COLORFORMAT_BGRA);
  r.origin = careless ? enum_value(in, GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT)
                      : in.ConsumeIntegralInRange(GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT);
  r.color_buffers = careless ? in.ConsumeIntegralInRange(1, 4) : in.ConsumeIntegralInRange(2, 3);
  r.aux_buffers = careless ? in.ConsumeIntegralInRange(-1, 2) : in.ConsumeIntegralInRange(0, 1);
  r.valid = r.format >= GR_COLORFORMAT_ARGB && r.format <= GR_COLORFORMAT_BGRA &&
            (r.origin == GR_ORIGIN_UPPER_LEFT || r.origin == GR_ORIGIN_LOWER_LEFT) &&
            r.color_buffers >= 2 && r.color_buffers <= 3 && r.aux_buffers >= 0 &&
            r.aux_buffers <= 1;
  return r;
}

// grSstWinOpen with the request's arguments, checking that it opens exactly when it should.
bool open_window(const WindowRequest &r) {
  if (!glideShimSetWindowSize(r.width, r.height)) violated("glideShimSetWindowSize", "a valid size was refused");
  const bool already_open = glide_shim::current().display.open;
  const FxBool opened = grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, r.format, r.origin,
                                     r.color_buffers, r.aux_buffers);
  if (opened && (!r.valid || already_open)) violated("grSstWinOpen", "bad arguments were accepted");
  if (!opened && r.valid && !already_open && glide_shim::current().initialized)
    violated("grSstWinOpen", glideShimGetLastErrorMessage());
  if (opened && (grTexMinAddress(GR_TMU0) != 0 || glide_shim::current().display.width != r.width ||
                 glide_shim::current().display.height != r.height))
    violated("grSstWinOpen", "the window is not the size asked for");
  return opened != FXFALSE;
}

// Ends what the previous input left begun (plain GL, rendering to a texture, LFB locks), so
// that its queued work is drawn before the state is reset.
void finish_previous_input() {
  GlideContext &ctx = glide_shim::current();
  if (!ctx.display.open) return;
  if (ctx.plain_gl) glideShimEndGL();
  if (ctx.texture_target.active) glideShimRenderToFrameBuffer();
  if (ctx.lfb.write_locked) grLfbUnlock(GR_LFB_WRITE_ONLY, ctx.lfb.write_buffer);
  if (ctx.lfb.read_locked) grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_FRONTBUFFER);
  ctx.flush();
}

// The state reset between inputs that keep the run's window: every group back to what
// grSstWinOpen loads (GlideContext::load_window_defaults, the same function grSstWinOpen calls),
// the renderer's decoded textures dropped (TMU memory is zero again), guMPInit's multipass
// state, and both colour buffers and the depth buffer cleared. The renderer itself, with its
// compiled shaders, stays.
void reset_window(const WindowRequest &r) {
  GlideContext &ctx = glide_shim::current();
  ctx.load_window_defaults(r.width, r.height, r.format, r.origin);
  ctx.renderer->textures().invalidate(0, glide_shim::kTmuMemoryBytes);
  guMPInit();
  grDepthMask(FXTRUE);
  for (const GrBuffer_t buffer : {GR_BUFFER_FRONTBUFFER, GR_BUFFER_BACKBUFFER}) {
    grRenderBuffer(buffer);
    grBufferClear(0, 0, 0xFFFF);
  }
  grDepthMask(FXFALSE);  // back to the defaults: no depth writes, drawing to the back buffer
  grRenderBuffer(GR_BUFFER_BACKBUFFER);
  ctx.flush();
}

// Gives the input a window as it asks: the run's, reset, when it has that size, else a new one.
// False when the input's (careless) arguments were refused and no window is open.
bool start_input(FuzzedDataProvider &in) {
  GlideContext &ctx = glide_shim::current();
  finish_previous_input();
  grErrorSetCallback(on_error);  // as set at start-up: the callback every check reads
  const WindowRequest r = window_request(in);
  if (!ctx.initialized) grGlideInit();
  const bool reusable = ctx.display.open && ctx.display.width == r.width &&
                        ctx.display.height == r.height && !g_renderer_counts;
  g_renderer_counts = false;
  if (reusable) {
    if (!r.valid) {
      // Careless arguments with the window open: refused as "already open".
      if (open_window(r)) violated("grSstWinOpen", "opened a second window");
    }
    WindowRequest usable = r;
    if (!r.valid) usable.format = GR_COLORFORMAT_ARGB, usable.origin = GR_ORIGIN_UPPER_LEFT;
    if (!glideShimSetWindowSize(r.width, r.height)) violated("glideShimSetWindowSize", "a valid size was refused");
    reset_window(usable);
    glideShimClearError();
    return true;
  }
  if (ctx.display.open) grSstWinClose();
  glideShimClearError();
  return open_window(r);
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
  const glide_shim::GuTextureManager &gu = ctx.gu_textures;
  if (gu.free_base > glide_shim::kTmuMemoryBytes || gu.next_id > MAX_MIPMAPS_PER_SST ||
      gu.records.size() != MAX_MIPMAPS_PER_SST)
    violated(call, "the gu texture manager's bookkeeping is out of range");
  if (gu.current != GR_NULL_MIPMAP_HANDLE && gu.current >= gu.next_id)
    violated(call, "the current gu mip map was never allocated");
}

// Runs one call: clears the last error, snapshots the state, calls, then checks. `touches`
// says which large groups the call may write (Touches), for the snapshot to hold them too.
Snapshot g_before;  // reused, so that its buffers are allocated once

template <typename Call>
void checked(const char *name, unsigned touches, Call &&call) {
  GlideContext &ctx = glide_shim::current();
  glideShimClearError();
  g_callback_count = 0;
  g_before.take(ctx, touches | g_thorough);
  call();
  const GlideShimError error = glideShimGetLastError();
  const std::string message = glideShimGetLastErrorMessage();
  if (error != GLIDESHIM_OK) {
    if (message.empty()) violated(name, "an error was reported without a message");
    if (g_callback_count == 0 || g_callback_message != message)
      violated(name, "the error callback did not get the error's message");
    if (error == GLIDESHIM_ERR_OUT_OF_MEMORY || error == GLIDESHIM_ERR_INTERNAL)
      violated(name, ("an exception was caught: " + message).c_str());
    if (const char *group = g_before.differs(ctx)) {
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

template <typename Call>
void checked(const char *name, Call &&call) {
  checked(name, kSmall, call);
}

// ---- the calls ---------------------------------------------------------------------------

void lfb_round_trip(FuzzedDataProvider &in) {
  const GlideContext &ctx = glide_shim::current();
  if (!ctx.display.open || ctx.plain_gl || ctx.lfb.write_locked || ctx.texture_target.active) return;
  // Byte swizzle and word swap (grLfbWriteColorSwizzle) move written 565 words on purpose, and
  // ABGR or BGRA lanes (grLfbWriteColorFormat) read their red and blue fields swapped.
  const glide_shim::LfbWriteLayout &layout = ctx.lfb.layout;
  if (layout.swizzle_bytes || layout.swap_words || layout.color_format == GR_COLORFORMAT_ABGR ||
      layout.color_format == GR_COLORFORMAT_BGRA)
    return;
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
  GlideContext &ctx = glide_shim::current();
  if (!ctx.display.open || ctx.plain_gl) return;
  GrState first{}, second{};
  checked("grGlideGetState", [&] { grGlideGetState(&first); });
  Snapshot before;
  before.take(ctx, kSmall);
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

// ---- the calls the original menu lacked: every other public entry point -----------------

std::string g_scratch;  // a directory of the build tree for the files calls read and write
GrState g_saved_state;  // grGlideGetState's block from earlier in this input
bool g_have_saved_state = false;

const char *const kFormatLines[] = {"rgb565", "argb1555", "argb4444", "i8",  "a8",   "ai44", "yiq",
                                    "rgb332", "argb8332", "ayiq8422", "ai88", "p8", "ap88", "bogus"};

// Bytes for a .3df file: mostly a plausible header (any format, LOD range and aspect) followed
// by fuzzed bytes, sometimes only fuzzed bytes.
std::string three_df_bytes(FuzzedDataProvider &in) {
  std::string text;
  if (in.ConsumeIntegralInRange(0, 7) != 0) {
    const int small_side = 1 << in.ConsumeIntegralInRange(0, 9);
    const int large_side = 1 << in.ConsumeIntegralInRange(0, 9);
    text = std::string(in.ConsumeBool() ? "3df v1.1\n" : "3df v1.0\n") +
           kFormatLines[in.ConsumeIntegralInRange<std::size_t>(0, 13)] + "\nlod range: " +
           std::to_string(small_side) + " " + std::to_string(large_side) + "\naspect ratio: " +
           std::to_string(1 << in.ConsumeIntegralInRange(0, 4)) + " " +
           std::to_string(1 << in.ConsumeIntegralInRange(0, 4)) + "\n";
  }
  const std::size_t body = in.ConsumeIntegralInRange<std::size_t>(0, 4096);
  const std::vector<std::uint8_t> bytes = in.ConsumeBytes<std::uint8_t>(std::min<std::size_t>(body, 256));
  for (std::size_t i = 0; i < body; ++i)
    text.push_back(static_cast<char>(bytes.empty() ? i : bytes[i % bytes.size()]));
  return text;
}

void three_df(FuzzedDataProvider &in) {
  const std::string path = g_scratch + "/input.3df";
  const std::string bytes = three_df_bytes(in);
  if (FILE *file = std::fopen(path.c_str(), "wb")) {
    std::fwrite(bytes.data(), 1, bytes.size(), file);
    std::fclose(file);
  }
  const bool missing = in.ConsumeIntegralInRange(0, 15) == 0;
  const std::string name = missing ? g_scratch + "/no_such.3df" : path;
  Gu3dfInfo info{};
  FxBool ok = FXFALSE;
  checked("gu3dfGetInfo", [&] { ok = gu3dfGetInfo(in.ConsumeIntegralInRange(0, 31) == 0 ? nullptr : name.c_str(), &info); });
  if (!ok) return;
  if (info.mem_required > (1u << 20)) violated("gu3dfGetInfo", "mem_required is beyond any .3df chain");
  std::vector<std::uint8_t> data(info.mem_required + 1);
  info.data = data.data();
  checked("gu3dfLoad", [&] { ok = gu3dfLoad(name.c_str(), &info); });
  if (ok && info.data != data.data()) violated("gu3dfLoad", "moved the caller's data pointer");
  // Download what was loaded, as a program would.
  if (ok) {
    GrTexInfo tex{info.header.small_lod, info.header.large_lod, info.header.aspect_ratio,
                  info.header.format, info.data};
    checked("grTexDownloadMipMap", kMemory,
            [&] { grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &tex); });
  }
}

// An RLE bitmap as ConvertAndDownloadRle reads it: 4 skipped bytes, one length byte per row,
// then the rows, each normally ending in a run of 0 (with a corrupt row now and then).
std::vector<FxU8> rle_bitmap(FuzzedDataProvider &in, long rows) {
  std::vector<std::vector<FxU8>> row_bytes(static_cast<std::size_t>(rows));
  for (auto &row : row_bytes) {
    const int codes = in.ConsumeIntegralInRange(0, 12);
    for (int i = 0; i < codes; ++i) {
      if (in.ConsumeBool()) {
        row.push_back(static_cast<FxU8>(0xE0 | in.ConsumeIntegralInRange(1, 31)));
        row.push_back(in.ConsumeIntegral<FxU8>());
      } else {
        row.push_back(static_cast<FxU8>(in.ConsumeIntegralInRange(0, 0xDF)));
      }
    }
    if (in.ConsumeIntegralInRange(0, 15) != 0) row.push_back(0xE0);  // the end code
    if (row.size() > 255) row.resize(255);
  }
  std::vector<FxU8> bitmap(4, 0);
  for (const auto &row : row_bytes) bitmap.push_back(static_cast<FxU8>(row.size()));
  for (const auto &row : row_bytes) bitmap.insert(bitmap.end(), row.begin(), row.end());
  return bitmap;
}

// A gu mip map id: mostly one the manager handed out, sometimes any value.
GrMipMapId_t mip_map_id(FuzzedDataProvider &in) {
  const FxU32 next = glide_shim::current().gu_textures.next_id;
  if (next > 0 && in.ConsumeIntegralInRange(0, 7) != 0) return in.ConsumeIntegralInRange<FxU32>(0, next - 1);
  return in.ConsumeBool() ? GR_NULL_MIPMAP_HANDLE : small_or_any(in, MAX_MIPMAPS_PER_SST + 2);
}

// The host bytes of mip map `id`'s whole chain, or 0 when it is no allocated id.
std::size_t mip_map_bytes(GrMipMapId_t id) {
  const GlideContext &ctx = glide_shim::current();
  if (id >= ctx.gu_textures.next_id || id >= ctx.gu_textures.records.size()) return 0;
  const GrMipMapInfo &r = ctx.gu_textures.records[id];
  return host_chain_bytes(r.lod_min, r.lod_max, r.aspect_ratio, r.format);
}

void gu_allocate(FuzzedDataProvider &in) {
  const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
  const FxU8 mask = static_cast<FxU8>(small_or_any(in, 4));
  GrTexInfo info = texture_info(in);
  const int mm = enum_value(in, GR_MIPMAP_DISABLE, GR_MIPMAP_NEAREST_DITHER);
  const int s = enum_value(in, 0, 1), t = enum_value(in, 0, 1);
  const int min = enum_value(in, 0, 1), mag = enum_value(in, 0, 1);
  const float bias = coordinate(in, 8.0f);
  const FxBool trilinear = boolean(in);
  const FxU32 free_before = glide_shim::current().gu_textures.free_base;
  GrMipMapId_t id = GR_NULL_MIPMAP_HANDLE;
  checked("guTexAllocateMemory", kGuRecords, [&] {
    id = guTexAllocateMemory(tmu, mask, 256, 256, info.format, mm, info.smallLod, info.largeLod,
                             info.aspectRatio, s, t, min, mag, bias, trilinear);
  });
  const GlideContext &ctx = glide_shim::current();
  if (id != GR_NULL_MIPMAP_HANDLE) {
    if (id >= ctx.gu_textures.next_id) violated("guTexAllocateMemory", "an id beyond the manager's count");
    if (ctx.gu_textures.free_base <= free_before || ctx.gu_textures.free_base > glide_shim::kTmuMemoryBytes)
      violated("guTexAllocateMemory", "the free pointer did not advance inside TMU memory");
  }
}

void gu_change(FuzzedDataProvider &in) {
  const GrMipMapId_t id = mip_map_id(in);
  auto keep_or = [&](int lo, int hi) { return in.ConsumeBool() ? -1 : enum_value(in, lo, hi); };
  const int width = keep_or(1, 256), height = keep_or(1, 256);
  const int fmt = keep_or(GR_TEXFMT_8BIT, GR_TEXFMT_RSVD2);
  const int mm = keep_or(GR_MIPMAP_DISABLE, GR_MIPMAP_NEAREST_DITHER);
  const int small = keep_or(GR_LOD_256, GR_LOD_1), large = keep_or(GR_LOD_256, GR_LOD_1);
  const int aspect = keep_or(GR_ASPECT_8x1, GR_ASPECT_1x8);
  const int s = keep_or(0, 1), t = keep_or(0, 1), min = keep_or(0, 1), mag = keep_or(0, 1);
  checked("guTexChangeAttributes", kGuRecords, [&] {
    guTexChangeAttributes(id, width, height, fmt, mm, small, large, aspect, s, t, min, mag);
  });
}

void gu_download(FuzzedDataProvider &in) {
  const GrMipMapId_t id = mip_map_id(in);
  std::vector<std::uint8_t> data = texel_data(in, mip_map_bytes(id));
  GuNccTable table{};
  const std::vector<std::uint8_t> bytes = in.ConsumeBytes<std::uint8_t>(sizeof table);
  if (!bytes.empty()) std::memcpy(&table, bytes.data(), bytes.size());
  const bool null_data = in.ConsumeIntegralInRange(0, 15) == 0;
  const bool null_table = in.ConsumeIntegralInRange(0, 7) == 0;
  if (in.ConsumeBool()) {
    checked("guTexDownloadMipMap", kAll, [&] {
      guTexDownloadMipMap(id, null_data ? nullptr : data.data(), null_table ? nullptr : &table);
    });
    return;
  }
  // One level at a time, as the caller's pointer advances.
  const GrLOD_t lod = enum_value(in, GR_LOD_256, GR_LOD_1);
  const GlideContext &ctx = glide_shim::current();
  std::vector<std::uint8_t> level;
  if (id < ctx.gu_textures.next_id) {
    const GrMipMapInfo &r = ctx.gu_textures.records[id];
    level = texel_data(in, host_chain_bytes(lod, lod, r.aspect_ratio, r.format));
  } else {
    level = texel_data(in, 0);
  }
  const void *src = null_data ? nullptr : level.data();
  checked("guTexDownloadMipMapLevel", kAll, [&] { guTexDownloadMipMapLevel(id, lod, &src); });
}

void lfb_layout(FuzzedDataProvider &in) {
  const FxBool swizzle = boolean(in), swap = boolean(in);
  checked("grLfbWriteColorSwizzle", [&] { grLfbWriteColorSwizzle(swizzle, swap); });
  const int format = enum_value(in, GR_COLORFORMAT_ARGB, GR_COLORFORMAT_BGRA);
  checked("grLfbWriteColorFormat", [&] { grLfbWriteColorFormat(format); });
}

void getters() {
  const GlideContext &ctx = glide_shim::current();
  int pending = -1;
  FxU32 status = 0, line = 1, width = 0, height = 0;
  FxBool busy = FXTRUE, retrace = FXFALSE;
  checked("grBufferNumPending", [&] { pending = grBufferNumPending(); });
  checked("grSstIsBusy", [&] { busy = grSstIsBusy(); });
  checked("grSstStatus", [&] { status = grSstStatus(); });
  checked("grSstVideoLine", [&] { line = grSstVideoLine(); });
  checked("grSstVRetraceOn", [&] { retrace = grSstVRetraceOn(); });
  checked("grSstScreenWidth", [&] { width = grSstScreenWidth(); });
  checked("grSstScreenHeight", [&] { height = grSstScreenHeight(); });
  if (ctx.display.open && !ctx.plain_gl) {
    if (pending < 0 || busy != FXFALSE || retrace == FXFALSE || line != 0 || (status & 0x3F) != 0x3F)
      violated("the status queries", "an idle board reported work or no retrace");
    if (width != static_cast<FxU32>(ctx.display.width) || height != static_cast<FxU32>(ctx.display.height))
      violated("grSstScreenWidth", "disagrees with the window");
  }
}

void multipass(FuzzedDataProvider &in, float span) {
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0:
      checked("guMPInit", [] { guMPInit(); });
      break;
    case 1: {
      const FxU32 function = small_or_any(in, GR_MPTEXTURECOMBINE_SUBTRACT + 1);
      checked("guMPTexCombineFunction", [&] { guMPTexCombineFunction(function); });
      break;
    }
    case 2: {
      const GrChipID_t tmu = enum_value(in, 0, 1);
      const GrMipMapId_t id = mip_map_id(in);
      checked("guMPTexSource", kGuRecords, [&] { guMPTexSource(tmu, id); });
      break;
    }
    default: {
      const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
      checked("guMPDrawTriangle", [&] { guMPDrawTriangle(&a, &b, &c); });
      break;
    }
  }
}

// Closing the window (or the library) and opening it again: the costly path of a new GL
// context, taken rarely so that the run stays fast.
void close_and_reopen(FuzzedDataProvider &in) {
  if (in.ConsumeIntegralInRange(0, 7) != 0) return;
  if (in.ConsumeBool()) {
    checked("grSstWinClose", [] { grSstWinClose(); });
    if (glide_shim::current().display.open) violated("grSstWinClose", "the window is still open");
  } else {
    checked("grGlideShutdown", [] { grGlideShutdown(); });
    if (glide_shim::current().display.open || glide_shim::current().initialized)
      violated("grGlideShutdown", "the library is still open");
    // Calls with no library open are refused, and change nothing.
    FxU32 width = 1;
    checked("grSstScreenWidth", [&] { width = grSstScreenWidth(); });
    if (width != 0) violated("grSstScreenWidth", "a size with no window open");
    checked("grGlideInit", [] { grGlideInit(); });
  }
  if (in.ConsumeBool()) {
    WindowRequest r = window_request(in);
    open_window(r);
  }
}

// A textured triangle as a program draws one: a valid mip map downloaded and made the source,
// a texture combine and colour combine that read it, random filtering, clamping and mip-mapping,
// so that draws go through the texture cache and every format's decoding.
void textured_draw(FuzzedDataProvider &in, float span) {
  static constexpr GrTextureFormat_t kFormats[] = {
      GR_TEXFMT_RGB_332,   GR_TEXFMT_YIQ_422,   GR_TEXFMT_ALPHA_8,          GR_TEXFMT_INTENSITY_8,
      GR_TEXFMT_ALPHA_INTENSITY_44, GR_TEXFMT_P_8, GR_TEXFMT_ARGB_8332,     GR_TEXFMT_AYIQ_8422,
      GR_TEXFMT_RGB_565,   GR_TEXFMT_ARGB_1555, GR_TEXFMT_ARGB_4444, GR_TEXFMT_ALPHA_INTENSITY_88,
      GR_TEXFMT_AP_88};
  GrTexInfo info{};
  info.largeLod = in.ConsumeIntegralInRange(GR_LOD_256, GR_LOD_1);
  info.smallLod = in.ConsumeIntegralInRange(info.largeLod, GR_LOD_1);
  info.aspectRatio = in.ConsumeIntegralInRange(GR_ASPECT_8x1, GR_ASPECT_1x8);
  info.format = kFormats[in.ConsumeIntegralInRange<std::size_t>(0, 12)];
  std::vector<std::uint8_t> data =
      texel_data(in, host_chain_bytes(info.smallLod, info.largeLod, info.aspectRatio, info.format));
  info.data = data.data();
  const FxU32 address = in.ConsumeIntegralInRange<FxU32>(0, 15) * 65536u;
  checked("grTexDownloadMipMap", kMemory,
          [&] { grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info); });
  checked("grTexSource", [&] { grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info); });
  const int texture_combine = in.ConsumeIntegralInRange(GR_TEXTURECOMBINE_DECAL, GR_TEXTURECOMBINE_ONE);
  checked("guTexCombineFunction", [&] { guTexCombineFunction(GR_TMU0, texture_combine); });
  const int color_combine = in.ConsumeIntegralInRange(GR_COLORCOMBINE_DECAL_TEXTURE,
                                                      GR_COLORCOMBINE_TEXTURE_TIMES_ALPHA_ADD_ITRGB);
  checked("guColorCombineFunction", [&] { guColorCombineFunction(color_combine); });
  const int filter = in.ConsumeIntegralInRange(0, 1), clamp = in.ConsumeIntegralInRange(0, 1);
  checked("grTexFilterMode", [&] { grTexFilterMode(GR_TMU0, filter, filter); });
  checked("grTexClampMode", [&] { grTexClampMode(GR_TMU0, clamp, clamp); });
  const int mipmap = in.ConsumeIntegralInRange(GR_MIPMAP_DISABLE, GR_MIPMAP_NEAREST_DITHER);
  checked("grTexMipMapMode", [&] { grTexMipMapMode(GR_TMU0, mipmap, FXFALSE); });
  const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
  checked("grDrawTriangle", [&] { grDrawTriangle(&a, &b, &c); });
}

void more_calls(FuzzedDataProvider &in, float span) {
  GlideContext &ctx = glide_shim::current();
  switch (in.ConsumeIntegralInRange(0, 42)) {
    case 0: {
      const GrVertex v = vertex(in, span);
      checked("grAADrawPoint", [&] { grAADrawPoint(in.ConsumeIntegralInRange(0, 31) == 0 ? nullptr : &v); });
      break;
    }
    case 1: {
      const GrVertex a = vertex(in, span), b = vertex(in, span);
      checked("grAADrawLine", [&] { grAADrawLine(&a, &b); });
      break;
    }
    case 2: {
      const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
      checked("guAADrawTriangleWithClip", [&] { guAADrawTriangleWithClip(&a, &b, &c); });
      break;
    }
    case 3:
      getters();
      break;
    case 4: {
      GrHwConfiguration config{};
      const bool null = in.ConsumeIntegralInRange(0, 7) == 0;
      checked("grSstQueryBoards", [&] { grSstQueryBoards(null ? nullptr : &config); });
      checked("grSstQueryHardware", [&] { grSstQueryHardware(null ? nullptr : &config); });
      break;
    }
    case 5: {
      const int board = enum_value(in, 0, 0);
      checked("grSstSelect", [&] { grSstSelect(board); });
      break;
    }
    case 6: {
      const FxU32 code = small_or_any(in, GR_CONTROL_MOVE + 1);
      checked("grSstControl", [&] { grSstControl(code); });
      break;
    }
    case 7: {
      const GrChipID_t chip = enum_value(in, GR_TMU0, GR_FBI);
      const int reg = in.ConsumeIntegral<int>();
      const FxU32 value = in.ConsumeIntegral<FxU32>();
      checked("grSstConfigPipeline", [&] { grSstConfigPipeline(chip, reg, value); });
      break;
    }
    case 8: {
      GrSstPerfStats_t stats{};
      const bool null = in.ConsumeIntegralInRange(0, 7) == 0;
      checked("grSstPerfStats", [&] { grSstPerfStats(null ? nullptr : &stats); });
      if (in.ConsumeBool()) checked("grSstResetPerfStats", [] { grSstResetPerfStats(); });
      break;
    }
    case 9: {
      FxU32 processed = 0, drawn = 0;
      checked("grTriStats", [&] { grTriStats(&processed, &drawn); });
      if (drawn > processed) violated("grTriStats", "more triangles drawn than processed");
      if (in.ConsumeBool()) checked("grResetTriStats", [] { grResetTriStats(); });
      break;
    }
    case 10:
      checked("grDisableAllEffects", [] { grDisableAllEffects(); });
      break;
    case 11: {
      char version[80];
      checked("grGlideGetVersion", [&] { grGlideGetVersion(in.ConsumeIntegralInRange(0, 15) == 0 ? nullptr : version); });
      const float x = coordinate(in, span), y = coordinate(in, span);
      checked("grSplash", [&] { grSplash(x, y, span, span, in.ConsumeIntegral<FxU32>()); });
      checked("grGlideShamelessPlug", [&] { grGlideShamelessPlug(boolean(in)); });
      checked("grCheckForRoom", [&] { grCheckForRoom(in.ConsumeIntegral<FxI32>()); });
      break;
    }
    case 12: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxBool enable = boolean(in);
      checked("grTexMultibase", [&] { grTexMultibase(tmu, enable); });
      break;
    }
    case 13: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int range = enum_value(in, GR_TEXBASE_256, GR_TEXBASE_32_TO_1);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8) & ~7u;
      const FxU32 even_odd = small_or_any(in, 4);
      GrTexInfo info = texture_info(in);
      const bool null_info = in.ConsumeIntegralInRange(0, 15) == 0;
      checked("grTexMultibaseAddress",
              [&] { grTexMultibaseAddress(tmu, range, address, even_odd, null_info ? nullptr : &info); });
      break;
    }
    case 14: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8);
      const GrLOD_t this_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrLOD_t large_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrAspectRatio_t aspect = enum_value(in, GR_ASPECT_8x1, GR_ASPECT_1x8);
      const GrTextureFormat_t format = enum_value(in, GR_TEXFMT_8BIT, GR_TEXFMT_RSVD2);
      const FxU32 even_odd = small_or_any(in, 4);
      const int start = in.ConsumeIntegralInRange(-1, 257), end = in.ConsumeIntegralInRange(-1, 257);
      // The whole level: rows start..end of it are read from the pointer's first row.
      std::vector<std::uint8_t> data = texel_data(in, host_chain_bytes(this_lod, this_lod, aspect, format));
      checked("grTexDownloadMipMapLevelPartial", kMemory, [&] {
        grTexDownloadMipMapLevelPartial(tmu, address, this_lod, large_lod, aspect, format,
                                        even_odd, data.data(), start, end);
      });
      break;
    }
    case 15: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const GrTexTable_t type = enum_value(in, GR_TEXTABLE_NCC0, GR_TEXTABLE_PALETTE);
      GuTexTable table{};
      const std::vector<std::uint8_t> bytes = in.ConsumeBytes<std::uint8_t>(sizeof table);
      if (!bytes.empty()) std::memcpy(&table, bytes.data(), bytes.size());
      const int start = in.ConsumeIntegralInRange(-1, 257), end = in.ConsumeIntegralInRange(-1, 257);
      checked("grTexDownloadTablePartial", [&] { grTexDownloadTablePartial(tmu, type, &table, start, end); });
      break;
    }
    case 16: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8) & ~7u;
      const GrLOD_t this_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrLOD_t large_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrAspectRatio_t aspect = enum_value(in, GR_ASPECT_8x1, GR_ASPECT_1x8);
      const GrTextureFormat_t format = enum_value(in, GR_TEXFMT_8BIT, GR_TEXFMT_RSVD2);
      const FxU32 even_odd = small_or_any(in, 4);
      const long rows = in.ConsumeIntegralInRange<long>(0, 8);
      std::vector<FxU8> bitmap = rle_bitmap(in, rows);
      const long bm_h = in.ConsumeIntegralInRange(0, 15) == 0 ? in.ConsumeIntegralInRange<long>(-2, 300) : rows;
      const FxU32 u0 = small_or_any(in, 16), v0 = small_or_any(in, 8);
      const FxU32 width = small_or_any(in, 32), height = small_or_any(in, 8);
      const FxU32 dest_width = small_or_any(in, 257), dest_height = small_or_any(in, 9);
      std::vector<FxU16> tlut(256);
      for (std::size_t i = 0; i < tlut.size(); ++i) tlut[i] = static_cast<FxU16>(i * 0x0821u);
      // A bitmap height beyond its rows would make the shim read rows that do not exist (the
      // C API cannot tell), so only fewer rows than written are claimed.
      const long claimed = std::min(bm_h, rows);
      checked("ConvertAndDownloadRle", kMemory, [&] {
        ConvertAndDownloadRle(tmu, address, this_lod, large_lod, aspect, format, even_odd,
                              bitmap.data(), claimed, u0, v0, width, height, dest_width,
                              dest_height, tlut.data());
      });
      break;
    }
    case 17:
    case 18:
      gu_allocate(in);
      break;
    case 19:
      gu_change(in);
      break;
    case 20:
    case 21:
      gu_download(in);
      break;
    case 22: {
      const GrMipMapId_t id = mip_map_id(in);
      checked("guTexSource", kGuRecords, [&] { guTexSource(id); });
      break;
    }
    case 23: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const GrMipMapId_t id = mip_map_id(in);
      GrMipMapId_t current = 0;
      GrMipMapInfo *info = nullptr;
      FxU32 avail = 0;
      checked("guTexGetCurrentMipMap", [&] { current = guTexGetCurrentMipMap(tmu); });
      checked("guTexGetMipMapInfo", [&] { info = guTexGetMipMapInfo(id); });
      checked("guTexMemQueryAvail", [&] { avail = guTexMemQueryAvail(tmu); });
      if (ctx.display.open && !ctx.plain_gl && tmu == GR_TMU0) {
        if (avail + ctx.gu_textures.free_base != glide_shim::kTmuMemoryBytes)
          violated("guTexMemQueryAvail", "free memory and the free pointer do not add up");
        if (current != ctx.gu_textures.current) violated("guTexGetCurrentMipMap", "not the current id");
      }
      // An id of the table not allocated yet gives its empty record, as the driver's does.
      if (info != nullptr && id >= ctx.gu_textures.next_id && info->valid != FXFALSE)
        violated("guTexGetMipMapInfo", "a valid record for an id never allocated");
      break;
    }
    case 24:
      checked("guTexMemReset", kGuRecords, [] { guTexMemReset(); });
      break;
    case 25:
      lfb_layout(in);
      break;
    case 26: {
      // RLE16 of a small image: first the size (dst NULL), then into a buffer of that size.
      const FxU32 width = in.ConsumeIntegralInRange<FxU32>(0, 24);
      const FxU32 height = in.ConsumeIntegralInRange<FxU32>(0, 24);
      std::vector<FxU16> image(static_cast<std::size_t>(width) * height + 1);
      const FxU16 a = in.ConsumeIntegral<FxU16>(), b = in.ConsumeIntegral<FxU16>();
      for (std::size_t i = 0; i < image.size(); ++i) image[i] = in.ConsumeBool() ? a : b;
      int bytes = -1;
      checked("guEncodeRLE16", [&] { bytes = guEncodeRLE16(nullptr, image.data(), width, height); });
      if (bytes < 0 || static_cast<std::size_t>(bytes) > 4 * (image.size() - 1))
        violated("guEncodeRLE16", "more bytes than one run per pixel");
      std::vector<std::uint8_t> out(static_cast<std::size_t>(bytes) + 1);
      int again = -1;
      checked("guEncodeRLE16", [&] { again = guEncodeRLE16(out.data(), image.data(), width, height); });
      if (again != bytes) violated("guEncodeRLE16", "counting and encoding disagree");
      checked("guEncodeRLE16", [&] { guEncodeRLE16(nullptr, nullptr, width, height); });
      break;
    }
    case 27: {
      FxU16 *mipmap = nullptr;
      checked("guTexCreateColorMipMap", [&] { mipmap = guTexCreateColorMipMap(); });
      if (mipmap == nullptr) violated("guTexCreateColorMipMap", "no mip map");
      GrTexInfo info{GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, mipmap};
      if (in.ConsumeBool())
        checked("grTexDownloadMipMap", kMemory,
                [&] { grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info); });
      std::free(mipmap);
      break;
    }
    case 28: {
      GrFog_t table[GR_FOG_TABLE_SIZE];
      float w = 0.0f;
      checked("guFogTableIndexToW", [&] { w = guFogTableIndexToW(in.ConsumeIntegralInRange(-2, 66)); });
      (void)w;
      const float density = coordinate(in, 1.0f);
      switch (in.ConsumeIntegralInRange(0, 2)) {
        case 0: checked("guFogGenerateExp", [&] { guFogGenerateExp(table, density); }); break;
        case 1: checked("guFogGenerateExp2", [&] { guFogGenerateExp2(table, density); }); break;
        default: {
          const float near_z = coordinate(in, 1000.0f), far_z = coordinate(in, 1000.0f);
          checked("guFogGenerateLinear", [&] { guFogGenerateLinear(table, near_z, far_z); });
          break;
        }
      }
      if (glideShimGetLastError() == GLIDESHIM_OK) checked("grFogTable", [&] { grFogTable(table); });
      break;
    }
    case 29: {
      const FxU32 word = in.ConsumeIntegral<FxU32>();
      const FxU16 half = in.ConsumeIntegral<FxU16>();
      FxU32 swapped = 0;
      FxU16 swapped_half = 0;
      checked("guEndianSwapWords", [&] { swapped = guEndianSwapWords(word); });
      checked("guEndianSwapBytes", [&] { swapped_half = guEndianSwapBytes(half); });
      if (guEndianSwapWords(swapped) != word || guEndianSwapBytes(swapped_half) != half)
        violated("guEndianSwap*", "swapping twice is not the identity");
      break;
    }
    case 30:
    case 31:
      multipass(in, span);
      break;
    case 32: {
      std::vector<FxU16> pixels(16 * 16);
      const int x = in.ConsumeIntegral<int>(), y = in.ConsumeIntegral<int>();
      checked("guFbReadRegion", [&] { guFbReadRegion(x, y, 16, 16, pixels.data(), 32); });
      checked("guFbWriteRegion", [&] { guFbWriteRegion(x, y, 16, 16, pixels.data(), 32); });
      checked("guMovieSetName", [&] { guMovieSetName(in.ConsumeBool() ? nullptr : "movie"); });
      checked("guMovieStart", [] { guMovieStart(); });
      checked("guMovieStop", [] { guMovieStop(); });
      break;
    }
    case 33:
      three_df(in);
      break;
    case 34: {
      int key = -1;
      FxBool closed = FXTRUE;
      checked("glideShimPollKey", [&] { key = glideShimPollKey(); });
      checked("glideShimWindowClosed", [&] { closed = glideShimWindowClosed(); });
      if (key != 0 || closed != FXFALSE) violated("glideShimPollKey", "keys or a close request headless");
      const char *backend = nullptr;
      checked("glideShimBackendName", [&] { backend = glideShimBackendName(); });
      if (backend == nullptr) violated("glideShimBackendName", "NULL");
      static const char *const kNames[] = {"glClear", "glDrawArrays", "glNoSuchFunction", "", nullptr};
      const char *name = kNames[in.ConsumeIntegralInRange(0, 4)];
      checked("glideShimGetProcAddress", [&] { glideShimGetProcAddress(name); });
      // Values past the last kind give "unknown"; only 0..15 fit the C++ enum's range (a C
      // caller's -1 would be undefined on the C++ side, before any code of the shim runs).
      const char *error_name = glideShimErrorName(static_cast<GlideShimError>(in.ConsumeIntegralInRange(0, 15)));
      if (error_name == nullptr || *error_name == '\0') violated("glideShimErrorName", "no name");
      break;
    }
    case 35: {
      // A PNG of a colour buffer (rare: it loads OpenImageIO), to a file, a directory or NULL.
      if (in.ConsumeIntegralInRange(0, 7) != 0) break;
      const GrBuffer_t buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_AUXBUFFER);
      const int where = in.ConsumeIntegralInRange(0, 3);
      const std::string path = where == 0 ? g_scratch : g_scratch + "/frame.png";
      checked("glideShimWritePng", [&] { glideShimWritePng(buffer, where == 1 ? nullptr : path.c_str()); });
      break;
    }
    case 36: {
      FxU32 pixels = 0;
      checked("glideShimPixelsWritten", [&] { pixels = glideShimPixelsWritten(); });
      (void)pixels;
      // Counting makes every later flush of the renderer wait for an occlusion query, and no
      // call stops it: rare, and the next input gets a new GL context.
      if (in.ConsumeIntegralInRange(0, 15) == 0) {
        checked("glideShimResetPixelsWritten", [] { glideShimResetPixelsWritten(); });
        g_renderer_counts = true;
      }
      break;
    }
    case 37:
      // Save now, restore later in the same input (after other changes): the restored groups
      // must be the saved ones, which saving again shows byte for byte.
      if (!g_have_saved_state || in.ConsumeBool()) {
        checked("grGlideGetState", [&] { grGlideGetState(&g_saved_state); });
        g_have_saved_state = glideShimGetLastError() == GLIDESHIM_OK;
      } else {
        checked("grGlideSetState", [&] { grGlideSetState(&g_saved_state); });
        if (glideShimGetLastError() == GLIDESHIM_OK) {
          GrState again{};
          checked("grGlideGetState", [&] { grGlideGetState(&again); });
          if (glideShimGetLastError() == GLIDESHIM_OK &&
              std::memcmp(&again, &g_saved_state, sizeof again) != 0)
            violated("grGlideSetState", "the state saved after a restore differs from the one restored");
        }
      }
      break;
    case 38:
      close_and_reopen(in);
      break;
    case 39: {
      GrTexInfo info = texture_info(in);
      const FxU32 even_odd = small_or_any(in, 4);
      checked("grTexTextureMemRequired", [&] { grTexTextureMemRequired(even_odd, in.ConsumeIntegralInRange(0, 15) == 0 ? nullptr : &info); });
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      checked("grTexMinAddress", [&] { grTexMinAddress(tmu); });
      checked("grTexMaxAddress", [&] { grTexMaxAddress(tmu); });
      break;
    }
    case 40:
    case 41:
      textured_draw(in, span);
      break;
    default: {
      const int width = in.ConsumeIntegralInRange(-2, glide_shim::kMaxScreenSide + 2);
      const int height = in.ConsumeIntegralInRange(-2, glide_shim::kMaxScreenSide + 2);
      checked("glideShimSetWindowSize", [&] { glideShimSetWindowSize(width, height); });
      break;
    }
  }
}

void one_call(FuzzedDataProvider &in, float span) {
  switch (in.ConsumeIntegralInRange(0, 99)) {
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
      checked("grTexDownloadMipMap", kMemory, [&] { grTexDownloadMipMap(tmu, address, even_odd, &info); });
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
      checked("grTexDownloadMipMapLevel", kMemory, [&] {
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
      // Every write mode (reserved ones and junk now and then), through the pixel pipeline
      // or not.
      static constexpr GrLfbWriteMode_t kModes[] = {
          GR_LFBWRITEMODE_565,       GR_LFBWRITEMODE_555,       GR_LFBWRITEMODE_1555,
          GR_LFBWRITEMODE_888,       GR_LFBWRITEMODE_8888,      GR_LFBWRITEMODE_565_DEPTH,
          GR_LFBWRITEMODE_555_DEPTH, GR_LFBWRITEMODE_1555_DEPTH, GR_LFBWRITEMODE_ZA16,
          GR_LFBWRITEMODE_ANY};
      const GrLfbWriteMode_t mode = in.ConsumeIntegralInRange(0, 7) == 0
                                        ? enum_value(in, 0, 0xff)
                                        : kModes[in.ConsumeIntegralInRange<std::size_t>(0, 9)];
      const GrOriginLocation_t origin = enum_value(in, GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT);
      const FxBool pipeline = in.ConsumeBool() ? FXTRUE : (in.ConsumeIntegralInRange(0, 7) == 0 ? 2 : FXFALSE);
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
      checked("glideShimRenderToTexture", kMemory, [&] { glideShimRenderToTexture(tmu, address, lod); });
      break;
    }
    case 43:
      checked("glideShimRenderToFrameBuffer", kMemory, [] { glideShimRenderToFrameBuffer(); });
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
      if (!bytes.empty()) std::memcpy(&table, bytes.data(), bytes.size());
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
      more_calls(in, span);
      break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv) {
  (void)argc, (void)argv;
  grErrorSetCallback(on_error);
  // Files the calls read and write (.3df inputs, PNGs) go beside the binary, in the build tree.
  char exe[4096] = {};
  const ssize_t length = readlink("/proc/self/exe", exe, sizeof exe - 1);
  std::string dir = length > 0 ? std::string(exe, static_cast<std::size_t>(length)) : std::string("./x");
  dir = dir.substr(0, dir.rfind('/'));
  g_scratch = dir + "/glide_api_fuzz.files";
  mkdir(g_scratch.c_str(), 0755);
  // The run's window, opened before the first input; the shim closes it at exit.
  grGlideInit();
  WindowRequest usual{kUsualWidth, kUsualHeight, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT, 2, 1, true};
  if (!open_window(usual)) violated("grSstWinOpen", "the run's window did not open");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  g_thorough = in.ConsumeIntegralInRange(0, 7) == 0 ? kAll : kSmall;
  g_have_saved_state = false;
  if (!start_input(in)) return 0;
  // Sides of the drawable area, for arguments near the screen's edges.
  const float span = static_cast<float>(std::max(glide_shim::current().display.width,
                                                 glide_shim::current().display.height));
  for (int calls = 0; calls < 48 && in.remaining_bytes() > 0; ++calls) one_call(in, span);
  return 0;
}

// GlideContext: the one explicit object behind the Glide API. It holds one group per Glide
// chapter, each with the defaults grSstWinOpen loads, plus the GL renderer once a window is open.
// gr* entry points check their arguments, then change one group; the renderer reads the groups
// when it draws. The only global is the pointer returned by current().
#pragma once

#include <glide.h>
#include <glideutl.h>

#include "glide_shim.h"
#include "vertex_fields.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

namespace glide_shim {

class GlRenderer;

struct CombineUnit {  // grColorCombine / grAlphaCombine
  GrCombineFunction_t function;
  GrCombineFactor_t factor;
  GrCombineLocal_t local;
  GrCombineOther_t other;
  bool invert;
  bool operator==(const CombineUnit &o) const {
    return function == o.function && factor == o.factor && local == o.local &&
           other == o.other && invert == o.invert;
  }
};

struct TexCombineUnit {  // grTexCombine, for one TMU
  GrCombineFunction_t rgb_function;
  GrCombineFactor_t rgb_factor;
  GrCombineFunction_t alpha_function;
  GrCombineFactor_t alpha_factor;
  bool rgb_invert;
  bool alpha_invert;
  bool operator==(const TexCombineUnit &o) const {
    return rgb_function == o.rgb_function && rgb_factor == o.rgb_factor &&
           alpha_function == o.alpha_function && alpha_factor == o.alpha_factor &&
           rgb_invert == o.rgb_invert && alpha_invert == o.alpha_invert;
  }
};

struct ColorPathState {
  CombineUnit color;
  CombineUnit alpha;
  GrColor_t constant_color;  // in the window's colour format (ARGB or ABGR)
  // grAlphaControlsITRGBLighting: the colour unit's local is the constant colour where the
  // TMU output's alpha has bit 7 set, else the iterated RGB (fbzColorPath bit 7).
  bool alpha_controls_itrgb;
  // The guColorCombineFunction *_DELTA0 presets: the RGB iterators hold the grConstantColorValue4
  // colour with zero slopes, so every pixel's iterated RGB is that colour (gc->state.r/g/b).
  bool delta0;
  float iterated4[4];  // grConstantColorValue4's a, r, g, b, 0..255
};

struct BlendState {
  GrAlphaBlendFnc_t rgb_src, rgb_dst, alpha_src, alpha_dst;
  GrCmpFnc_t alpha_test_function;
  GrAlpha_t alpha_test_reference;  // 0..255
};

struct ChromaKeyState {
  GrChromakeyMode_t mode;
  GrColor_t value;  // in the window's colour format
};

struct DepthState {
  GrDepthBufferMode_t mode;
  GrCmpFnc_t function;
  bool mask;         // depth writes
  FxI16 bias_level;  // signed, in depth-code units
};

struct ClipRect {  // screen pixels in the current origin; max is exclusive
  FxU32 min_x, min_y, max_x, max_y;
};

struct RasterState {
  GrCullMode_t cull;
  GrDitherMode_t dither;
  ClipRect clip;
  bool rgb_mask;
  bool alpha_mask;
  GrBuffer_t render_buffer;
  GrOriginLocation_t origin;
  FxU32 stw_hint;  // GR_HINT_STWHINT bits
};

struct TextureTarget {  // glideShimRenderToTexture
  bool active = false;
  FxU32 address = 0;
  int side = 0;
  ClipRect saved_clip{};
};

struct TextureSource {  // what grTexSource points TMU0 at
  bool valid;
  FxU32 address;  // byte address in TMU memory
  GrLOD_t small_lod, large_lod;
  GrAspectRatio_t aspect;
  GrTextureFormat_t format;
  FxU32 even_odd;  // GR_MIPMAPLEVELMASK_*: which levels the chain holds
};

// The TMU's look-up tables (grTexDownloadTable): one 256-entry palette for P_8 and AP_88, and
// two NCC tables for YIQ_422 and AYIQ_8422, kept as the 12 packed words the hardware receives.
struct TextureTables {
  FxU32 palette[256];  // 0x??RRGGBB; the top byte is ignored
  FxU32 ncc[2][12];    // GuNccTable.packed_data: Y (4 words), I (4), Q (4)
  GrNCCTable_t ncc_select;
  FxU32 generation;  // bumped on every change, so decoded textures know they are out of date
};

struct TmuState {
  GrTextureClampMode_t clamp_s, clamp_t;
  GrTextureFilterMode_t min_filter, mag_filter;
  GrMipMapMode_t mipmap_mode;
  bool lod_blend;
  float lod_bias;
  bool allow_lod_dither;  // grHints(GR_HINT_ALLOW_MIPMAP_DITHER), read by grTexMipMapMode
  bool lod_dither;        // GR_MIPMAP_NEAREST_DITHER took effect (the hint was on)
  bool multibase;         // grTexMultibase
  // Virtual start of a full 256..1 chain for each multibase range (256, 128, 64, 32..1), as the
  // texBaseAddr registers hold it: a level's bytes sit at base + its offset in such a chain.
  // Without multibase every level uses base[0], which grTexSource sets.
  std::int64_t base[4];
  TexCombineUnit combine;
  // grTexDetailControl as the tDetail register holds it: the LOD below which detail appears
  // (signed, whole LODs), the shift of (bias - LOD) and the largest factor (0..255).
  int detail_bias, detail_scale, detail_max;
  TextureSource source;
  TextureTables tables;
  std::vector<std::uint8_t> memory;  // the TMU's texture RAM; downloads write raw bytes here
};

struct DisplayState {
  bool open;
  int width, height;
  GrColorFormat_t color_format;
  float gamma;
  int swaps;  // frames shown so far, for the frame dump's file names
  bool dump_dir_missing_reported;  // GLIDESHIM_DUMP_DIR named no directory: said once per window
  int none_width = 640, none_height = 480;  // the size GR_RESOLUTION_NONE opens
};

// How the hardware reads LFB write data (lfbMode's RGBA lanes, byte swizzle and word swap), set by
// grLfbWriteColorFormat and grLfbWriteColorSwizzle; it applies to locks and grLfbWriteRegion alike.
struct LfbWriteLayout {
  GrColorFormat_t color_format = GR_COLORFORMAT_ARGB;
  bool swizzle_bytes = false;
  bool swap_words = false;
};

struct LfbLockState {
  bool read_locked, write_locked;
  GrBuffer_t write_buffer;
  GrOriginLocation_t write_origin;
  GrLfbWriteMode_t write_mode;                   // the format of write_pixels
  bool write_pipeline;                           // the write lock goes through the pixel pipeline
  GrAlpha_t write_alpha;                         // constant alpha and depth as grLfbLock loaded
  FxU16 write_depth;                             // them into zaColor for the lock
  LfbWriteLayout layout;
  std::vector<FxU16> read_pixels;                // whole-screen 565 or depth words for a read lock
  std::vector<std::uint8_t> write_pixels;        // whole-screen pixels in write_mode for a write lock
  std::vector<std::uint8_t> write_original;      // write_pixels as locked, to find what changed
  GrAlpha_t constant_alpha = 0xFF;  // grLfbConstantAlpha: alpha of LFB writes that carry none
  FxU16 constant_depth = 0;         // grLfbConstantDepth: depth code of writes that carry none
};

struct FogState {  // grFogMode, grFogColorValue, grFogTable
  GrFogMode_t mode;     // GR_FOG_* source in the low byte, MULT2 / ADD2 flags above it
  GrColor_t color;      // in the window's colour format
  GrFog_t table[GR_FOG_TABLE_SIZE];  // fog blend per W-code octave quarter, 0..255
};

// grSstPerfStats: the FBI's pixel counters, counted once grSstResetPerfStats starts them.
struct PerfStatsState {
  bool counting;
  GrSstPerfStats_t counts;
  FxU32 triangles_processed;  // grTriStats: triangles given to the rasteriser's setup
  FxU32 triangles_drawn;      // and those left after culling and zero-area rejection
};

// Without a callback each distinct message (the same text) goes to stderr once per process,
// as 3dfx's driver printed its errors; at most kMaxPrintedErrors of them, so that a program
// that fails with a new coordinate every frame neither floods stderr nor grows this set.
constexpr std::size_t kMaxPrintedErrors = 64;

struct ErrorState {
  GrErrorCallbackFnc_t callback;
  GlideShimError last;
  std::string message;
  std::unordered_set<std::string> printed;  // messages already written to stderr
  bool print_limit_reached;                 // said once that no more are printed
  bool printed_without_memory;              // the one line report_exception prints unallocated
};

// GLIDESHIM_QUIET set to anything but "" or "0": errors without a callback are not printed.
bool errors_quiet();

// The gu texture manager (guTexAllocateMemory and friends, gu_texture_manager.cpp): digutex.c's
// mip-map table, the TMU's free-memory pointer and guTexSource's NCC-table bookkeeping.
// grSstWinOpen empties it, as the driver's grSstWinOpen calls guTexMemReset.
struct GuTextureManager {
  std::vector<GrMipMapInfo> records;  // MAX_MIPMAPS_PER_SST entries, indexed by id; never moved
  FxU32 next_id = 0;                  // ids below this are allocated (the driver's free_mmid)
  FxU32 free_base = 0;                // first free byte of TMU memory (freemem_base)
  GrMipMapId_t current = GR_NULL_MIPMAP_HANDLE;  // the id guTexSource last selected
  GrMipMapId_t ncc_owner[2] = {GR_NULL_MIPMAP_HANDLE, GR_NULL_MIPMAP_HANDLE};  // per NCC table
  GrNCCTable_t next_ncc_table = GR_NCCTABLE_NCC0;  // where the next id's NCC table goes
  void reset();  // guTexMemReset: every id freed, all TMU memory free
};

constexpr FxU32 kTmuMemoryBytes = 2u * 1024u * 1024u;  // one Voodoo 1 TMU
constexpr int kMaxScreenSide = 2048;

class GlideContext {
 public:
  GlideContext();
  ~GlideContext();

  bool initialized = false;  // grGlideInit called and not shut down
  ColorPathState color_path{};
  BlendState blend{};
  ChromaKeyState chroma{};
  DepthState depth{};
  RasterState raster{};
  TmuState tmu{};
  DisplayState display{};
  LfbLockState lfb{};
  FogState fog{};
  PerfStatsState perf{};
  TextureTarget texture_target{};
  GuTextureManager gu_textures{};
  // guMP*'s two virtual TMUs and combine (gu_multipass.cpp). Like the driver's _gumpState it
  // survives grSstWinOpen; only guMPInit resets it.
  GrMPState multipass{{GR_NULL_MIPMAP_HANDLE, GR_NULL_MIPMAP_HANDLE}, GR_MPTEXTURECOMBINE_ADD};
  bool plain_gl = false;  // between glideShimBeginGL and glideShimEndGL
  // The fast paths: work the frame cannot show is skipped, with the exact path's bytes (see
  // docs/environment.md). GLIDESHIM_EXACT=1 turns them off at grSstWinOpen; tests flip it.
  bool fast_paths = true;
  // Fidelity knobs (GLIDESHIM_PLAIN_GL, read at grSstWinOpen; kPlain* in gl/shader_source.h):
  // modelled behaviours replaced by plain GL's. Off (0) by default; the frame is then exact.
  int fidelity_knobs = 0;
  ErrorState errors{};
  std::unique_ptr<GlRenderer> renderer;
  // fields_read(*this), kept for grDrawTriangle until it goes stale: every entry point flushes
  // the queue before it changes the state fields_read reads, and a flush marks it stale.
  VertexFields vertex_fields{};
  bool vertex_fields_stale = true;

  // Loads the defaults grSstWinOpen establishes (gsst.c), group by group.
  void load_window_defaults(int width, int height, GrColorFormat_t format, GrOriginLocation_t o);

  // Records an error: kept as the last error and sent once to the grErrorSetCallback callback,
  // or, with none installed, printed to stderr unless printed before or GLIDESHIM_QUIET is set.
  void report(GlideShimError kind, const std::string &message);
  // Guard for entry points that need an open window; reports and returns false otherwise.
  bool require_open(const char *function) {
    return (!plain_gl && initialized && display.open) || refuse_closed(function);
  }
  bool refuse_closed(const char *function);  // require_open's report; always false
  // Draws queued triangles before a state change; a no-op before grSstWinOpen.
  void flush();
};

GlideContext &current();

// Registers, once, an exit handler that closes a window the program left open. grSstWinOpen
// calls it once its GL context exists, so that the handler runs before Mesa's own (exit
// handlers run last-registered first), which stops llvmpipe's threads: a GL context destroyed
// after that (by the static context's destructor) waits for those threads forever.
void close_window_at_exit();

bool is_compare(GrCmpFnc_t function);  // a GR_CMP_* value

// Decodes a GrColor_t in the window's format to 8-bit R, G, B, A.
struct Rgba8 {
  std::uint8_t r, g, b, a;
};
Rgba8 unpack_color(GrColor_t color, GrColorFormat_t format);

}  // namespace glide_shim

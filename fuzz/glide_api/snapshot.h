// The state groups of the current GlideContext, copied before a call so that a call that reported
// an error can be checked to have changed none of them.
#pragma once

#include "context.h"

#include <cstdint>
#include <vector>

namespace glide_api_fuzz {

// What a call may touch beyond the small groups, which every snapshot holds: TMU memory (2 MB)
// and the gu manager's records (1024 of them) are copied only before the calls that write
// them, and before every call of a "thorough" input (one in eight), to keep the run fast.
enum Touches : unsigned { kSmall = 0, kMemory = 1, kGuRecords = 2, kAll = 3 };

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

  void take(glide_shim::GlideContext &ctx, unsigned what);
  // The name of the first group that differs from `ctx`, or nullptr.
  const char *differs(const glide_shim::GlideContext &ctx) const;
};

}  // namespace glide_api_fuzz

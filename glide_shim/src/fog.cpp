// Chapter "fog": the fog mode, colour and 64-entry table, and the gu* table generators written
// as 3dfx's gu.c computes them (float arithmetic, truncation to 0..255). The per-pixel fog is in
// the generated fragment shader (gl/shader_pixel_ops.cpp): table fog indexed by the W depth code.
#include "context.h"

#include <cmath>
#include <string>

using glide_shim::current;

namespace {

constexpr int kFogEntries = GR_FOG_TABLE_SIZE;

bool is_fog_mode(GrFogMode_t mode) {
  const GrFogMode_t source = mode & 0xFF;
  const GrFogMode_t flags = mode & ~0xFF;
  return source >= GR_FOG_DISABLE && source <= GR_FOG_WITH_ITERATED_Z &&
         (flags & ~(GR_FOG_MULT2 | GR_FOG_ADD2)) == 0;
}

// World w at the start of fog-table entry i: entry i covers W codes i*1024 .. i*1024+1023, and
// code (e<<12) + (j<<10) stands for w = 2^(e+3) / (8 - j).
float index_to_w(int i) {
  return static_cast<float>(std::pow(2.0, 3.0 + static_cast<double>(i >> 2))) /
         static_cast<float>(8 - (i & 3));
}

// gu.c's clamp-and-truncate of a fog fraction to a table byte.
GrFog_t to_fog_byte(float f) {
  if (f > 1.0f) f = 1.0f;
  else if (f < 0.0f) f = 0.0f;
  return static_cast<GrFog_t>(f * 255.0f);
}

// Shared checks of guFogGenerateExp / Exp2: a table and a positive, finite density.
bool check_generator(const char *function, const GrFog_t *table, float density) {
  auto &ctx = current();
  if (table == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, std::string(function) + ": fogtable is NULL");
    return false;
  }
  if (!std::isfinite(density) || density <= 0.0f) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, std::string(function) + ": density " +
                                               std::to_string(density) +
                                               " must be positive and finite");
    return false;
  }
  return true;
}

// A density so small that the farthest entry's fog rounds to 0 in float gives no table (the
// normalisation would divide by zero and every entry be NaN): refused like a zero density.
bool check_scale(const char *function, float density, float scale) {
  if (std::isfinite(scale)) return true;
  current().report(GLIDESHIM_ERR_OUT_OF_RANGE, std::string(function) + ": density " +
                                                   std::to_string(density) +
                                                   " is too small to give a fog table");
  return false;
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void grFogMode(GrFogMode_t mode) {
  auto &ctx = current();
  if (!ctx.require_open("grFogMode")) return;
  if (!is_fog_mode(mode)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grFogMode: unknown mode " + std::to_string(mode));
    return;
  }
  if (mode == ctx.fog.mode) return;
  ctx.flush();
  ctx.fog.mode = mode;
}

void grFogColorValue(GrColor_t fogcolor) {
  auto &ctx = current();
  if (!ctx.require_open("grFogColorValue")) return;
  if (fogcolor == ctx.fog.color) return;
  ctx.flush();
  ctx.fog.color = fogcolor;
}

void grFogTable(const GrFog_t ft[]) {
  auto &ctx = current();
  if (!ctx.require_open("grFogTable")) return;
  if (ft == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grFogTable: ft is NULL");
    return;
  }
  ctx.flush();
  for (int i = 0; i < kFogEntries; ++i) ctx.fog.table[i] = ft[i];
}

float guFogTableIndexToW(int i) {
  if (i < 0 || i >= kFogEntries) {
    current().report(GLIDESHIM_ERR_OUT_OF_RANGE, "guFogTableIndexToW: index " +
                                                     std::to_string(i) + " is outside 0..63");
    return 0.0f;
  }
  return index_to_w(i);
}

void guFogGenerateExp(GrFog_t fogtable[], float density) {
  if (!check_generator("guFogGenerateExp", fogtable, density)) return;
  // Normalised so the last entry is fully fogged: f = (1 - e^-dw) / (1 - e^-d*w63).
  const float far_dp = density * index_to_w(kFogEntries - 1);
  const float scale = 1.0f / (1.0f - static_cast<float>(std::exp(-far_dp)));
  if (!check_scale("guFogGenerateExp", density, scale)) return;
  for (int i = 0; i < kFogEntries; ++i) {
    const float dp = density * index_to_w(i);
    fogtable[i] = to_fog_byte((1.0f - static_cast<float>(std::exp(-dp))) * scale);
  }
}

void guFogGenerateExp2(GrFog_t fogtable[], float density) {
  if (!check_generator("guFogGenerateExp2", fogtable, density)) return;
  const float far_dp = density * index_to_w(kFogEntries - 1);
  const float scale = 1.0f / (1.0f - static_cast<float>(std::exp(-(far_dp * far_dp))));
  if (!check_scale("guFogGenerateExp2", density, scale)) return;
  for (int i = 0; i < kFogEntries; ++i) {
    const float dp = density * index_to_w(i);
    fogtable[i] = to_fog_byte((1.0f - static_cast<float>(std::exp(-(dp * dp)))) * scale);
  }
}

void guFogGenerateLinear(GrFog_t fogtable[], float nearZ, float farZ) {
  auto &ctx = current();
  if (fogtable == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "guFogGenerateLinear: fogtable is NULL");
    return;
  }
  if (!std::isfinite(nearZ) || !std::isfinite(farZ) || !(farZ > nearZ)) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, "guFogGenerateLinear: need finite nearZ < farZ, got " +
                                               std::to_string(nearZ) + ", " +
                                               std::to_string(farZ));
    return;
  }
  for (int i = 0; i < kFogEntries; ++i) {
    float world_w = index_to_w(i);  // w of the entry, capped at the W buffer's range
    if (world_w > 65535.0f) world_w = 65535.0f;
    fogtable[i] = to_fog_byte((world_w - nearZ) / (farZ - nearZ));
  }
}

}  // namespace glide_shim_api

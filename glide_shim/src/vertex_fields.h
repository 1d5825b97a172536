// Which GrVertex fields the current state reads and how (draw.cpp's fields_read): the recipe
// that turns a program's vertex into the shim's. Kept in the context between state changes.
#pragma once

#include <glide.h>

#include <cstdint>

namespace glide_shim {

struct DepthState;

// How a vertex's GL depth is formed: none (depth buffering off: 0), the W-buffer's 1/w with
// no bias (clamped to 0..1), or vertex_depth's general case (a Z-buffer, a biased W-buffer).
enum class DepthSource { None, UnbiasedW, General };

// A GrVertex's first 12 floats (x y z r g b ooz a oow, TMU0's sow tow oow), by index.
constexpr int kCheckedVertexFloats = 12;

struct VertexFields {  // which GrVertex fields the current state reads, and how it reads them
  bool rgb, alpha, ooz, oow, texture;
  GrFogMode_t fog;  // the fog source: table fog reads oow, iterated-Z fog ooz, iterated alpha a
  bool delta0;      // the RGB iterators hold delta0_rgb (guColorCombineFunction's *_DELTA0)
  float delta0_rgb[3];
  bool q_from_tmu;  // GR_STWHINT_W_DIFF_TMU0: the texture divisor is tmuvtx[0].oow, not oow
  DepthSource depth_source;
  const DepthState *depth;  // the context's, for DepthSource::General
  // The exponent field (0x7F800000) for each of the first 12 floats the checks read (x, y and
  // the fields above), 0 for the others: a bit mask for checking all of a vertex at once.
  std::uint32_t checked_exponents[kCheckedVertexFloats];
};

}  // namespace glide_shim

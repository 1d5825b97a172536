// grDrawTriangle's vertex work for a whole triangle at once, with to_shim_vertex's bits: the
// NaN/infinity probe as one bit mask over each vertex's first 12 floats, the 12.4 snap of the
// six screen coordinates on four lanes at a time, and one branch per field a triangle, not
// one per vertex. The context keeps fields_read's answer until a flush marks it stale.
#include "draw.h"

#include "depth.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace glide_shim {
namespace {

// Four lanes of floats or of 32-bit integers (GCC's and Clang's vector extensions; SSE2 on
// x86-64): a comparison gives -1 in each lane where it holds, 0 elsewhere.
using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));

static_assert(offsetof(GrVertex, tmuvtx[0].oow) == (kCheckedVertexFloats - 1) * sizeof(float),
              "the checks read GrVertex's first 12 floats as x y z r g b ooz a oow sow tow oow");

Int4 bits_of(Float4 v) {
  Int4 b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

Float4 float_of(Int4 b) {
  Float4 v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

// The six screen coordinates in the Glide origin (a.x a.y b.x b.y, then c.x c.y twice), less
// the 3<<18 snap offset where a program left it on (draw.cpp's remove_snap_offset): v - 0
// keeps every other value, signed zeros included.
struct Positions {
  Float4 ab, cc;
};

Float4 without_snap_offset(Float4 v) {
  const Int4 in_window = (v >= kSnapOffset - 4096.0f) & (v < kSnapOffset + 4096.0f);
  return v - float_of(bits_of(Float4{} + kSnapOffset) & in_window);
}

bool all_lanes(Int4 condition) {
  condition &= __builtin_shufflevector(condition, condition, 2, 3, 0, 1);
  condition &= __builtin_shufflevector(condition, condition, 1, 0, 3, 2);
  return condition[0] != 0;
}

// |v| <= 32768 in each lane (false for NaN).
Int4 in_setup_range(Float4 v) {
  return float_of(bits_of(v) & 0x7FFFFFFF) <= kMaxScreenCoordinate;
}

// The positions, and whether all six are within the setup range. A coordinate within it is not
// in the offset's window, so most triangles have nothing to remove.
[[gnu::always_inline]] inline bool positions_in_range(const GrVertex &a, const GrVertex &b,
                                                     const GrVertex &c, Positions &p) {
  p = {Float4{a.x, a.y, b.x, b.y}, Float4{c.x, c.y, c.x, c.y}};
  if (all_lanes(in_setup_range(p.ab) & in_setup_range(p.cc))) return true;
  p = {without_snap_offset(p.ab), without_snap_offset(p.cc)};
  return all_lanes(in_setup_range(p.ab) & in_setup_range(p.cc));
}

// draw.cpp's snap_checked on four lanes, for |v| <= 32768: the product by 16 is exact, so is its
// truncation and the fraction left; a fraction of at least one half steps away from zero; the
// result takes the product's sign, so a negative zero stays negative.
Float4 snapped(Float4 v) {
  const Float4 scaled = v * 16.0f;
  const Int4 whole = __builtin_convertvector(scaled, Int4);
  const Float4 fraction = scaled - __builtin_convertvector(whole, Float4);
  const Int4 rounded = whole - (fraction >= 0.5f) + (fraction <= -0.5f);
  const Float4 magnitude = __builtin_convertvector(rounded, Float4) * 0.0625f;
  const Int4 sign = Int4{} + INT32_MIN;
  return float_of((bits_of(magnitude) & ~sign) | (bits_of(scaled) & sign));
}

using Word4 = std::uint32_t __attribute__((vector_size(16)));

Word4 load_words(const void *from) {
  Word4 words;
  std::memcpy(&words, from, sizeof words);
  return words;
}

// True when no float the state reads, of the three vertices, is NaN or infinite: such a float
// has all exponent bits set, and adding one to that exponent field carries into the sign bit.
[[gnu::always_inline]] inline bool all_finite(const VertexFields &fields, const GrVertex &a,
                                              const GrVertex &b, const GrVertex &c) {
  static_assert(sizeof fields.checked_exponents == 3 * sizeof(Word4), "three vectors of four");
  const Word4 checked[3] = {load_words(&fields.checked_exponents[0]),
                            load_words(&fields.checked_exponents[4]),
                            load_words(&fields.checked_exponents[8])};
  const auto carries = [&checked](const GrVertex &v) {
    const float *f = &v.x;
    return ((load_words(f) & checked[0]) + 0x00800000u) |
           ((load_words(f + 4) & checked[1]) + 0x00800000u) |
           ((load_words(f + 8) & checked[2]) + 0x00800000u);
  };
  Word4 failed = carries(a) | carries(b) | carries(c);
  failed |= __builtin_shufflevector(failed, failed, 2, 3, 0, 1);
  failed |= __builtin_shufflevector(failed, failed, 1, 0, 3, 2);
  return (failed[0] & 0x80000000u) == 0;
}

[[gnu::always_inline]] inline void convert(const VertexFields &fields, const GrVertex &a,
                                           const GrVertex &b, const GrVertex &c,
                                           const Positions &p, ShimVertex *out) {
  const Float4 ab = snapped(p.ab), cc = snapped(p.cc);
  out[0].x = ab[0], out[0].y = ab[1], out[1].x = ab[2], out[1].y = ab[3];
  out[2].x = cc[0], out[2].y = cc[1];
  // `write` for each vertex and its output, unrolled, the field choices made once.
  const auto each = [&](auto write) { write(a, out[0]), write(b, out[1]), write(c, out[2]); };
  switch (fields.depth_source) {
    case DepthSource::None:
      each([](const GrVertex &, ShimVertex &o) { o.depth = 0.0f; });
      break;
    case DepthSource::UnbiasedW:
      each([](const GrVertex &v, ShimVertex &o) {
        o.depth = std::clamp(std::min(v.oow, 1.0f), 0.0f, 1.0f);
      });
      break;
    default:
      each([&fields](const GrVertex &v, ShimVertex &o) {
        o.depth = vertex_depth(*fields.depth, fields.ooz ? v.ooz : 0.0f, fields.oow ? v.oow : 0.0f);
      });
  }
  if (fields.delta0) {
    each([&fields](const GrVertex &, ShimVertex &o) {
      o.r = fields.delta0_rgb[0], o.g = fields.delta0_rgb[1], o.b = fields.delta0_rgb[2];
    });
  } else if (fields.rgb) {
    each([](const GrVertex &v, ShimVertex &o) { o.r = v.r, o.g = v.g, o.b = v.b; });
  } else {
    each([](const GrVertex &, ShimVertex &o) { o.r = o.g = o.b = 0.0f; });
  }
  if (fields.alpha) {
    each([](const GrVertex &v, ShimVertex &o) { o.a = v.a; });
  } else {
    each([](const GrVertex &, ShimVertex &o) { o.a = 0.0f; });
  }
  switch (fields.fog) {
    case GR_FOG_WITH_TABLE:
      each([](const GrVertex &v, ShimVertex &o) { o.fog = v.oow; });
      break;
    case GR_FOG_WITH_ITERATED_Z:
      each([](const GrVertex &v, ShimVertex &o) { o.fog = v.ooz; });
      break;
    default:
      each([](const GrVertex &, ShimVertex &o) { o.fog = 0.0f; });
  }
  if (!fields.texture) {
    each([](const GrVertex &, ShimVertex &o) { o.sow = o.tow = o.q = 0.0f; });
  } else if (fields.q_from_tmu) {
    each([](const GrVertex &v, ShimVertex &o) {
      o.sow = v.tmuvtx[0].sow, o.tow = v.tmuvtx[0].tow, o.q = v.tmuvtx[0].oow;
    });
  } else {
    each([](const GrVertex &v, ShimVertex &o) {
      o.sow = v.tmuvtx[0].sow, o.tow = v.tmuvtx[0].tow, o.q = v.oow;
    });
  }
}

}  // namespace

const VertexFields &current_vertex_fields(GlideContext &context) {
  if (context.vertex_fields_stale) {
    context.vertex_fields = fields_read(context);
    context.vertex_fields_stale = false;
  }
  return context.vertex_fields;
}

bool triangle_is_valid(const VertexFields &fields, const GrVertex &a, const GrVertex &b,
                       const GrVertex &c) {
  Positions positions;
  return all_finite(fields, a, b, c) && positions_in_range(a, b, c, positions);
}

void convert_triangle(const VertexFields &fields, const GrVertex &a, const GrVertex &b,
                      const GrVertex &c, ShimVertex *out) {
  Positions positions;
  positions_in_range(a, b, c, positions);
  convert(fields, a, b, c, positions, out);
}

ShimVertex *queue_checked_triangle(GlRenderer &renderer, const VertexFields &fields,
                                   const GrVertex &a, const GrVertex &b, const GrVertex &c) {
  Positions positions;
  if (!all_finite(fields, a, b, c) || !positions_in_range(a, b, c, positions)) return nullptr;
  ShimVertex *out = renderer.queue_space(Primitive::Triangles, 3);
  convert(fields, a, b, c, positions, out);
  return out;
}

}  // namespace glide_shim

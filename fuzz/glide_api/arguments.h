// Arguments decoded from the input: mostly values a program would pass, sometimes the edges of
// their types, so that both the accepted and the refused paths of every call are reached.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>
#include <glide.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace glide_api_fuzz {

// Mostly values near a valid range [lo, hi] (one past each end included), sometimes any int.
int enum_value(FuzzedDataProvider &in, int lo, int hi);
// 0..hi, sometimes any value.
FxU32 small_or_any(FuzzedDataProvider &in, FxU32 hi);
FxBool boolean(FuzzedDataProvider &in);
// A float for a vertex field: on-screen values (screen space, 0..span) most of the time, then
// the edges of float.
float coordinate(FuzzedDataProvider &in, float span);
GrVertex vertex(FuzzedDataProvider &in, float span);

// Host bytes of a mip-map chain large_lod..small_lod as GrTexInfo.data holds it; 0 when the
// arguments are not a valid texture.
std::size_t host_chain_bytes(GrLOD_t small_lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
                             GrTextureFormat_t format);
// A data buffer for a download: exactly `bytes` when they are not 0 (ASan catches any read past
// it), else a few bytes that a correct shim never reads.
std::vector<std::uint8_t> texel_data(FuzzedDataProvider &in, std::size_t bytes);
GrTexInfo texture_info(FuzzedDataProvider &in);

}  // namespace glide_api_fuzz

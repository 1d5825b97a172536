// Step 2 of the projected shadow texture (the region read back and downloaded), and the loading
// of a frame's textures into TMU0 memory again when they did not all fit
// (shadow_texture_memory.h): the LFB path downloads step 2's read-back, the direct path draws
// step 1 again. Addresses are byte addresses in TMU0 memory.
#include "techniques/projected/projected_shadow.h"

#include <glide_shim.h>

#include <vector>

namespace gs {
namespace {

void download(const ShadowTexture &texture, FxU32 address) {
  GrTexInfo info = texture.info;
  info.data = const_cast<FxU16 *>(texture.texels.data());  // grTexDownloadMipMap only reads it
  grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
}

}  // namespace

ShadowTexture read_shadow_texture(const LightView &view, const ProjectedShadowOptions &options) {
  ShadowTexture texture;
  texture.info.smallLod = texture.info.largeLod = shadow_lod(view.size);
  texture.info.aspectRatio = GR_ASPECT_1x1;
  // The same 16-bit words, read as ARGB_4444: alpha is the top nibble of the red field.
  // The chroma-key variant reads them as the colour they were drawn in.
  texture.info.format = options.chroma_key ? GR_TEXFMT_RGB_565 : GR_TEXFMT_ARGB_4444;
  if (view.direct_path) return texture;  // step 1 writes texture memory itself

  const auto side = static_cast<FxU32>(view.size);
  texture.texels.resize(static_cast<std::size_t>(side) * side);  // system memory
  grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, side, side, side * 2, texture.texels.data());
  return texture;
}

// Step 2: the region read back and downloaded as ARGB_4444 (or already in texture memory).
ShadowTexture make_shadow_texture(const LightView &view, const ProjectedShadowOptions &options,
                                  FxU32 texture_address) {
  ShadowTexture texture = read_shadow_texture(view, options);
  texture.address = texture_address;
  if (!view.direct_path) download(texture, texture_address);
  return texture;
}

std::optional<FxU32> bind_shadow_texture(const ShadowJob &job, ShadowTextureMemory &memory,
                                         const FrameGeometry &geometry) {
  GrTexInfo info = job.texture.info;
  const ShadowTextureMemory::Slot slot =
      memory.bind(job.texture.id, grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &info));
  if (!slot.load) return slot.address;
  if (!job.view.direct_path) {
    download(job.texture, slot.address);
    return slot.address;
  }
  // Step 1 again, into the slot, in the state step 1 found; the pass then goes on as it was.
  GrState state;
  grGlideGetState(&state);
  grGlideSetState(&job.step1_state);
  LightView view = job.view;
  SurfaceMask mask;
  if (job.mask_receiver) mask.receiver = &geometry.objects[*job.mask_receiver];
  mask.farthest = job.mask_farthest;
  if (!job.mask_triangles.empty()) mask.triangles = &job.mask_triangles;
  draw_caster_flat(view, slot.address, job.mask_receiver ? &mask : nullptr, job.draw);
  grGlideSetState(&state);
  if (view.usable) return slot.address;
  memory.forget(slot.address, slot.address + 1);  // it holds nothing of the texture
  return std::nullopt;
}

}  // namespace gs

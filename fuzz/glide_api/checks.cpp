// The checks' state and the invariants of an open window (checks.h).
#include "glide_api/checks.h"

#include <glideutl.h>

#include <cstdio>
#include <cstdlib>

namespace glide_api_fuzz {

[[noreturn]] void violated(const char *call, const char *what) {
  std::fprintf(stderr, "glide_api_fuzz: after %s: %s\n", call, what);
  std::abort();
}

unsigned g_thorough = 0;
Snapshot g_before;

std::string g_callback_message;
int g_callback_count = 0;

void on_error(const char *message, FxBool fatal) {
  (void)fatal;
  if (message == nullptr) violated("an error", "the callback was given a NULL message");
  g_callback_message = message;
  ++g_callback_count;
}

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

}  // namespace glide_api_fuzz

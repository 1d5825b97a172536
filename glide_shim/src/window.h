// The shim's window: showing the displayed buffer in a window backend's window, and the key
// and close queries of glide_shim.h. Headless backends show nothing and report no input.
#pragma once

namespace glide_shim {

class GlideContext;

// After a grBufferSwap: the window shows the front buffer through the gamma table, the same
// bytes the frame export writes. Does nothing for a headless backend.
void show_front_buffer(GlideContext &context, int swap_interval);

}  // namespace glide_shim

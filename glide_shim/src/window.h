// The shim's window: showing the displayed buffer in a window backend's window, and the key
// and close queries of glide_shim.h. Headless backends show nothing and report no input.
#pragma once

namespace glide_shim {

class GlideContext;

// After a grBufferSwap: the window shows the front buffer through the gamma table, the same
// bytes the frame export writes. Does nothing for a headless backend.
void show_front_buffer(GlideContext &context, int swap_interval);

// At grSstWinClose with GLIDESHIM_HOLD=1 in the environment and a window backend: keeps the
// window showing the last frame until a key is pressed or the window is closed, so the last
// frame of a program that quits after `-n` frames can be looked at (and screenshot). Says so
// once on stderr. Does nothing headless or without the variable.
void hold_last_frame(GlideContext &context);

}  // namespace glide_shim

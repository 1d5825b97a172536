// A surface backend gives the shim a current OpenGL compatibility context and its function
// table. All rendering goes into the shim's own framebuffer objects, so OSMesa, EGL surfaceless
// and the SDL window's GLX/Wayland context produce the same pixels. A window backend also shows
// each scanned-out frame and collects keys. Only backend_*.cpp touch OSMesa, EGL or SDL.
#pragma once

#include "gl/gl_functions.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace glide_shim {

enum class BackendKind { OSMesa, EglSurfaceless, SdlWindow };

class Backend {
 public:
  virtual ~Backend() = default;
  virtual const char *name() const = 0;
  // Any GL entry point of this context by name (for code outside the shim); null if unknown.
  virtual void *proc_address(const char *name) const = 0;

  // The window part; headless backends keep these defaults (nothing shown, no input).
  virtual bool shows_window() const { return false; }
  // Shows a frame: 8-bit RGB rows, top row first, exactly as the frame export writes them.
  virtual void present(const std::vector<std::uint8_t> &, int, int) {}
  // grBufferSwap's interval: vertical retraces each swap waits for (0: none).
  virtual void set_swap_interval(int) {}
  // Reads the window system's pending events into the key queue (redrawing an exposed window).
  virtual void pump_events() {}
  // The oldest queued key (a GLIDESHIM_KEY_* code, glide_shim.h), 0 when none.
  virtual int next_key() { return 0; }
  virtual bool close_requested() const { return false; }

  GlFunctions gl;
};

// Creates and makes current a context of `kind`; on failure returns null and says why in `error`.
// width x height is the screen grSstWinOpen asked for: the window's size for a window backend.
std::unique_ptr<Backend> create_osmesa_backend(std::string &error);
std::unique_ptr<Backend> create_egl_backend(std::string &error);
std::unique_ptr<Backend> create_sdl_backend(int width, int height, std::string &error);
std::unique_ptr<Backend> create_backend(BackendKind kind, int width, int height,
                                        std::string &error);

// GLIDESHIM_BACKEND=osmesa|egl|sdl|window picks the backend (sdl and window are the same);
// unset means OSMesa. Returns false for any other value, leaving `kind` alone.
bool backend_from_environment(BackendKind &kind, std::string &error);

}  // namespace glide_shim

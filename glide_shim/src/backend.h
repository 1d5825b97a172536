// A surface backend gives the shim a current OpenGL compatibility context and its function
// table; nothing else. All rendering goes into the shim's own framebuffer objects, so OSMesa and
// EGL surfaceless produce the same pixels. Only backend_*.cpp touch OSMesa or EGL.
#pragma once

#include "gl_functions.h"

#include <memory>
#include <string>

namespace glide_shim {

enum class BackendKind { OSMesa, EglSurfaceless };

class Backend {
 public:
  virtual ~Backend() = default;
  virtual const char *name() const = 0;
  // Any GL entry point of this context by name (for code outside the shim); null if unknown.
  virtual void *proc_address(const char *name) const = 0;
  GlFunctions gl;
};

// Creates and makes current a context of `kind`; on failure returns null and says why in `error`.
std::unique_ptr<Backend> create_osmesa_backend(std::string &error);
std::unique_ptr<Backend> create_egl_backend(std::string &error);
std::unique_ptr<Backend> create_backend(BackendKind kind, std::string &error);

// GLIDESHIM_BACKEND=osmesa|egl picks the backend; unset means OSMesa. Returns false for any
// other value, leaving `kind` alone.
bool backend_from_environment(BackendKind &kind, std::string &error);

}  // namespace glide_shim

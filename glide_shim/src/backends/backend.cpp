// Backend selection and the shared part of loading the GL function table.
#include "backends/backend.h"

#include <cstdlib>
#include <cstring>

namespace glide_shim {

std::string GlFunctions::load(const std::function<void *(const char *)> &lookup) {
#define GLIDESHIM_LOAD_GL(fn)                                       \
  fn = reinterpret_cast<decltype(fn)>(lookup(#fn));                 \
  if (fn == nullptr) return #fn;
  GLIDESHIM_GL_FUNCTIONS(GLIDESHIM_LOAD_GL)
#undef GLIDESHIM_LOAD_GL
  return "";
}

std::unique_ptr<Backend> create_backend(BackendKind kind, int width, int height,
                                        std::string &error) {
  switch (kind) {
    case BackendKind::OSMesa: return create_osmesa_backend(error);
    case BackendKind::EglSurfaceless: return create_egl_backend(error);
    case BackendKind::SdlWindow: return create_sdl_backend(width, height, error);
  }
  error = "unknown backend";
  return nullptr;
}

bool backend_from_environment(BackendKind &kind, std::string &error) {
  const char *value = std::getenv("GLIDESHIM_BACKEND");
  if (value == nullptr || *value == '\0' || std::strcmp(value, "osmesa") == 0) {
    kind = BackendKind::OSMesa;
    return true;
  }
  if (std::strcmp(value, "egl") == 0) {
    kind = BackendKind::EglSurfaceless;
    return true;
  }
  if (std::strcmp(value, "sdl") == 0 || std::strcmp(value, "window") == 0) {
    kind = BackendKind::SdlWindow;
    return true;
  }
  error = std::string("GLIDESHIM_BACKEND='") + value +
          "' is not a backend (use osmesa, egl, or sdl for a window)";
  return false;
}

}  // namespace glide_shim

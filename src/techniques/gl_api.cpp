// Loading the plain-GL entry points from the shim's context.
#include "techniques/gl_api.h"

#include <glide_shim.h>

namespace gs {

bool load_gl_api(GlApi &api, std::string &error) {
#define GS_LOAD_GL(name)                                                          \
  api.name = reinterpret_cast<decltype(api.name)>(glideShimGetProcAddress(#name)); \
  if (api.name == nullptr) {                                                      \
    error = "the GL context has no " #name;                                       \
    return false;                                                                 \
  }
  GS_GL_FUNCTIONS(GS_LOAD_GL)
#undef GS_LOAD_GL
  return true;
}

}  // namespace gs

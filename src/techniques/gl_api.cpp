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

void set_eye_linear_texgen(const GlApi &gl, const glm::mat4 &to_texture) {
  const GLenum coords[4] = {GL_S, GL_T, GL_R, GL_Q};
  const GLenum enables[4] = {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
                             GL_TEXTURE_GEN_Q};
  for (int row = 0; row < 4; ++row) {
    const GLfloat plane[4] = {to_texture[0][row], to_texture[1][row], to_texture[2][row],
                              to_texture[3][row]};
    gl.glTexGeni(coords[row], GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    gl.glTexGenfv(coords[row], GL_EYE_PLANE, plane);
    gl.glEnable(enables[row]);
  }
}

}  // namespace gs

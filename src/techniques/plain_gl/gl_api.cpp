// Loading the plain-GL entry points from the shim's context.
#include "techniques/plain_gl/gl_api.h"

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

namespace {

// EYE_LINEAR texgen for the active unit, enabled: s, t, r, q are the rows of `to_texture`.
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

}  // namespace

void bind_projected_pair(const GlApi &gl, int first_unit, const GLuint textures[2],
                         const glm::mat4 *const to_texture[2]) {
  for (int i = 0; i < 2; ++i) {
    gl.glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + first_unit + i));
    gl.glBindTexture(GL_TEXTURE_2D, textures[i]);
    gl.glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    set_eye_linear_texgen(gl, *to_texture[i]);
    gl.glEnable(GL_TEXTURE_2D);
  }
  gl.glActiveTexture(GL_TEXTURE0);
}

void release_projected_pair(const GlApi &gl, int first_unit) {
  for (int i = 1; i >= 0; --i) {
    gl.glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + first_unit + i));
    gl.glBindTexture(GL_TEXTURE_2D, 0);
    gl.glDisable(GL_TEXTURE_2D);
    for (GLenum gen : {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q})
      gl.glDisable(gen);
  }
  gl.glActiveTexture(GL_TEXTURE0);
}

}  // namespace gs

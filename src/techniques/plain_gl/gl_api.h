// The OpenGL entry points the plain-GL techniques (depth maps, stencil volumes) call, taken from
// the shim's context with glideShimGetProcAddress (the shim owns the context; nothing here links
// libGL). Load once per window, between glideShimBeginGL and glideShimEndGL or after.
#pragma once

#include <GL/gl.h>
#include <GL/glext.h>
#include <glm/glm.hpp>

#include <string>

namespace gs {

#define GS_GL_FUNCTIONS(X)                                                                        \
  X(glEnable) X(glDisable) X(glClear) X(glClearColor) X(glClearDepth) X(glClearStencil)          \
  X(glDepthFunc) X(glDepthMask) X(glDepthRange) X(glColorMask) X(glStencilFunc) X(glStencilOp)    \
  X(glStencilOpSeparate) X(glStencilMask) X(glCullFace) X(glFrontFace) X(glPolygonOffset)        \
  X(glBlendFunc) X(glAlphaFunc) X(glShadeModel) X(glMatrixMode) X(glLoadMatrixf)                  \
  X(glLoadIdentity) X(glMultMatrixf) X(glEnableClientState) X(glDisableClientState)              \
  X(glVertexPointer) X(glColorPointer) X(glNormalPointer) X(glTexCoordPointer) X(glDrawElements) \
  X(glDrawArrays) X(glColor4f) X(glGenTextures) X(glDeleteTextures) X(glBindTexture)             \
  X(glTexImage2D) X(glTexSubImage2D) X(glTexParameteri) X(glTexParameterfv) X(glTexGeni)         \
  X(glTexGenfv) X(glTexEnvi) X(glTexEnvfv) X(glActiveTexture) X(glCopyTexSubImage2D)             \
  X(glGenFramebuffers) X(glDeleteFramebuffers) X(glBindFramebuffer) X(glFramebufferTexture2D)    \
  X(glCheckFramebufferStatus) X(glViewport) X(glScissor) X(glDrawBuffer) X(glReadBuffer)         \
  X(glReadPixels) X(glGetIntegerv) X(glGetFloatv) X(glClipPlane) X(glFinish) X(glFlush)          \
  X(glGetError) X(glPushAttrib) X(glPopAttrib) X(glLineWidth) X(glPointSize) X(glLightModelfv)   \
  X(glDrawBuffers)

struct GlApi {
#define GS_DECLARE_GL(name) decltype(&::name) name = nullptr;
  GS_GL_FUNCTIONS(GS_DECLARE_GL)
#undef GS_DECLARE_GL
};

// Fills `api` from the shim's current context; false with `error` naming the first missing one.
bool load_gl_api(GlApi &api, std::string &error);

// Two projected textures on texture units `first_unit` and `first_unit + 1`, each modulating the
// fragment and addressed by EYE_LINEAR texgen whose s, t, r, q are the rows of its matrix: planes
// in the vertex arrays' space, given while the modelview matrix is the camera's view of them.
// Leaves unit 0 active. release_projected_pair unbinds both and turns their texgen off.
void bind_projected_pair(const GlApi &gl, int first_unit, const GLuint textures[2],
                         const glm::mat4 *const to_texture[2]);
void release_projected_pair(const GlApi &gl, int first_unit);

}  // namespace gs

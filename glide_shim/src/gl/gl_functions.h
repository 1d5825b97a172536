// The OpenGL entry points the shim uses, resolved at run time from whichever backend made the
// context (OSMesa or EGL). Resolving by hand, rather than linking libGL, is what lets one binary
// pick its backend at run time: OSMesa and glvnd's libGL both export gl* and must not meet.
#pragma once

#include <GL/gl.h>
#include <GL/glext.h>

#include <functional>
#include <string>

namespace glide_shim {

// X(name) for every GL function called by the shim. decltype(&::glName) gives the pointer type
// without odr-using the symbol, so nothing is linked against libGL or libOSMesa.
#define GLIDESHIM_GL_FUNCTIONS(X) \
  X(glViewport) X(glScissor) X(glEnable) \
  X(glDisable) X(glClear) X(glClearColor) X(glClearDepth) X(glClearStencil) X(glColorMask) \
  X(glDepthMask) X(glDepthFunc) X(glBlendFunc) X(glReadPixels) X(glDrawPixels) \
  X(glPixelStorei) X(glWindowPos2i) X(glFinish) X(glFlush) X(glGenTextures) \
  X(glDeleteTextures) X(glBindTexture) X(glTexImage2D) X(glTexSubImage2D) X(glTexParameteri) \
  X(glActiveTexture) X(glGenFramebuffers) X(glDeleteFramebuffers) X(glBindFramebuffer) \
  X(glFramebufferRenderbuffer) X(glCheckFramebufferStatus) X(glGenRenderbuffers) \
  X(glDeleteRenderbuffers) X(glBindRenderbuffer) X(glRenderbufferStorage) X(glDrawBuffer) \
  X(glReadBuffer) X(glCreateShader) X(glShaderSource) X(glCompileShader) X(glGetShaderiv) \
  X(glGetShaderInfoLog) X(glCreateProgram) X(glAttachShader) X(glBindAttribLocation) \
  X(glLinkProgram) X(glGetProgramiv) X(glGetProgramInfoLog) X(glUseProgram) X(glDeleteShader) \
  X(glDeleteProgram) X(glGetUniformLocation) X(glUniform1i) X(glUniform1f) X(glUniform2f) \
  X(glUniform2fv) X(glUniform3f) X(glUniform4f) X(glUniform4fv) X(glVertexAttribPointer) X(glEnableVertexAttribArray) X(glDisableVertexAttribArray) \
  X(glDrawArrays) X(glPushAttrib) X(glPopAttrib) \
  X(glPushClientAttrib) X(glPopClientAttrib) X(glMatrixMode) X(glPushMatrix) X(glPopMatrix) \
  X(glLoadIdentity) X(glOrtho) X(glTexEnvi) X(glEnableClientState) \
  X(glDisableClientState) X(glVertexPointer) X(glColorPointer) X(glTexCoordPointer) X(glStencilMask) \
  X(glStencilFunc) X(glStencilOp) X(glGetBooleanv) \
  X(glBindBuffer) X(glGenQueries) X(glDeleteQueries) X(glBeginQuery) \
  X(glEndQuery) X(glGetQueryObjectuiv)

struct GlFunctions {
#define GLIDESHIM_DECLARE_GL(name) decltype(&::name) name = nullptr;
  GLIDESHIM_GL_FUNCTIONS(GLIDESHIM_DECLARE_GL)
#undef GLIDESHIM_DECLARE_GL

  // Fills every pointer through `lookup`; returns the name of the first one missing, or "".
  std::string load(const std::function<void *(const char *)> &lookup);
};

}  // namespace glide_shim

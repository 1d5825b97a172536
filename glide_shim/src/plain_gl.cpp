// Plain OpenGL between Glide calls (glide_shim.h): the shim flushes its queue, saves GL state and
// lends its context and frame buffer to the caller, then takes them back.
#include "context.h"
#include "gl/gl_renderer.h"

using glide_shim::current;

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

FxBool glideShimBeginGL(void) {
  auto &ctx = current();
  if (!ctx.require_open("glideShimBeginGL")) return FXFALSE;
  if (ctx.plain_gl) {
    ctx.report(GLIDESHIM_ERR_INCONSISTENT, "glideShimBeginGL: plain GL is already begun");
    return FXFALSE;
  }
  if (ctx.texture_target.active) {
    ctx.report(GLIDESHIM_ERR_INCONSISTENT,
               "glideShimBeginGL: call glideShimRenderToFrameBuffer first");
    return FXFALSE;
  }
  ctx.renderer->begin_plain_gl();
  ctx.plain_gl = true;
  return FXTRUE;
}

void glideShimEndGL(void) {
  auto &ctx = current();
  if (!ctx.plain_gl) {
    ctx.report(GLIDESHIM_ERR_INCONSISTENT, "glideShimEndGL: glideShimBeginGL was not called");
    return;
  }
  ctx.renderer->end_plain_gl();
  ctx.plain_gl = false;
}

void *glideShimGetProcAddress(const char *name) {
  auto &ctx = current();
  if (name == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "glideShimGetProcAddress: name is NULL");
    return nullptr;
  }
  if (!ctx.renderer) {
    ctx.report(GLIDESHIM_ERR_NOT_INITIALIZED, "glideShimGetProcAddress: no window is open");
    return nullptr;
  }
  return ctx.renderer->proc_address(name);
}

}  // namespace glide_shim_api

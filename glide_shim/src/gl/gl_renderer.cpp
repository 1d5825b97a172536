// The emulated frame buffer: RGB565 colour buffers that stand for the Voodoo's front and back
// buffers, sharing one depth buffer as the Voodoo's aux buffer does; their clears and region
// access, the side target that stands for texture memory, and the hand-over to plain GL. Drawing
// is in draw_path.cpp, program_cache.cpp and compare_to_bias_draw.cpp.
#include "gl/gl_renderer.h"
#include "gl/gl_renderer_internal.h"

#include "context.h"

#include <algorithm>
#include <cstddef>

namespace glide_shim {

using namespace gl_internal;

GlRenderer::GlRenderer(GlideContext &context, std::unique_ptr<Backend> backend, int width,
                       int height)
    : context_(context), backend_(std::move(backend)), width_(width), height_(height) {}

GlRenderer::~GlRenderer() {
  const GlFunctions &gl = backend_->gl;
  textures_.release(gl);
  for (auto &entry : programs_) gl.glDeleteProgram(entry.second.program);
  if (bias_mark_program_ != 0) gl.glDeleteProgram(bias_mark_program_);
  if (query_ != 0) gl.glDeleteQueries(1, &query_);
  for (ClearSource *source : {&clear_source_, &whole_clear_source_}) {
    if (source->framebuffer == 0) continue;
    gl.glDeleteFramebuffers(1, &source->framebuffer);
    gl.glDeleteRenderbuffers(1, &source->color);
    if (source->depth != 0) gl.glDeleteRenderbuffers(1, &source->depth);
  }
  gl.glDeleteFramebuffers(1, &framebuffer_);
  gl.glDeleteRenderbuffers(2, color_buffers_);
  gl.glDeleteRenderbuffers(1, &depth_buffer_);
  if (texture_framebuffer_ != 0) {
    gl.glDeleteFramebuffers(1, &texture_framebuffer_);
    gl.glDeleteRenderbuffers(1, &texture_color_);
    gl.glDeleteRenderbuffers(1, &texture_depth_);
  }
}

std::unique_ptr<GlRenderer> GlRenderer::create(GlideContext &context, BackendKind kind,
                                               int width, int height, std::string &error) {
  std::unique_ptr<Backend> backend = create_backend(kind, width, height, error);
  if (!backend) return nullptr;
  std::unique_ptr<GlRenderer> renderer(
      new GlRenderer(context, std::move(backend), width, height));
  if (!renderer->build_framebuffer(error)) return nullptr;
  return renderer;
}

bool GlRenderer::build_framebuffer(std::string &error) {
  const GlFunctions &gl = backend_->gl;
  gl.glGenFramebuffers(1, &framebuffer_);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glGenRenderbuffers(2, color_buffers_);
  for (int i = 0; i < 2; ++i) {
    gl.glBindRenderbuffer(GL_RENDERBUFFER, color_buffers_[i]);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGB565, width_, height_);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i),
                                 GL_RENDERBUFFER, color_buffers_[i]);
  }
  // 24 bits hold 1/w finely enough for w up to ~1e4 per unit step; stencil is for the shadow
  // volume technique that draws in plain GL between Glide calls.
  gl.glGenRenderbuffers(1, &depth_buffer_);
  gl.glBindRenderbuffer(GL_RENDERBUFFER, depth_buffer_);
  gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width_, height_);
  gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                               depth_buffer_);
  if (gl.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "the RGB565 + depth framebuffer object is incomplete";
    return false;
  }
  target_ = {framebuffer_, width_, height_};
  gl.glViewport(0, 0, width_, height_);
  gl.glDisable(GL_DITHER);  // the shader does the Voodoo's dither itself
  gl.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.glGenQueries(1, &query_);
  return true;
}

int GlRenderer::buffer_index(GrBuffer_t buffer) const {
  return buffer == GR_BUFFER_FRONTBUFFER ? front_ : 1 - front_;
}

void GlRenderer::swap_buffers() {
  flush();
  front_ = 1 - front_;
}

void GlRenderer::begin_plain_gl() {
  flush();
  stencil_untouched_ = false;  // plain GL code may keep values in the stencil buffer
  const GlFunctions &gl = backend_->gl;
  gl.glPushAttrib(GL_ALL_ATTRIB_BITS);
  gl.glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
  for (GLenum matrix : {GL_PROJECTION, GL_MODELVIEW, GL_TEXTURE}) {
    gl.glMatrixMode(matrix);
    gl.glPushMatrix();
    gl.glLoadIdentity();
  }
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glDrawBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + buffer_index(context_.raster.render_buffer)));
  gl.glViewport(0, 0, width_, height_);
  gl.glScissor(0, 0, width_, height_);
  gl.glUseProgram(0);
  gl.glBindTexture(GL_TEXTURE_2D, 0);
  // The shim's generic attribute arrays point into its vertex queue; attribute 0 would override
  // the caller's glVertexPointer. flush() enables them again before the next Glide draw.
  for (unsigned attribute : {kPosition, kDepth, kColor, kStq, kFog}) {
    gl.glDisableVertexAttribArray(attribute);
  }
  for (GLenum cap : {GL_DEPTH_TEST, GL_BLEND, GL_CULL_FACE, GL_STENCIL_TEST, GL_SCISSOR_TEST}) {
    gl.glDisable(cap);
  }
  gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl.glDepthMask(GL_TRUE);
  gl.glStencilMask(0xFF);
  // GL's default clear values: a W-buffer grBufferClear leaves the clear depth at 0 (far 1/w).
  gl.glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  gl.glClearDepth(1.0);
  gl.glClearStencil(0);
}

void GlRenderer::end_plain_gl() {
  const GlFunctions &gl = backend_->gl;
  for (GLenum matrix : {GL_TEXTURE, GL_MODELVIEW, GL_PROJECTION}) {
    gl.glMatrixMode(matrix);
    gl.glPopMatrix();
  }
  gl.glPopClientAttrib();
  gl.glPopAttrib();
  // State the attribute stack does not cover: the shim sets what it needs before every draw.
  gl.glUseProgram(0);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glActiveTexture(GL_TEXTURE0);
  gl.glBindTexture(GL_TEXTURE_2D, 0);
  gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
  gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

void GlRenderer::clear(std::uint16_t rgb565, bool color, double gl_depth, bool depth) {
  flush();
  const GlFunctions &gl = backend_->gl;
  apply_fixed_function_state();
  GLbitfield mask = 0;
  if (color && context_.raster.rgb_mask) {
    // Exact 565 levels, so GL's float-to-565 conversion cannot round them elsewhere.
    gl.glClearColor(static_cast<float>(rgb565 >> 11) / 31.0f,
                    static_cast<float>((rgb565 >> 5) & 0x3F) / 63.0f,
                    static_cast<float>(rgb565 & 0x1F) / 31.0f, 1.0f);
    mask |= GL_COLOR_BUFFER_BIT;
  }
  if (depth) {
    gl.glDepthMask(GL_TRUE);
    gl.glClearDepth(gl_depth);
    mask |= GL_DEPTH_BUFFER_BIT;
    // Fast path: depth and stencil share 32-bit words, and llvmpipe clears depth alone by a
    // read-modify-write of every word (six times the work of the fill that clears both). The
    // shim's own stencil use (COMPARE_TO_BIAS) returns every bit it sets to 0, so until plain GL
    // code has had the frame buffer the stencil holds zeros (or what GL left undefined), and
    // clearing it to 0 as well changes nothing anyone can read.
    const bool texture_target = target_.framebuffer != framebuffer_;
    if (context_.fast_paths && (texture_target || stencil_untouched_)) {
      gl.glStencilMask(0xFF);
      gl.glClearStencil(0);
      mask |= GL_STENCIL_BUFFER_BIT;
    }
  }
  if (mask != 0) mask = clear_by_copy(rgb565, gl_depth, mask);
  if (mask != 0) gl.glClear(mask);
}

void GlRenderer::read_color(int index, int x, int y, int w, int h, std::uint16_t *dst,
                            std::size_t stride) {
  flush();
  const GlFunctions &gl = backend_->gl;
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glReadBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + index));
  // GL row 0 is the bottom; read the block in one call, then hand rows out top first.
  std::vector<std::uint16_t> block(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  gl.glReadPixels(x, height_ - (y + h), w, h, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, block.data());
  auto *out = reinterpret_cast<std::uint8_t *>(dst);
  for (int row = 0; row < h; ++row) {
    const std::uint16_t *line = block.data() + static_cast<std::size_t>(h - 1 - row) * w;
    std::copy(line, line + w, reinterpret_cast<std::uint16_t *>(out + row * stride));
  }
}

void GlRenderer::write_color(int index, int x, int y, int w, int h, const std::uint16_t *src,
                             std::size_t stride) {
  flush();
  const GlFunctions &gl = backend_->gl;
  std::vector<std::uint16_t> block(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  const auto *in = reinterpret_cast<const std::uint8_t *>(src);
  for (int row = 0; row < h; ++row) {
    const auto *line = reinterpret_cast<const std::uint16_t *>(in + row * stride);
    std::copy(line, line + w, block.data() + static_cast<std::size_t>(h - 1 - row) * w);
  }
  // LFB writes bypass the pixel pipeline: fixed function with every test and blend off.
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glDrawBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + index));
  gl.glUseProgram(0);
  gl.glDisable(GL_SCISSOR_TEST);
  gl.glDisable(GL_DEPTH_TEST);
  gl.glDisable(GL_BLEND);
  gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  gl.glWindowPos2i(x, height_ - (y + h));
  gl.glDrawPixels(w, h, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, block.data());
}

void GlRenderer::write_depth(int x, int y, int w, int h, const float *src) {
  flush();
  const GlFunctions &gl = backend_->gl;
  std::vector<float> block(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (int row = 0; row < h; ++row) {  // rows from the top in, GL rows from the bottom out
    const float *line = src + static_cast<std::size_t>(row) * w;
    std::copy(line, line + w, block.data() + static_cast<std::size_t>(h - 1 - row) * w);
  }
  // GL writes drawn depth only through the depth test, so the test passes always.
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  gl.glUseProgram(0);
  gl.glDisable(GL_SCISSOR_TEST);
  gl.glDisable(GL_BLEND);
  gl.glEnable(GL_DEPTH_TEST);
  gl.glDepthFunc(GL_ALWAYS);
  gl.glDepthMask(GL_TRUE);
  gl.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl.glWindowPos2i(x, height_ - (y + h));
  gl.glDrawPixels(w, h, GL_DEPTH_COMPONENT, GL_FLOAT, block.data());
}

void GlRenderer::begin_texture_target(int side) {
  flush();
  const GlFunctions &gl = backend_->gl;
  if (side != texture_side_) {
    if (texture_framebuffer_ == 0) {
      gl.glGenFramebuffers(1, &texture_framebuffer_);
      gl.glGenRenderbuffers(1, &texture_color_);
      gl.glGenRenderbuffers(1, &texture_depth_);
    }
    gl.glBindFramebuffer(GL_FRAMEBUFFER, texture_framebuffer_);
    gl.glBindRenderbuffer(GL_RENDERBUFFER, texture_color_);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGB565, side, side);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                 texture_color_);
    gl.glBindRenderbuffer(GL_RENDERBUFFER, texture_depth_);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, side, side);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                 texture_depth_);
    texture_side_ = side;
  }
  target_ = {texture_framebuffer_, side, side};
}

void GlRenderer::end_texture_target(std::uint16_t *words) {
  flush();
  const GlFunctions &gl = backend_->gl;
  gl.glBindFramebuffer(GL_FRAMEBUFFER, texture_framebuffer_);
  gl.glReadBuffer(GL_COLOR_ATTACHMENT0);
  std::vector<std::uint16_t> block(static_cast<std::size_t>(texture_side_) * texture_side_);
  gl.glReadPixels(0, 0, texture_side_, texture_side_, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, block.data());
  for (int row = 0; row < texture_side_; ++row) {  // GL rows bottom first; texels top first
    const std::uint16_t *line = block.data() + static_cast<std::size_t>(texture_side_ - 1 - row) * texture_side_;
    std::copy(line, line + texture_side_, words + static_cast<std::size_t>(row) * texture_side_);
  }
  target_ = {framebuffer_, width_, height_};
}

void GlRenderer::read_depth(int x, int y, int w, int h, float *dst) {
  flush();
  const GlFunctions &gl = backend_->gl;
  gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  std::vector<float> block(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  gl.glReadPixels(x, height_ - (y + h), w, h, GL_DEPTH_COMPONENT, GL_FLOAT, block.data());
  for (int row = 0; row < h; ++row) {
    const float *line = block.data() + static_cast<std::size_t>(h - 1 - row) * w;
    std::copy(line, line + w, dst + static_cast<std::size_t>(row) * w);
  }
}

}  // namespace glide_shim

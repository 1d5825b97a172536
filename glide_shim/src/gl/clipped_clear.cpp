// A clear of part of the target (grBufferClear inside a clip window smaller than the buffer, as
// on the Voodoo only the clip window is filled): Mesa turns a scissored glClear into a quad drawn
// through a fragment program, about 33 instructions a pixel on llvmpipe with a depth clear. On the
// fast paths the region is copied instead (glCopyImageSubData, a row-by-row memcpy on llvmpipe)
// from a side buffer that holds the clear values: the same words, for a fraction of the work.
#include "gl/gl_renderer.h"
#include "gl/gl_renderer_internal.h"

#include "context.h"

#include <cstdio>
#include <cstring>

namespace glide_shim {
namespace {

// GL 4.3 or ARB_copy_image: glCopyImageSubData copies between renderbuffers of one format.
bool has_copy_image(const char *version, const char *extensions) {
  int major = 0, minor = 0;
  if (version != nullptr && std::sscanf(version, "%d.%d", &major, &minor) == 2 &&
      (major > 4 || (major == 4 && minor >= 3))) {
    return true;
  }
  return extensions != nullptr && std::strstr(extensions, "GL_ARB_copy_image") != nullptr;
}

}  // namespace

using namespace gl_internal;

bool GlRenderer::clear_by_copy(std::uint16_t rgb565, double gl_depth, unsigned mask) {
  const ClipRect &clip = context_.raster.clip;
  const int w = static_cast<int>(clip.max_x - clip.min_x), h = static_cast<int>(clip.max_y - clip.min_y);
  if (!context_.fast_paths || (w == target_.width && h == target_.height)) return false;
  // Depth and stencil share their words: the copy writes both, so only where clear() may
  // clear the stencil too (its fast path).
  if ((mask & GL_DEPTH_BUFFER_BIT) != 0 && (mask & GL_STENCIL_BUFFER_BIT) == 0) return false;
  const GlFunctions &gl = backend_->gl;
  if (copy_image_ == nullptr) {
    if (copy_image_checked_) return false;
    copy_image_checked_ = true;
    using GetString = const GLubyte *(*)(GLenum);
    auto get_string = reinterpret_cast<GetString>(backend_->proc_address("glGetString"));
    if (get_string == nullptr ||
        !has_copy_image(reinterpret_cast<const char *>(get_string(GL_VERSION)),
                        reinterpret_cast<const char *>(get_string(GL_EXTENSIONS)))) {
      return false;
    }
    copy_image_ = reinterpret_cast<decltype(copy_image_)>(backend_->proc_address("glCopyImageSubData"));
    if (copy_image_ == nullptr) return false;
  }
  if (w <= 0 || h <= 0) return true;  // an empty clip window clears nothing

  const bool color = (mask & GL_COLOR_BUFFER_BIT) != 0, depth = (mask & GL_DEPTH_BUFFER_BIT) != 0;
  ClearSource &source = clear_source_;
  if (w > source.width || h > source.height) {  // grown to the largest region asked for
    if (source.framebuffer == 0) {
      gl.glGenFramebuffers(1, &source.framebuffer);
      gl.glGenRenderbuffers(1, &source.color);
      gl.glGenRenderbuffers(1, &source.depth);
    }
    source.width = std::max(w, source.width), source.height = std::max(h, source.height);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, source.framebuffer);
    gl.glBindRenderbuffer(GL_RENDERBUFFER, source.color);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGB565, source.width, source.height);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, source.color);
    gl.glBindRenderbuffer(GL_RENDERBUFFER, source.depth);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, source.width, source.height);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                 source.depth);
    source.filled = false;
  }
  if (!source.filled || (color && source.rgb565 != rgb565) || (depth && source.gl_depth != gl_depth)) {
    // The side buffer filled whole (llvmpipe's tile fill) with this clear's values; a value not
    // cleared here keeps the one asked for, since the side buffer is refilled on any change.
    source.rgb565 = rgb565;
    source.gl_depth = gl_depth;
    source.filled = true;
    gl.glBindFramebuffer(GL_FRAMEBUFFER, source.framebuffer);
    gl.glDrawBuffer(GL_COLOR_ATTACHMENT0);
    gl.glDisable(GL_SCISSOR_TEST);
    gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.glDepthMask(GL_TRUE);
    gl.glStencilMask(0xFF);
    gl.glClearColor(static_cast<float>(rgb565 >> 11) / 31.0f,
                    static_cast<float>((rgb565 >> 5) & 0x3F) / 63.0f,
                    static_cast<float>(rgb565 & 0x1F) / 31.0f, 1.0f);
    gl.glClearDepth(gl_depth);
    gl.glClearStencil(0);
    gl.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    apply_fixed_function_state();  // back to the target, its scissor and masks
  }
  // The clip window in GL's rows from the bottom, as apply_fixed_function_state's scissor.
  const int x = static_cast<int>(clip.min_x);
  const int y = context_.raster.origin == GR_ORIGIN_UPPER_LEFT ? target_.height - static_cast<int>(clip.max_y)
                                                                : static_cast<int>(clip.min_y);
  const bool frame_buffer = target_.framebuffer == framebuffer_;
  if (color) {
    const unsigned into = frame_buffer ? color_buffers_[buffer_index(context_.raster.render_buffer)]
                                       : texture_color_;
    copy_image_(source.color, GL_RENDERBUFFER, 0, 0, 0, 0, into, GL_RENDERBUFFER, 0, x, y, 0, w, h, 1);
  }
  if (depth) {
    const unsigned into = frame_buffer ? depth_buffer_ : texture_depth_;
    copy_image_(source.depth, GL_RENDERBUFFER, 0, 0, 0, 0, into, GL_RENDERBUFFER, 0, x, y, 0, w, h, 1);
  }
  return true;
}

}  // namespace glide_shim

// Clears by copy, on the fast paths: the region is copied (glCopyImageSubData, a row-by-row
// memcpy on llvmpipe) from a side buffer that holds the clear values, the same words for less
// work than GL's clear where that is measured to cost more:
// - a clear of part of the target (grBufferClear inside a clip window smaller than the buffer, as
//   on the Voodoo only the clip window is filled): Mesa turns a scissored glClear into a quad
//   drawn through a fragment program, about 33 instructions a pixel on llvmpipe with a depth
//   clear. Colour and depth are copied.
// - the colour of a clear of the whole target, on llvmpipe only: it fills a 16-bit colour buffer
//   one pixel at a time (util_fill_rect's scalar loop for 2-byte pixels), 28% of the CPU time of
//   shim_bench's SDK Gouraud frame (perf, LP_NUM_THREADS=0), where the depth and stencil fill is
//   a 32-bit `rep stos` (10%) that glClear keeps. Only for a colour cleared whole twice in a row,
//   so a colour that changes every frame costs one glClear, not a refill plus a copy.
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

bool GlRenderer::load_copy_image() {
  if (copy_image_ != nullptr) return true;
  if (copy_image_checked_) return false;
  copy_image_checked_ = true;
  using GetString = const GLubyte *(*)(GLenum);
  auto get_string = reinterpret_cast<GetString>(backend_->proc_address("glGetString"));
  if (get_string == nullptr ||
      !has_copy_image(reinterpret_cast<const char *>(get_string(GL_VERSION)),
                      reinterpret_cast<const char *>(get_string(GL_EXTENSIONS)))) {
    return false;
  }
  const char *renderer = reinterpret_cast<const char *>(get_string(GL_RENDERER));
  copy_beats_color_fill_ = renderer != nullptr && std::strstr(renderer, "llvmpipe") != nullptr;
  copy_image_ = reinterpret_cast<decltype(copy_image_)>(backend_->proc_address("glCopyImageSubData"));
  return copy_image_ != nullptr;
}

unsigned GlRenderer::clear_by_copy(std::uint16_t rgb565, double gl_depth, unsigned mask) {
  const ClipRect &clip = context_.raster.clip;
  const int w = static_cast<int>(clip.max_x - clip.min_x), h = static_cast<int>(clip.max_y - clip.min_y);
  if (!context_.fast_paths) return mask;
  // A side buffer of its own for the whole target's colour: sharing one, each clipped clear of
  // another colour (step 1's corner in the fighter demo, every texture) refilled it whole at the
  // target's size, and each whole clear refilled it back (+5 M instructions a shadowed demo frame).
  const bool whole = w == target_.width && h == target_.height;
  ClearSource &source = whole ? whole_clear_source_ : clear_source_;
  bool color = (mask & GL_COLOR_BUFFER_BIT) != 0, depth = (mask & GL_DEPTH_BUFFER_BIT) != 0;
  if (whole) {  // the whole target: its colour only
    const bool repeated = last_whole_color_ == rgb565;
    last_whole_color_ = color ? std::optional<std::uint16_t>(rgb565) : std::nullopt;
    const bool held = source.filled && source.rgb565 == rgb565 && source.width >= w && source.height >= h;
    if (!color || !(repeated || held) || !load_copy_image() || !copy_beats_color_fill_) return mask;
    depth = false;
  } else {
    // Depth and stencil share their words: the copy writes both, so only where clear() may
    // clear the stencil too (its fast path).
    if (depth && (mask & GL_STENCIL_BUFFER_BIT) == 0) return mask;
    if (!load_copy_image()) return mask;
    if (w <= 0 || h <= 0) return 0;  // an empty clip window clears nothing
  }

  const GlFunctions &gl = backend_->gl;
  if (w > source.width || h > source.height) {  // grown to the largest region asked for
    if (source.framebuffer == 0) {
      gl.glGenFramebuffers(1, &source.framebuffer);
      gl.glGenRenderbuffers(1, &source.color);
      if (!whole) gl.glGenRenderbuffers(1, &source.depth);
    }
    source.width = std::max(w, source.width), source.height = std::max(h, source.height);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, source.framebuffer);
    gl.glBindRenderbuffer(GL_RENDERBUFFER, source.color);
    gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGB565, source.width, source.height);
    gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, source.color);
    if (!whole) {  // the whole target's side buffer holds colour only
      gl.glBindRenderbuffer(GL_RENDERBUFFER, source.depth);
      gl.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, source.width, source.height);
      gl.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                   source.depth);
    }
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
    gl.glClear(whole ? GL_COLOR_BUFFER_BIT
                     : GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
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
    ++colors_copied_;
  }
  if (depth) {
    const unsigned into = frame_buffer ? depth_buffer_ : texture_depth_;
    copy_image_(source.depth, GL_RENDERBUFFER, 0, 0, 0, 0, into, GL_RENDERBUFFER, 0, x, y, 0, w, h, 1);
  }
  return mask & ~static_cast<unsigned>((color ? GL_COLOR_BUFFER_BIT : 0) |
                                       (depth ? GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT : 0));
}

}  // namespace glide_shim

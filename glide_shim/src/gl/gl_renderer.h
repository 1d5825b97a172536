// The GL side of the shim: the emulated frame buffer (two RGB565 colour buffers and one depth
// buffer in a framebuffer object), the queue of primitives waiting to be drawn, and the
// translation of the context's state into a generated shader and fixed-function settings.
// Defined in gl_renderer.cpp (the frame buffer), draw_path.cpp, program_cache.cpp and
// compare_to_bias_draw.cpp.
#pragma once

#include "backends/backend.h"
#include "depth.h"
#include "gl/shader_source.h"
#include "gl/texture_cache.h"

#include <cstdint>
#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace glide_shim {

class GlideContext;

// One vertex as the GPU receives it. Only fields the current state reads were taken from the
// program's GrVertex; the rest are zero.
struct ShimVertex {
  float x, y;           // screen pixels in the Glide origin, snapped to 1/16 (12.4 fixed point)
  float depth;          // GL window depth [0,1]: 1/w for the W-buffer, ooz/65535 for the Z-buffer
  float r, g, b, a;     // iterated colour, 0..255
  float sow, tow, q;    // texture numerators and divisor (oow or tmuvtx[0].oow), screen-linear
  float fog;            // fog iterator: oow for table fog, ooz for iterated-Z fog, else 0
};

enum class Primitive { Triangles, Lines, Points };

// The vertices waiting to be drawn: a vector that grows without zeroing what it adds, so a
// triangle can be written straight into it.
class VertexQueue {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  const ShimVertex *data() const { return storage_.get(); }
  void clear() { size_ = 0; }
  ShimVertex *grow(std::size_t count) {  // `count` more vertices at the end, uninitialised
    if (size_ + count > capacity_) reserve(std::max(2 * capacity_, size_ + count));
    ShimVertex *added = storage_.get() + size_;
    size_ += count;
    return added;
  }
  void shrink(std::size_t count) { size_ -= count; }
  void append(const ShimVertex *vertices, std::size_t count) {
    std::copy(vertices, vertices + count, grow(count));
  }

 private:
  void reserve(std::size_t capacity) {
    std::unique_ptr<ShimVertex[]> storage(new ShimVertex[capacity]);
    std::copy(storage_.get(), storage_.get() + size_, storage.get());
    storage_ = std::move(storage);
    capacity_ = capacity;
  }
  std::unique_ptr<ShimVertex[]> storage_;
  std::size_t size_ = 0, capacity_ = 0;
};

class GlRenderer {
 public:
  // Makes the backend's context, the frame buffer and the vertex shader; null on failure.
  static std::unique_ptr<GlRenderer> create(GlideContext &context, BackendKind kind, int width,
                                            int height, std::string &error);
  ~GlRenderer();

  const char *backend_name() const { return backend_->name(); }
  Backend &backend() { return *backend_; }
  const GlFunctions &gl() const { return backend_->gl; }

  void queue(Primitive primitive, const ShimVertex *vertices, int count);
  // Room for `count` vertices of `primitive` at the end of the queue (drawing the queue first if
  // it holds another primitive), uninitialised, for the caller to write in place; unqueue(count)
  // takes the last `count` back (a vertex that failed its checks, a culled triangle).
  ShimVertex *queue_space(Primitive primitive, int count) {
    if (primitive != primitive_) {
      flush();
      primitive_ = primitive;
    }
    return queue_.grow(static_cast<std::size_t>(count));
  }
  void unqueue(int count) { queue_.shrink(static_cast<std::size_t>(count)); }
  void flush();  // draws the queue with the context's current state

  // Fills the clip window of the current render buffer; colour and depth each optional.
  void clear(std::uint16_t rgb565, bool color, double gl_depth, bool depth);
  void swap_buffers();
  int buffer_index(GrBuffer_t buffer) const;  // colour attachment behind FRONT or BACK

  // Region access with an upper-left origin, in the frame buffer's own 565 words.
  void read_color(int index, int x, int y, int w, int h, std::uint16_t *dst, std::size_t stride);
  void write_color(int index, int x, int y, int w, int h, const std::uint16_t *src,
                   std::size_t stride);
  void read_depth(int x, int y, int w, int h, float *dst);  // GL window depth [0,1]
  // Writes GL window depths (rows from the top) into the depth buffer, bypassing every test.
  void write_depth(int x, int y, int w, int h, const float *src);

  TextureCache &textures() { return textures_; }

  // Draws and clears go to a side x side 565 target standing for texture memory, until
  // end_texture_target hands its words back (rows from the top) and returns to the frame buffer.
  void begin_texture_target(int side);
  void end_texture_target(std::uint16_t *words);

  // Hands the GL context to outside code (glideShimBeginGL) and takes it back.
  void begin_plain_gl();
  void end_plain_gl();
  void *proc_address(const char *name) const { return backend_->proc_address(name); }

  void start_counting();
  // Draws the queue now, as flush() does, for primitives that never overlap one another (an LFB
  // write's one point per pixel): the perf counters' stages then count the whole queue in one
  // pass each, which gives the counts one primitive at a time would.
  void flush_disjoint();
  std::uint32_t pixels_counted() const { return pixels_counted_; }
  // Colour clears done by copy from the side buffer (clipped_clear.cpp), for the tests.
  std::uint64_t colors_copied() const { return colors_copied_; }

 private:
  GlRenderer(GlideContext &context, std::unique_ptr<Backend> backend, int width, int height);
  bool build_framebuffer(std::string &error);
  const ShaderProgram *program_for(const PipelineKey &key);
  // The same, with the key's defines() (its cache name) already made: flush makes it once.
  const ShaderProgram *program_for(const PipelineKey &key, const std::string &name);
  // Binds the TMU's texture and compiles the level it samples into a fast key (see
  // PipelineKey::level_compiled).
  void compile_level(PipelineKey &key);
  void apply_fixed_function_state();
  void set_fog_uniforms(const ShaderProgram &program);
  void use_program(const ShaderProgram *program, const PipelineKey &key);
  // Pixels of queue_[first, first + count) that pass every enabled test (an occlusion query).
  std::uint32_t samples_drawn(unsigned mode, int first, int count);
  // Draws queue_[first, first + count) with the bound program; in the COMPARE_TO_BIAS modes
  // only where the stored depth passes (stencil bit 7 marks it for the draw, then is cleared),
  // one primitive at a time when `depth_writes`. Returns the pixels drawn when `query` is set.
  std::uint32_t draw_tested(unsigned mode, int first, int count, bool query, bool depth_writes);
  unsigned bias_mark_program();  // writes a constant depth and no colour; 0 on failure
  // clear()'s work by copy (clipped_clear.cpp): on the fast paths, copies the region from a side
  // buffer where glCopyImageSubData costs less than GL's clear (a clip window smaller than the
  // target, from clear_source_; the whole target's colour on llvmpipe, from
  // whole_clear_source_). Returns the bits of the GL clear `mask` it left for glClear.
  unsigned clear_by_copy(std::uint16_t rgb565, double gl_depth, unsigned mask);
  bool load_copy_image();  // copy_image_, loaded once; false if the GL has none
  void draw_counting_stages(const ShaderProgram *program, const PipelineKey &key, unsigned mode);

  struct Target {
    unsigned framebuffer = 0;
    int width = 0, height = 0;
  };

  GlideContext &context_;
  std::unique_ptr<Backend> backend_;
  int width_, height_;  // the frame buffer
  Target target_;        // where draws go: the frame buffer or the texture target
  unsigned texture_framebuffer_ = 0, texture_color_ = 0, texture_depth_ = 0;
  int texture_side_ = 0;
  unsigned framebuffer_ = 0;
  unsigned color_buffers_[2] = {0, 0};
  unsigned depth_buffer_ = 0;
  int front_ = 0;  // the attachment scanned out; the other one is the back buffer
  Primitive primitive_ = Primitive::Triangles;
  VertexQueue queue_;
  std::map<std::string, ShaderProgram> programs_;
  std::map<std::string, int> states_seen_;  // fast keys drawn so far without their program
  TextureCache textures_;
  bool counting_ = false;
  unsigned drawing_program_ = 0;  // the program use_program bound last
  // The stored-depth intervals the COMPARE_TO_BIAS test passes on, as apply_fixed_function_state
  // set them up (0 outside those modes, for NEVER, and when it passes everywhere).
  DepthInterval bias_intervals_[2] = {};
  int bias_interval_count_ = 0;
  unsigned bias_mark_program_ = 0;
  int bias_mark_depth_ = -1, bias_mark_screen_ = -1, bias_mark_y_down_ = -1;
  unsigned query_ = 0;
  std::uint32_t pixels_counted_ = 0;
  bool disjoint_ = false;  // flush_disjoint is drawing
  // clear_by_copy's side buffers (GL rows from the bottom, like any renderbuffer), holding the
  // values of the last clear it filled them for.
  struct ClearSource {
    unsigned framebuffer = 0, color = 0, depth = 0;
    int width = 0, height = 0;
    bool filled = false;
    std::uint16_t rgb565 = 0;
    double gl_depth = 0.0;
  };
  ClearSource clear_source_;        // for clipped clears: colour, depth and stencil
  ClearSource whole_clear_source_;  // for the whole target's colour (no depth renderbuffer)
  // The colour of the last clear of the whole target, if it cleared colour.
  std::optional<std::uint16_t> last_whole_color_;
  decltype(&::glCopyImageSubData) copy_image_ = nullptr;  // loaded on the first clear by copy
  bool copy_image_checked_ = false;
  bool copy_beats_color_fill_ = false;  // the renderer is llvmpipe (clipped_clear.cpp)
  std::uint64_t colors_copied_ = 0;
  // No plain GL code (glideShimBeginGL) has drawn into the frame buffer yet, so its stencil
  // holds nothing but zeros (see clear()).
  bool stencil_untouched_ = true;
};

}  // namespace glide_shim

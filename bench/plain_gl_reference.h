// The plain-GL references shim_bench times the shim against: the same pixels as a porter would
// draw them in plain GL, in the shim's own context (PlainGl: the triangle stream; PlainSdk: the
// SDK-style frames of shim_workloads.h).
#pragma once

#include "gl/gl_renderer.h"
#include "shim_workloads.h"

#include <glide.h>

#include <vector>

namespace shim_bench {

using shim_workloads::Triangle;

// The shim enables generic attribute arrays 0-4 for its own draws; attribute 0 would stand in
// for glVertexPointer, so plain GL turns them off first (the shim turns them on at each draw).
void disable_shim_arrays(const glide_shim::GlFunctions &gl) {
  for (unsigned attribute = 0; attribute < 5; ++attribute) gl.glDisableVertexAttribArray(attribute);
}

// The plain-GL comparison of the triangle stream: fixed-function Gouraud * bilinear texture,
// client vertex arrays, into its own 640x480 RGB565 framebuffer object in the shim's context.
class PlainGl {
 public:
  PlainGl(const glide_shim::GlFunctions &gl, const std::vector<Triangle> &triangles,
          const std::vector<FxU16> &texels)
      : gl_(gl) {
    for (const Triangle &t : triangles) {
      for (const GrVertex &v : t.v) {
        positions_.insert(positions_.end(), {v.x, v.y});
        colors_.insert(colors_.end(), {static_cast<unsigned char>(v.r), static_cast<unsigned char>(v.g),
                                       static_cast<unsigned char>(v.b), 255});
        coords_.insert(coords_.end(), {v.tmuvtx[0].sow / 256.0f, v.tmuvtx[0].tow / 256.0f});
      }
    }
    gl_.glGenFramebuffers(1, &framebuffer_);
    gl_.glGenRenderbuffers(1, &color_);
    gl_.glBindRenderbuffer(GL_RENDERBUFFER, color_);
    gl_.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGB565, 640, 480);
    gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl_.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    gl_.glGenTextures(1, &texture_);
    gl_.glBindTexture(GL_TEXTURE_2D, texture_);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl_.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 256, 256, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5,
                     texels.data());
  }

  void draw() {
    gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl_.glDrawBuffer(GL_COLOR_ATTACHMENT0);
    gl_.glUseProgram(0);
    disable_shim_arrays(gl_);
    gl_.glDisable(GL_SCISSOR_TEST);
    gl_.glDisable(GL_DEPTH_TEST);
    gl_.glDisable(GL_BLEND);
    gl_.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl_.glViewport(0, 0, 640, 480);
    gl_.glMatrixMode(GL_PROJECTION);
    gl_.glLoadIdentity();
    gl_.glOrtho(0, 640, 480, 0, -1, 1);
    gl_.glMatrixMode(GL_MODELVIEW);
    gl_.glLoadIdentity();
    gl_.glEnable(GL_TEXTURE_2D);
    gl_.glBindTexture(GL_TEXTURE_2D, texture_);
    gl_.glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    gl_.glClear(GL_COLOR_BUFFER_BIT);
    gl_.glEnableClientState(GL_VERTEX_ARRAY);
    gl_.glEnableClientState(GL_COLOR_ARRAY);
    gl_.glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    gl_.glVertexPointer(2, GL_FLOAT, 0, positions_.data());
    gl_.glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors_.data());
    gl_.glTexCoordPointer(2, GL_FLOAT, 0, coords_.data());
    gl_.glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(positions_.size() / 2));
    gl_.glDisableClientState(GL_VERTEX_ARRAY);
    gl_.glDisableClientState(GL_COLOR_ARRAY);
    gl_.glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    gl_.glDisable(GL_TEXTURE_2D);
    gl_.glFinish();
  }

 private:
  const glide_shim::GlFunctions &gl_;
  std::vector<float> positions_, coords_;
  std::vector<unsigned char> colors_;
  unsigned framebuffer_ = 0, color_ = 0, texture_ = 0;
};

// The SDK-style frames as a porter would write them in plain GL: a 640x480 RGB565 + 24-bit depth
// framebuffer object (no stencil: the frame has no use for one), glClear of colour and depth, depth test LESS, smooth shading, the
// vertices in homogeneous form so colour and texture are interpolated with perspective as the
// Voodoo does, GL_MODULATE with a GL_LINEAR 256x256 565 texture, blending SRC_ALPHA /
// ONE_MINUS_SRC_ALPHA, glFinish.
class PlainSdk {
 public:
  PlainSdk(const glide_shim::GlFunctions &gl, const std::vector<FxU16> &texels) : gl_(gl) {
    gl_.glGenFramebuffers(1, &framebuffer_);
    gl_.glGenRenderbuffers(2, renderbuffers_);
    gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl_.glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
    gl_.glRenderbufferStorage(GL_RENDERBUFFER, GL_RGB565, shim_workloads::kWidth, shim_workloads::kHeight);
    gl_.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  renderbuffers_[0]);
    gl_.glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
    gl_.glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, shim_workloads::kWidth,
                              shim_workloads::kHeight);
    gl_.glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  renderbuffers_[1]);
    gl_.glGenTextures(1, &texture_);
    gl_.glBindTexture(GL_TEXTURE_2D, texture_);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl_.glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 256, 256, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5,
                     texels.data());
    for (shim_workloads::Workload w : {shim_workloads::Workload::Gouraud, shim_workloads::Workload::Textured,
                                   shim_workloads::Workload::Blended}) {
      Arrays &a = arrays_[static_cast<int>(w)];
      for (const shim_workloads::Point &p : shim_workloads::points(w)) {
        const float depth = 1.0f - 1.0f / p.w;  // nearer is smaller, as GL_LESS wants
        a.positions.insert(a.positions.end(), {p.x * p.w, p.y * p.w, (2.0f * depth - 1.0f) * p.w, p.w});
        a.colors.insert(a.colors.end(), {static_cast<unsigned char>(p.r), static_cast<unsigned char>(p.g),
                                         static_cast<unsigned char>(p.b), static_cast<unsigned char>(p.a)});
        a.coords.insert(a.coords.end(), {p.s / 256.0f, p.t / 256.0f});
      }
    }
  }

  void frame(shim_workloads::Workload workload) {
    const Arrays &a = arrays_[static_cast<int>(workload)];
    const bool textured = workload != shim_workloads::Workload::Gouraud;
    gl_.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl_.glDrawBuffer(GL_COLOR_ATTACHMENT0);
    gl_.glUseProgram(0);
    disable_shim_arrays(gl_);
    gl_.glDisable(GL_SCISSOR_TEST);
    gl_.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl_.glDepthMask(GL_TRUE);
    gl_.glViewport(0, 0, shim_workloads::kWidth, shim_workloads::kHeight);
    gl_.glMatrixMode(GL_PROJECTION);
    gl_.glLoadIdentity();
    gl_.glOrtho(0, shim_workloads::kWidth, shim_workloads::kHeight, 0, 1, -1);  // z passes through
    gl_.glMatrixMode(GL_MODELVIEW);
    gl_.glLoadIdentity();
    gl_.glClearColor(0x30 / 255.0f, 0x20 / 255.0f, 0x10 / 255.0f, 1.0f);
    gl_.glClearDepth(1.0);
    gl_.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl_.glEnable(GL_DEPTH_TEST);
    gl_.glDepthFunc(GL_LESS);
    if (workload == shim_workloads::Workload::Blended) {
      gl_.glEnable(GL_BLEND);
      gl_.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    } else {
      gl_.glDisable(GL_BLEND);
    }
    if (textured) {
      gl_.glActiveTexture(GL_TEXTURE0);
      gl_.glEnable(GL_TEXTURE_2D);
      gl_.glBindTexture(GL_TEXTURE_2D, texture_);
      gl_.glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
      gl_.glEnableClientState(GL_TEXTURE_COORD_ARRAY);
      gl_.glTexCoordPointer(2, GL_FLOAT, 0, a.coords.data());
    }
    gl_.glEnableClientState(GL_VERTEX_ARRAY);
    gl_.glEnableClientState(GL_COLOR_ARRAY);
    gl_.glVertexPointer(4, GL_FLOAT, 0, a.positions.data());
    gl_.glColorPointer(4, GL_UNSIGNED_BYTE, 0, a.colors.data());
    gl_.glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(a.positions.size() / 4));
    gl_.glDisableClientState(GL_VERTEX_ARRAY);
    gl_.glDisableClientState(GL_COLOR_ARRAY);
    if (textured) {
      gl_.glDisableClientState(GL_TEXTURE_COORD_ARRAY);
      gl_.glDisable(GL_TEXTURE_2D);
    }
    gl_.glDisable(GL_BLEND);
    gl_.glFinish();
  }

 private:
  struct Arrays {
    std::vector<float> positions, coords;
    std::vector<unsigned char> colors;
  };
  const glide_shim::GlFunctions &gl_;
  Arrays arrays_[3];
  unsigned framebuffer_ = 0, renderbuffers_[2] = {0, 0}, texture_ = 0;
};

}  // namespace shim_bench

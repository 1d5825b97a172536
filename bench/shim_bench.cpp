// shim_bench: what the Glide layer costs. (1) 100,000 small Gouraud-textured triangles at
// 640x480 through grDrawTriangle, against the same triangles as hand-written GL vertex arrays
// in the same context; (2) the article's step 2: a 256x256 grLfbReadRegion plus ARGB_4444
// download, and the upload that the next draw triggers. Medians of repeats after warm-up.
#include <glide.h>
#include <glide_shim.h>

#include "context.h"
#include "gl/gl_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double median_ms(int warmups, int repeats, const std::function<void()> &run) {
  for (int i = 0; i < warmups; ++i) run();
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) {
    const auto start = Clock::now();
    run();
    times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

struct Triangle {
  GrVertex v[3];
};

std::vector<Triangle> small_triangles(int count) {
  std::mt19937 random(1);
  std::uniform_real_distribution<float> x(0.0f, 630.0f), y(0.0f, 470.0f), d(0.0f, 6.0f),
      c(0.0f, 255.0f), s(0.0f, 256.0f);
  std::vector<Triangle> triangles(static_cast<std::size_t>(count));
  for (Triangle &t : triangles) {
    const float x0 = x(random), y0 = y(random);
    for (int k = 0; k < 3; ++k) {
      GrVertex &v = t.v[k];
      std::memset(&v, 0, sizeof v);
      v.x = x0 + (k == 1 ? 6.0f : d(random));
      v.y = y0 + (k == 2 ? 6.0f : d(random));
      v.r = c(random), v.g = c(random), v.b = c(random), v.a = 255.0f;
      v.oow = 1.0f;
      v.tmuvtx[0].sow = s(random), v.tmuvtx[0].tow = s(random);
    }
  }
  return triangles;
}

// The plain-GL comparison: fixed-function Gouraud * bilinear texture, client vertex arrays,
// into its own 640x480 RGB565 framebuffer object in the shim's context.
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
    gl_.glDisable(GL_SCISSOR_TEST);
    gl_.glDisable(GL_DEPTH_TEST);
    gl_.glDisable(GL_BLEND);
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

}  // namespace

int main(int argc, char **argv) {
  int repeats = 9;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0) {
      std::printf("usage: shim_bench [--repeats N]\n"
                  "Prints the median time (after warm-up) of 100,000 small Gouraud-textured\n"
                  "triangles through the Glide shim and through plain GL vertex arrays, their\n"
                  "ratio, and the time of a 256x256 LFB read plus ARGB_4444 download.\n");
      return 0;
    }
    if (std::strcmp(argv[i], "--repeats") == 0 && i + 1 < argc) {
      repeats = std::max(1, std::atoi(argv[++i]));
    } else {
      std::fprintf(stderr, "shim_bench: unknown argument '%s' (see --help)\n", argv[i]);
      return 2;
    }
  }
  grGlideInit();
  if (!grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    std::fprintf(stderr, "shim_bench: %s\n", glideShimGetLastErrorMessage());
    return 1;
  }
  const std::vector<Triangle> triangles = small_triangles(100000);
  std::vector<FxU16> texels(256 * 256);
  std::mt19937 random(2);
  for (FxU16 &t : texels) t = static_cast<FxU16>(random());
  GrTexInfo info{GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);

  auto glide_frame = [&] {
    grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
    guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
    guColorCombineFunction(GR_COLORCOMBINE_TEXTURE_TIMES_ITRGB);
    grBufferClear(0, 0, 0);
    for (const Triangle &t : triangles) grDrawTriangle(&t.v[0], &t.v[1], &t.v[2]);
    grSstIdle();
  };
  PlainGl plain(glide_shim::current().renderer->gl(), triangles, texels);

  std::printf("shim_bench: %s backend, 640x480, median of %d after 2 warm-ups\n",
              glideShimBackendName(), repeats);
  // Interleave the two paths so machine noise hits both alike.
  std::vector<double> glide_times, gl_times;
  for (int round = 0; round < 3; ++round) {
    glide_times.push_back(median_ms(round == 0 ? 2 : 0, repeats, glide_frame));
    gl_times.push_back(median_ms(round == 0 ? 2 : 0, repeats, [&] { plain.draw(); }));
  }
  std::sort(glide_times.begin(), glide_times.end());
  std::sort(gl_times.begin(), gl_times.end());
  const double glide_ms = glide_times[1], gl_ms = gl_times[1];
  std::printf("  100k triangles, grDrawTriangle      %8.2f ms\n", glide_ms);
  std::printf("  100k triangles, plain GL arrays     %8.2f ms\n", gl_ms);
  std::printf("  ratio shim / plain GL               %8.2f   (target <= 1.25)\n", glide_ms / gl_ms);

  // Step 2 of the article: read the 565 region, download the same words as ARGB_4444, and
  // the upload the next draw triggers (one small textured triangle).
  std::vector<FxU16> shadow(256 * 256);
  GrTexInfo shadow_info{GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_ARGB_4444, shadow.data()};
  const double read_ms = median_ms(5, 41, [&] {
    grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 256, 256, 512, shadow.data());
  });
  const double download_ms = median_ms(5, 41, [&] {
    grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 256, 256, 512, shadow.data());
    grTexDownloadMipMap(GR_TMU0, 0x100000, GR_MIPMAPLEVELMASK_BOTH, &shadow_info);
  });
  const double with_upload_ms = median_ms(5, 41, [&] {
    grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 256, 256, 512, shadow.data());
    grTexDownloadMipMap(GR_TMU0, 0x100000, GR_MIPMAPLEVELMASK_BOTH, &shadow_info);
    grTexSource(GR_TMU0, 0x100000, GR_MIPMAPLEVELMASK_BOTH, &shadow_info);
    grDrawTriangle(&triangles[0].v[0], &triangles[0].v[1], &triangles[0].v[2]);
    grSstIdle();
  });
  std::printf("  256x256 grLfbReadRegion             %8.1f us\n", read_ms * 1000.0);
  std::printf("  ... + ARGB_4444 grTexDownloadMipMap %8.1f us\n", download_ms * 1000.0);
  std::printf("  ... + GL upload and one draw        %8.1f us\n", with_upload_ms * 1000.0);
  grGlideShutdown();
  return 0;
}

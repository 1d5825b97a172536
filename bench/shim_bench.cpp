// shim_bench: what the Glide layer costs against the same work in plain GL, in the same run and
// context, as a ratio of medians after warm-up with the two paths interleaved:
// (1) the SDK-style frames of issue 13 (bench/shim_workloads.h): a 640x480 clear, two Gouraud
//     W-buffer triangles and a swap; the same with a bilinear 256x256 565 texture; 50 small
//     textured alpha-blended triangles;
// (2) 100,000 small Gouraud-textured triangles through grDrawTriangle against the same
//     triangles as hand-written GL vertex arrays;
// (3) the article's step 2: a 256x256 grLfbReadRegion plus ARGB_4444 download, and the upload
//     that the next draw triggers.
// `--only ROW --path shim|gl --frames N` draws N frames of one row's one path untimed, for
// callgrind (LP_NUM_THREADS=0).
#include <glide.h>
#include <glide_shim.h>

#include "context.h"
#include "gl/gl_renderer.h"
#include "plain_gl_reference.h"
#include "shim_workloads.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace {

using shim_bench::PlainGl;
using shim_bench::PlainSdk;
using shim_bench::disable_shim_arrays;
using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double median_ms(int warmups, int repeats, const std::function<void()> &run) {
  for (int i = 0; i < warmups; ++i) run();
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) {
    const auto start = Clock::now();
    run();
    times.push_back(elapsed_ms(start));
  }
  return median(times);
}

using shim_workloads::Triangle;

// Times `shim` and `gl` frame by frame, in alternating blocks of `block` frames after `warmups`
// of each; returns the medians (ms) of the shim's and plain GL's frames.
std::pair<double, double> interleaved(int warmups, int rounds, int block,
                                      const std::function<void()> &shim,
                                      const std::function<void()> &gl) {
  for (int i = 0; i < warmups; ++i) shim(), gl();
  std::vector<double> shim_ms, gl_ms;
  for (int round = 0; round < rounds; ++round) {
    for (int i = 0; i < block; ++i) {
      const auto start = Clock::now();
      shim();
      shim_ms.push_back(elapsed_ms(start));
    }
    for (int i = 0; i < block; ++i) {
      const auto start = Clock::now();
      gl();
      gl_ms.push_back(elapsed_ms(start));
    }
  }
  return {median(shim_ms), median(gl_ms)};
}

// --fidelity: each workload with each fidelity knob (GLIDESHIM_PLAIN_GL) against the exact frame,
// in a window of its own per knob. The error is in 565 LSBs per channel (the red and blue
// channels' 5-bit steps, green's 6-bit ones) against the frame with no knob, which is the
// CPU Voodoo model's (tests/numeric check the exact path against it operation by operation).
struct KnobFrame {
  std::vector<FxU16> words;
  double median_ms = 0;
};

KnobFrame render_with_knobs(const std::string &row, const char *knobs, int frames) {
  if (knobs != nullptr) setenv("GLIDESHIM_PLAIN_GL", knobs, 1); else unsetenv("GLIDESHIM_PLAIN_GL");
  KnobFrame result;
  grGlideInit();
  if (!grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    std::fprintf(stderr, "shim_bench: %s\n", glideShimGetLastErrorMessage());
    std::exit(1);
  }
  std::vector<FxU16> sdk_texels = shim_workloads::texture_565();
  std::vector<FxU16> stream_texels = shim_workloads::stream_texture();
  static const std::vector<Triangle> triangles = shim_workloads::stream_triangles(100000);
  GrTexInfo info{GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, stream_texels.data()};
  std::function<void()> frame;
  GrBuffer_t buffer = GR_BUFFER_FRONTBUFFER;
  if (row == "stream") {
    grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    frame = [&] { shim_workloads::stream_frame(triangles, info, 0); };
    buffer = GR_BUFFER_BACKBUFFER;
  } else {
    const shim_workloads::Workload w = row == "gouraud"    ? shim_workloads::Workload::Gouraud
                                       : row == "textured" ? shim_workloads::Workload::Textured
                                                           : shim_workloads::Workload::Blended;
    shim_workloads::set_up(w, sdk_texels);
    frame = [w] {
      shim_workloads::glide_frame(w);
      grSstIdle();
    };
  }
  result.median_ms = median_ms(3, frames, frame);
  result.words.resize(static_cast<std::size_t>(shim_workloads::kWidth) * shim_workloads::kHeight);
  grLfbReadRegion(buffer, 0, 0, shim_workloads::kWidth, shim_workloads::kHeight,
                  shim_workloads::kWidth * 2, result.words.data());
  grGlideShutdown();
  unsetenv("GLIDESHIM_PLAIN_GL");
  return result;
}

struct Error565 {
  int max_lsb = 0;
  double mean_lsb = 0, changed = 0;  // mean over every channel of every pixel; share of pixels
};

Error565 error_565(const std::vector<FxU16> &a, const std::vector<FxU16> &b) {
  Error565 e;
  double sum = 0;
  std::size_t changed = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const int d[3] = {std::abs((a[i] >> 11) - (b[i] >> 11)),
                      std::abs(((a[i] >> 5) & 0x3F) - ((b[i] >> 5) & 0x3F)),
                      std::abs((a[i] & 0x1F) - (b[i] & 0x1F))};
    for (int c : d) e.max_lsb = std::max(e.max_lsb, c), sum += c;
    changed += a[i] != b[i];
  }
  e.mean_lsb = sum / (3.0 * static_cast<double>(a.size()));
  e.changed = static_cast<double>(changed) / static_cast<double>(a.size());
  return e;
}

int run_fidelity(int frames) {
  std::printf("shim_bench --fidelity: each modelled behaviour switched to plain GL (GLIDESHIM_PLAIN_GL),\n"
              "error in 565 LSBs against the exact frame, median of %d frames after 3 warm-ups\n",
              frames);
  const char *knobs[] = {"write", "iterators", "combine", "bilinear", "all"};
  for (const char *row : {"gouraud", "textured", "blended", "stream"}) {
    const KnobFrame exact = render_with_knobs(row, nullptr, frames);
    std::printf("  %-9s exact                 %8.3f ms\n", row, exact.median_ms);
    for (const char *knob : knobs) {
      const KnobFrame plain = render_with_knobs(row, knob, frames);
      const Error565 e = error_565(plain.words, exact.words);
      std::printf("  %-9s %-10s %8.3f ms  max %d LSB  mean %.4f LSB  pixels changed %6.2f%%\n",
                  row, knob, plain.median_ms, e.max_lsb, e.mean_lsb, 100.0 * e.changed);
      std::fflush(stdout);
    }
  }
  return 0;
}

int usage_error(const char *message, const char *argument) {
  std::fprintf(stderr, "shim_bench: %s '%s' (see --help)\n", message, argument);
  return 2;
}

}  // namespace

int main(int argc, char **argv) {
  int repeats = 9, sdk_rounds = 20;
  std::string only, path = "shim", timed_row;
  int profile_frames = 10;
  bool fidelity = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0) {
      std::printf(
          "usage: shim_bench [--repeats N] [--sdk-rounds N] [--row gouraud|textured|blended]\n"
          "       shim_bench --only gouraud|textured|blended|stream [--path shim|gl] [--frames N]\n"
          "       shim_bench --fidelity [--frames N]\n"
          "Prints, each against the same work in plain GL in the same run (ratio of medians after\n"
          "warm-up, the two interleaved): the SDK-style frames (640x480 clear + two Gouraud\n"
          "W-buffer triangles + swap; the same with a bilinear 256x256 565 texture; 50 small\n"
          "textured alpha-blended triangles), 100,000 small Gouraud-textured triangles, and the\n"
          "time of a 256x256 LFB read plus ARGB_4444 download (--row: one SDK row alone, timed\n"
          "as above). --only draws N frames of one row's\n"
          "one path, untimed (for callgrind with LP_NUM_THREADS=0). --fidelity renders each row with\n"
          "each fidelity knob of GLIDESHIM_PLAIN_GL and prints its error against the exact frame.\n"
          "GLIDESHIM_EXACT=1 forces the shim's fast paths off.\n");
      return 0;
    }
    const bool has_value = i + 1 < argc;
    if (std::strcmp(argv[i], "--repeats") == 0 && has_value) {
      repeats = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--sdk-rounds") == 0 && has_value) {
      sdk_rounds = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--only") == 0 && has_value) {
      only = argv[++i];
      if (only != "gouraud" && only != "textured" && only != "blended" && only != "stream") {
        return usage_error("unknown row", only.c_str());
      }
    } else if (std::strcmp(argv[i], "--path") == 0 && has_value) {
      path = argv[++i];
      if (path != "shim" && path != "gl") return usage_error("unknown path", path.c_str());
    } else if (std::strcmp(argv[i], "--row") == 0 && has_value) {
      timed_row = argv[++i];
      if (timed_row != "gouraud" && timed_row != "textured" && timed_row != "blended") {
        return usage_error("unknown SDK row", timed_row.c_str());
      }
    } else if (std::strcmp(argv[i], "--fidelity") == 0) {
      fidelity = true;
    } else if (std::strcmp(argv[i], "--frames") == 0 && has_value) {
      profile_frames = std::max(1, std::atoi(argv[++i]));
    } else {
      return usage_error("unknown argument", argv[i]);
    }
  }
  if (fidelity) return run_fidelity(profile_frames);
  grGlideInit();
  if (!grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    std::fprintf(stderr, "shim_bench: %s\n", glideShimGetLastErrorMessage());
    return 1;
  }
  const glide_shim::GlFunctions &gl = glide_shim::current().renderer->gl();
  std::vector<FxU16> sdk_texels = shim_workloads::texture_565();
  PlainSdk plain_sdk(gl, sdk_texels);
  const shim_workloads::Workload workloads[3] = {shim_workloads::Workload::Gouraud,
                                             shim_workloads::Workload::Textured,
                                             shim_workloads::Workload::Blended};

  if (!only.empty() && only != "stream") {  // one path of one SDK row, for a profiler
    const shim_workloads::Workload w = only == "gouraud"    ? shim_workloads::Workload::Gouraud
                                   : only == "textured" ? shim_workloads::Workload::Textured
                                                        : shim_workloads::Workload::Blended;
    shim_workloads::set_up(w, sdk_texels);
    for (int i = 0; i < profile_frames; ++i) {
      if (path == "shim") {
        shim_workloads::glide_frame(w);
        grSstIdle();
      } else {
        plain_sdk.frame(w);
      }
    }
    grGlideShutdown();
    return 0;
  }

  const std::vector<Triangle> triangles = shim_workloads::stream_triangles(100000);
  std::vector<FxU16> texels = shim_workloads::stream_texture();
  GrTexInfo info{GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  // Above the SDK frames' texture in TMU memory.
  const FxU32 stream_address = 0x40000;

  auto glide_stream = [&] { shim_workloads::stream_frame(triangles, info, stream_address); };
  auto stream_state = [&] {  // the window's defaults, which the stream ran on before the SDK rows
    grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
    grDepthMask(FXFALSE);
    grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
    guAlphaSource(GR_ALPHASOURCE_CC_ALPHA);
    grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
    grTexDownloadMipMap(GR_TMU0, stream_address, GR_MIPMAPLEVELMASK_BOTH, &info);
  };
  PlainGl plain(gl, triangles, texels);

  if (only == "stream") {
    stream_state();
    for (int i = 0; i < profile_frames; ++i) {
      if (path == "shim") glide_stream(); else plain.draw();
    }
    grGlideShutdown();
    return 0;
  }

  const char *exact = std::getenv("GLIDESHIM_EXACT");
  std::printf("shim_bench: %s backend, 640x480%s\n", glideShimBackendName(),
              exact != nullptr && std::strcmp(exact, "1") == 0 ? ", fast paths off (GLIDESHIM_EXACT=1)" : "");

  // (1) The SDK-style frames. Each frame is timed alone (a Glide frame ends in grSstIdle, the
  // GL one in glFinish); blocks of 10 shim frames alternate with 10 plain-GL frames.
  std::printf("  SDK-style frames (median of %d frames each, after 10 warm-ups):\n", sdk_rounds * 10);
  const double targets[3] = {1.15, 1.3, 1.3};
  const char *labels[3] = {"clear + 2 Gouraud triangles + swap", "... with bilinear 565 texture",
                           "clear + 50 textured blended tris"};
  for (int k = 0; k < 3; ++k) {
    const shim_workloads::Workload w = workloads[k];
    if (!timed_row.empty() && timed_row != shim_workloads::name(w)) continue;
    shim_workloads::set_up(w, sdk_texels);
    const auto [shim_ms, gl_ms] = interleaved(
        10, sdk_rounds, 10,
        [&] {
          shim_workloads::glide_frame(w);
          grSstIdle();
        },
        [&] { plain_sdk.frame(w); });
    std::printf("    %-36s shim %6.3f ms  plain GL %6.3f ms  ratio %5.2f  (target <= %.2f)\n",
                labels[k], shim_ms, gl_ms, shim_ms / gl_ms, targets[k]);
    std::fflush(stdout);
  }
  if (!timed_row.empty()) {  // --row: that SDK row alone
    grGlideShutdown();
    return 0;
  }
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  guAlphaSource(GR_ALPHASOURCE_CC_ALPHA);

  // (2) The 100k-triangle stream. Interleave the two paths so machine noise hits both alike.
  stream_state();
  std::printf("  100k-triangle stream (median of %d after 2 warm-ups, middle of 3 rounds):\n",
              repeats);
  std::vector<double> glide_times, gl_times;
  for (int round = 0; round < 3; ++round) {
    glide_times.push_back(median_ms(round == 0 ? 2 : 0, repeats, glide_stream));
    gl_times.push_back(median_ms(round == 0 ? 2 : 0, repeats, [&] { plain.draw(); }));
  }
  std::sort(glide_times.begin(), glide_times.end());
  std::sort(gl_times.begin(), gl_times.end());
  const double glide_ms = glide_times[1], gl_ms = gl_times[1];
  std::printf("    100k triangles, grDrawTriangle      %8.2f ms\n", glide_ms);
  std::printf("    100k triangles, plain GL arrays     %8.2f ms\n", gl_ms);
  std::printf("    ratio shim / plain GL               %8.2f   (target <= 1.15)\n", glide_ms / gl_ms);

  // (3) Step 2 of the article: read the 565 region, download the same words as ARGB_4444, and
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
  std::printf("  256x256 grLfbReadRegion               %8.1f us\n", read_ms * 1000.0);
  std::printf("  ... + ARGB_4444 grTexDownloadMipMap   %8.1f us\n", download_ms * 1000.0);
  std::printf("  ... + GL upload and one draw          %8.1f us\n", with_upload_ms * 1000.0);
  grGlideShutdown();
  return 0;
}

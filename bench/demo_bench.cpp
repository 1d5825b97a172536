// demo_bench: what the projected shadows cost in the fighter demo at 640x480 with 256x256
// textures. Same run, same frames: the frame without shadows, with them through the LFB path and
// through the direct (render-to-texture) path; where the main thread's frame goes (on a core, in
// the run queue, asleep waiting for the rasterisers) and step 2's read-back wait; the five step
// times; frames per second without PNG writing; peak memory. Medians of repeats after a warm-up
// (llvmpipe compiles each new state on its first draw). `--only none|lfb|direct --frames N`
// draws N frames of one mode untimed, for callgrind (LP_NUM_THREADS=0). GLIDESHIM_EXACT=1 forces
// the shim's fast paths off.
#include "scene/fight_scene.h"
#include "techniques/projected/projected_shadow.h"

#include <glide.h>
#include <glide_shim.h>

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

// Where the main thread's wall time goes (milliseconds, from /proc/thread-self/schedstat): on a
// core (the program's own work, the shim's and Mesa's set-up; llvmpipe rasterises on threads of
// its own) and waiting in the run queue for a core (a busy machine). The rest of the wall time it
// was asleep: waiting for the rasterisers (a read-back, grSstIdle). `process` is the CPU time of
// every thread of the process.
struct ThreadTimes {
  double on_cpu = 0.0, run_queue = 0.0, process = 0.0;
  static ThreadTimes now() {
    ThreadTimes t;
    if (std::FILE *file = std::fopen("/proc/thread-self/schedstat", "r")) {
      unsigned long long cpu_ns = 0, queue_ns = 0;
      if (std::fscanf(file, "%llu %llu", &cpu_ns, &queue_ns) == 2) {
        t.on_cpu = static_cast<double>(cpu_ns) * 1e-6, t.run_queue = static_cast<double>(queue_ns) * 1e-6;
      }
      std::fclose(file);
    }
    timespec process{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &process);
    t.process = static_cast<double>(process.tv_sec) * 1e3 + static_cast<double>(process.tv_nsec) * 1e-6;
    return t;
  }
  ThreadTimes operator-(const ThreadTimes &o) const {
    return {on_cpu - o.on_cpu, run_queue - o.run_queue, process - o.process};
  }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// --fidelity: frame 10 of the fight with projected shadows (LFB path), rendered in a window of
// its own with the fidelity knobs `knobs` (GLIDESHIM_PLAIN_GL; null: none), as 565 words.
std::vector<FxU16> fight_frame(const char *knobs) {
  if (knobs != nullptr) setenv("GLIDESHIM_PLAIN_GL", knobs, 1); else unsetenv("GLIDESHIM_PLAIN_GL");
  grGlideInit();
  std::vector<FxU16> words(640 * 480);
  if (grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                   GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    gs::FightScene fight(640, 480, 256);
    gs::render_projected_shadows(fight.at(10.0f / 30.0f), gs::ProjectedShadowOptions{}, false);
    grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 640, 480, 640 * 2, words.data());
  }
  grGlideShutdown();
  unsetenv("GLIDESHIM_PLAIN_GL");
  return words;
}

int run_fidelity() {
  std::printf("demo_bench --fidelity: frame 10 with projected shadows, each modelled behaviour\n"
              "switched to plain GL (GLIDESHIM_PLAIN_GL), error in 565 LSBs against the exact frame\n");
  const std::vector<FxU16> exact = fight_frame(nullptr);
  for (const char *knob : {"write", "iterators", "combine", "bilinear", "all"}) {
    const std::vector<FxU16> plain = fight_frame(knob);
    int max_lsb = 0;
    double sum = 0;
    std::size_t changed = 0;
    for (std::size_t i = 0; i < exact.size(); ++i) {
      const int d[3] = {std::abs((plain[i] >> 11) - (exact[i] >> 11)),
                        std::abs(((plain[i] >> 5) & 0x3F) - ((exact[i] >> 5) & 0x3F)),
                        std::abs((plain[i] & 0x1F) - (exact[i] & 0x1F))};
      for (int c : d) max_lsb = std::max(max_lsb, c), sum += c;
      changed += plain[i] != exact[i];
    }
    std::printf("  %-10s max %d LSB  mean %.4f LSB  pixels changed %6.2f%%\n", knob, max_lsb,
                sum / (3.0 * static_cast<double>(exact.size())),
                100.0 * static_cast<double>(changed) / static_cast<double>(exact.size()));
  }
  return 0;
}

}  // namespace

int main(int argc, char **argv) {
  int frames = 40;
  int only = -1;  // --only: one mode, untimed
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0) {
      std::printf("usage: demo_bench [--frames N] [--only none|lfb|direct] [--fidelity]\nTimes N frames of the "
                  "fighter demo at 640x480, 256x256 shadows: without shadows, LFB path, direct\n"
                  "path (median ms per frame), where the main thread's frame goes, the five steps,\n"
                  "frames per second and peak memory.\n"
                  "--only draws N frames of one mode untimed (for callgrind, LP_NUM_THREADS=0).\n"
                  "--fidelity prints each GLIDESHIM_PLAIN_GL knob's error on one shadowed frame.\n"
                  "GLIDESHIM_EXACT=1 forces the shim's fast paths off.\n");
      return 0;
    }
    if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
      frames = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--fidelity") == 0) {
      return run_fidelity();
    } else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
      const std::string mode = argv[++i];
      only = mode == "none" ? 0 : mode == "lfb" ? 1 : mode == "direct" ? 2 : -2;
      if (only == -2) {
        std::fprintf(stderr, "demo_bench: unknown mode '%s' (see --help)\n", mode.c_str());
        return 2;
      }
    } else {
      std::fprintf(stderr, "demo_bench: unknown argument '%s' (see --help)\n", argv[i]);
      return 2;
    }
  }
  if (only < 0) frames = std::max(4, frames);  // a median of at least four
  grGlideInit();
  if (!grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    std::fprintf(stderr, "demo_bench: %s\n", glideShimGetLastErrorMessage());
    return 1;
  }
  gs::FightScene fight(640, 480, 256);
  gs::ProjectedShadowOptions lfb, direct;
  direct.direct_path = true;
  // As the demo draws them: a shadow refused as too coarse is drawn at the size it names.
  lfb.grow_to_accepted = direct.grow_to_accepted = true;

  enum Mode { kNone, kLfb, kDirect };
  if (only >= 0) {  // one mode, untimed, for a profiler
    for (int i = 0; i < frames; ++i) {
      const gs::Scene &scene = fight.at(static_cast<float>(i) / 30.0f);
      if (only == kNone) gs::render_scene(scene, gs::project_scene(scene));
      else gs::render_projected_shadows(scene, only == kLfb ? lfb : direct, false);
      grSstIdle();
      grBufferSwap(0);
    }
    grGlideShutdown();
    return 0;
  }
  const char *names[3] = {"no shadows", "shadows, LFB path", "shadows, direct path"};
  std::vector<double> frame_ms[3];
  std::vector<ThreadTimes> thread_ms[3];  // per frame (ThreadTimes)
  // Per frame of the two shadowed modes: step 2's time in the unsynchronised frame, the
  // read-backs' wait for step 1's drawing and their copies (nothing on the direct path, whose
  // step 1 reads its words back itself).
  std::vector<double> read_back_ms[3];
  std::vector<gs::StepTimes> steps;
  // Warm-up: every mode once, so llvmpipe's shader compiles are out of the measurement.
  for (int mode = 0; mode < 3; ++mode) {
    const gs::Scene &scene = fight.at(0.0f);
    if (mode == kNone) gs::render_scene(scene, gs::project_scene(scene));
    else gs::render_projected_shadows(scene, mode == kLfb ? lfb : direct, false);
    grBufferSwap(0);
  }
  // Modes interleaved frame by frame, so machine noise falls on all three alike.
  for (int i = 0; i < frames; ++i) {
    const gs::Scene &scene = fight.at(static_cast<float>(i) / 30.0f);
    for (int mode = 0; mode < 3; ++mode) {
      const auto start = Clock::now();
      const ThreadTimes times_start = ThreadTimes::now();
      if (mode == kNone) gs::render_scene(scene, gs::project_scene(scene));
      else read_back_ms[mode].push_back(
               gs::render_projected_shadows(scene, mode == kLfb ? lfb : direct, false).times.ms[1]);
      grSstIdle();
      frame_ms[mode].push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      thread_ms[mode].push_back(ThreadTimes::now() - times_start);
      grBufferSwap(0);
    }
  }
  // Step times need a synchronising idle after each step, which slows the frame a little.
  for (int i = 0; i < frames; ++i) {
    steps.push_back(gs::render_projected_shadows(fight.at(static_cast<float>(i) / 30.0f), lfb, true).times);
    grBufferSwap(0);
  }
  const std::string backend = glideShimBackendName();
  grGlideShutdown();

  std::printf("demo_bench: fighter demo, 640x480, 256x256 shadow textures, %d frames, %s backend\n",
              frames, backend.c_str());
  const double none = median(frame_ms[kNone]);
  for (int mode = 0; mode < 3; ++mode) {
    const double ms = median(frame_ms[mode]);
    std::printf("  %-22s %7.2f ms  %6.1f frames/s  ratio to no shadows %.2f\n", names[mode], ms,
                1000.0 / ms, ms / none);
  }
  std::printf("  main thread, median ms a frame: on a core, in the run queue, asleep (waiting for\n"
              "  the rasterisers); CPU of all threads\n");
  for (int mode = 0; mode < 3; ++mode) {
    std::vector<double> cpu, queue, asleep, process;
    for (std::size_t i = 0; i < thread_ms[mode].size(); ++i) {
      const ThreadTimes &t = thread_ms[mode][i];
      cpu.push_back(t.on_cpu), queue.push_back(t.run_queue), process.push_back(t.process);
      asleep.push_back(frame_ms[mode][i] - t.on_cpu - t.run_queue);
    }
    std::printf("  %-22s %7.2f %7.2f %7.2f   all threads %7.2f", names[mode], median(cpu),
                median(queue), median(asleep), median(process));
    if (mode == kLfb) std::printf("   step 2 (read-backs) %5.2f", median(read_back_ms[mode]));
    std::printf("\n");
  }
  std::printf("  LFB path / direct path %7.2f       (target within 1.10)\n",
              median(frame_ms[kLfb]) / median(frame_ms[kDirect]));
  std::printf("  shadows / no shadows   %7.2f       (target at most 1.30)\n",
              median(frame_ms[kLfb]) / none);
  const char *step_names[5] = {"1 caster from the light", "2 LFB read + 4444 download",
                               "3 (s,t) for the receivers", "4 the scene", "5 shadow pass"};
  std::vector<double> totals;
  for (const gs::StepTimes &t : steps) totals.push_back(t.total_ms);
  const double total = median(totals);
  std::printf("  steps (synchronised frame %.2f ms):\n", total);
  for (int s = 0; s < 5; ++s) {
    std::vector<double> v;
    for (const gs::StepTimes &t : steps) v.push_back(t.ms[s]);
    std::printf("    step %-28s %6.2f ms  %5.1f%%\n", step_names[s], median(v), 100.0 * median(v) / total);
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("  peak memory            %7.1f MB   (target under 150)\n",
              static_cast<double>(usage.ru_maxrss) / 1024.0);
  return 0;
}

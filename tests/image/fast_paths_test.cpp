// The shim's fast paths are exact: every benchmark workload rendered with them allowed
// and with them forced off (GLIDESHIM_EXACT=1, read at grSstWinOpen) gives the same bytes. The
// workloads: the SDK-style frames and shim_bench's 100,000-triangle stream (bench/
// shim_workloads.h), frames of the fighter demo without shadows and with projected shadows on
// both paths, every figure of the articles, and the one-feature programs of tests/sdk (fog,
// LFB formats and pipeline, antialiasing, mip-mapping, palettes, .3df, the gu texture manager),
// whose dumped frames are compared as files, and dithered lines, points and slivers in both
// origins (the fast dither's row source). A fast path that changed one byte would not be a
// fast path but a fidelity knob, off by default (docs/environment.md).
#include "context.h"
#include "gl/gl_renderer.h"
#include "figures/figures.h"
#include "gl/shader_source.h"
#include "image_compare.h"
#include "scene/fight_scene.h"
#include "shim_workloads.h"
#include "techniques/projected/projected_shadow.h"
#include "techniques/light_passes/scene_pass.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Sets GLIDESHIM_EXACT for the windows opened while it lives, and restores it after.
class ExactSwitch {
 public:
  explicit ExactSwitch(bool exact) {
    const char *old = std::getenv("GLIDESHIM_EXACT");
    had_ = old != nullptr;
    if (had_) old_ = old;
    setenv("GLIDESHIM_EXACT", exact ? "1" : "0", 1);
  }
  ~ExactSwitch() {
    if (had_) setenv("GLIDESHIM_EXACT", old_.c_str(), 1); else unsetenv("GLIDESHIM_EXACT");
  }
  ExactSwitch(const ExactSwitch &) = delete;
  ExactSwitch &operator=(const ExactSwitch &) = delete;

 private:
  bool had_ = false;
  std::string old_;
};

// The colour buffer and the depth buffer as the LFB reads them (565 and 16-bit depth codes).
struct Buffers {
  std::vector<FxU16> color, depth;
};

Buffers read_buffers(GrBuffer_t color_buffer) {
  const int w = static_cast<int>(grSstScreenWidth()), h = static_cast<int>(grSstScreenHeight());
  Buffers b;
  b.color.resize(static_cast<std::size_t>(w) * h);
  b.depth.resize(b.color.size());
  EXPECT_TRUE(grLfbReadRegion(color_buffer, 0, 0, static_cast<FxU32>(w), static_cast<FxU32>(h),
                              static_cast<FxU32>(w * 2), b.color.data()));
  EXPECT_TRUE(grLfbReadRegion(GR_BUFFER_AUXBUFFER, 0, 0, static_cast<FxU32>(w),
                              static_cast<FxU32>(h), static_cast<FxU32>(w * 2), b.depth.data()));
  return b;
}

// Opens a 640x480 window with the fast paths allowed or not, runs `draw`, and returns what it
// left in `color_buffer` and the depth buffer.
Buffers render(bool exact, GrBuffer_t color_buffer, const std::function<void()> &draw) {
  ExactSwitch exact_switch(exact);
  grGlideInit();
  Buffers b;
  if (!grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    ADD_FAILURE() << glideShimGetLastErrorMessage();
    return b;
  }
  EXPECT_EQ(glide_shim::current().fast_paths, !exact) << "GLIDESHIM_EXACT is read at grSstWinOpen";
  glideShimClearError();
  draw();
  grSstIdle();
  b = read_buffers(color_buffer);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
  grGlideShutdown();
  return b;
}

// Counts the differing words, so a failure says how far apart the two are.
void expect_same(const Buffers &fast, const Buffers &exact, const std::string &what) {
  ASSERT_EQ(fast.color.size(), exact.color.size()) << what;
  ASSERT_FALSE(exact.color.empty()) << what;
  std::size_t color = 0, depth = 0;
  for (std::size_t i = 0; i < exact.color.size(); ++i) {
    color += fast.color[i] != exact.color[i];
    depth += fast.depth[i] != exact.depth[i];
  }
  EXPECT_EQ(color, 0u) << what << ": colour words that differ";
  EXPECT_EQ(depth, 0u) << what << ": depth words that differ";
}

// ...and that the frame is not empty, so identical bytes mean something.
void expect_drawn(const Buffers &b, const std::string &what) {
  std::size_t differing = 0;
  for (FxU16 word : b.color) differing += word != b.color.front();
  EXPECT_GT(differing, b.color.size() / 100) << what << ": the frame is nearly uniform";
}

std::string workload_name(const ::testing::TestParamInfo<shim_workloads::Workload> &param) {
  return shim_workloads::name(param.param);
}

std::string mode_name(const ::testing::TestParamInfo<int> &param) {
  return param.param == 0 ? "NoShadows" : param.param == 1 ? "LfbPath" : "DirectPath";
}

std::string figure_name(const ::testing::TestParamInfo<const gs::FigureEntry *> &param) {
  std::string name = param.param->name;
  for (char &c : name) {
    if (c == '-') c = '_';
  }
  return name;
}

class SdkFrames : public ::testing::TestWithParam<shim_workloads::Workload> {};

TEST_P(SdkFrames, FastPathsGiveTheExactBytes) {
  const shim_workloads::Workload workload = GetParam();
  std::vector<FxU16> texels = shim_workloads::texture_565();
  auto draw = [&] {
    shim_workloads::set_up(workload, texels);
    for (int frame = 0; frame < 2; ++frame) shim_workloads::glide_frame(workload);
  };
  const Buffers fast = render(false, GR_BUFFER_FRONTBUFFER, draw);
  const Buffers exact = render(true, GR_BUFFER_FRONTBUFFER, draw);
  expect_drawn(exact, shim_workloads::name(workload));
  expect_same(fast, exact, shim_workloads::name(workload));
}

INSTANTIATE_TEST_SUITE_P(Workloads, SdkFrames,
                         ::testing::Values(shim_workloads::Workload::Gouraud,
                                           shim_workloads::Workload::Textured,
                                           shim_workloads::Workload::Blended),
                         workload_name);

TEST(ShimBenchStream, FastPathsGiveTheExactBytes) {
  const std::vector<shim_workloads::Triangle> triangles = shim_workloads::stream_triangles(100000);
  std::vector<FxU16> texels = shim_workloads::stream_texture();
  auto draw = [&] {
    GrTexInfo info{GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
    grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    // Twice: the fast paths compile a state's sources in when it is drawn a second time.
    shim_workloads::stream_frame(triangles, info, 0);
    shim_workloads::stream_frame(triangles, info, 0);
  };
  const Buffers fast = render(false, GR_BUFFER_BACKBUFFER, draw);
  const Buffers exact = render(true, GR_BUFFER_BACKBUFFER, draw);
  expect_drawn(exact, "stream");
  expect_same(fast, exact, "stream");
}

// The fast dither takes a pixel's row from an interpolated varying, except for lines, whose
// varyings change only along the line. Dithered mid-range colours, in both origins: lines with
// integer and half-integer ends at several slopes, points, and slivers a fraction of a pixel
// wide, each drawn twice so the second draw runs the state's compiled-in program.
TEST(DitheredPrimitives, FastPathsGiveTheExactBytes) {
  auto vertex = [](float x, float y, float shade) {
    GrVertex v{};
    v.x = x, v.y = y, v.oow = 1.0f;
    v.r = 37.0f + shade, v.g = 90.0f + shade * 0.5f, v.b = 150.0f - shade;
    return v;
  };
  auto draw = [&] {
    grDitherMode(GR_DITHER_4x4);
    guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
    for (int pass = 0; pass < 4; ++pass) {
      grSstOrigin(pass < 2 ? GR_ORIGIN_UPPER_LEFT : GR_ORIGIN_LOWER_LEFT);
      const float top = pass < 2 ? 10.0f : 250.0f;
      for (int i = 0; i < 24; ++i) {
        const float k = static_cast<float>(i);
        const float y = top + k * 4.0f + (i % 2 == 0 ? 0.0f : 0.5f);
        const GrVertex a = vertex(10.0f, y, 2.0f * k);
        const GrVertex b = vertex(300.0f, y + static_cast<float>(i % 3) * 9.0f, 90.0f);
        grDrawLine(&a, &b);
        const GrVertex c = vertex(320.0f + 8.0f * k, top, 3.0f * k);
        const GrVertex d = vertex(330.0f + 8.0f * k, top + 90.0f, 60.0f);
        grDrawLine(&c, &d);
        const GrVertex p = vertex(500.0f + 0.25f * k, y + 0.3f, 5.0f * k);
        grDrawPoint(&p);
        const GrVertex s0 = vertex(520.0f, y, 0.0f), s2 = vertex(520.0f, y + 0.125f, 50.0f);
        const GrVertex s1 = vertex(630.0f, y + 0.0625f * (k + 1.0f), 100.0f);
        grDrawTriangle(&s0, &s1, &s2);
      }
    }
  };
  const Buffers fast = render(false, GR_BUFFER_BACKBUFFER, draw);
  const Buffers exact = render(true, GR_BUFFER_BACKBUFFER, draw);
  std::size_t drawn = 0;
  for (FxU16 word : exact.color) drawn += word != 0;
  EXPECT_GT(drawn, 5000u) << "too little drawn for the comparison to mean something";
  expect_same(fast, exact, "dithered lines, points and slivers");
}

// grBufferClear inside a clip window smaller than the screen (the fast paths copy it from a side
// buffer, clipped_clear.cpp; GL clears it through the scissor), in both origins: colour and depth,
// colour alone, depth alone in a window wider than any before (the side buffer grows), an empty
// window, and values that change between clears.
TEST(ClippedClears, FastPathsGiveTheExactBytes) {
  for (GrOriginLocation_t origin : {GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT}) {
    auto draw = [origin] {
      grSstOrigin(origin);
      grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
      grDepthMask(FXTRUE);
      grBufferClear(0x00406080, 0, 0x1234);  // the whole screen
      grClipWindow(10, 20, 266, 276);
      grBufferClear(0x00F00000, 0, GR_WDEPTHVALUE_FARTHEST);
      grClipWindow(300, 5, 330, 400);
      grDepthMask(FXFALSE);
      grBufferClear(0x0000FF00, 0, 0x4000);  // colour only: depth writes are off
      grColorMask(FXFALSE, FXFALSE);
      grDepthMask(FXTRUE);
      grClipWindow(100, 100, 600, 130);
      grBufferClear(0x000000FF, 0, 0x2000);  // depth only: colour writes are off
      grColorMask(FXTRUE, FXFALSE);
      grClipWindow(50, 50, 50, 90);
      grBufferClear(0x00FFFFFF, 0, 0);  // an empty window clears nothing
      grClipWindow(0, 0, 640, 480);
    };
    const std::string what = origin == GR_ORIGIN_UPPER_LEFT ? "upper-left origin" : "lower-left origin";
    const Buffers fast = render(false, GR_BUFFER_BACKBUFFER, draw);
    const Buffers exact = render(true, GR_BUFFER_BACKBUFFER, draw);
    // Red 240 (565 0xF000) fills the first window, green the second, which it does not overlap.
    std::size_t red = 0, green = 0, white = 0;
    for (FxU16 word : fast.color) red += word == 0xF000, green += word == 0x07E0, white += word == 0xFFFF;
    EXPECT_EQ(red, 256u * 256u) << what;
    EXPECT_EQ(green, 30u * 395u) << what;
    EXPECT_EQ(white, 0u) << what;
    expect_same(fast, exact, what);
  }
}

// grBufferClear of the whole screen, whose colour the fast paths copy on llvmpipe once it is
// cleared whole twice in a row or its own side buffer already holds it (clipped_clear.cpp): a
// colour repeated, changed, back again, with a new depth, colour alone, and after a clipped clear
// of the same colour; a triangle and a swap each frame, both buffers compared.
TEST(WholeClears, FastPathsGiveTheExactBytes) {
  const GrColor_t colors[8] = {0x302010, 0x302010, 0x302010, 0xA0C0E0,
                               0x302010, 0x302010, 0xA0C0E0, 0xA0C0E0};
  std::uint64_t copied = 0;
  bool llvmpipe = false;
  auto draw = [&] {
    grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
    guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
    for (int frame = 0; frame < 8; ++frame) {
      grDepthMask(frame == 5 ? FXFALSE : FXTRUE);  // frame 5: colour only
      if (frame == 6) {
        grClipWindow(100, 100, 200, 150);
        grBufferClear(colors[frame], 0, GR_WDEPTHVALUE_FARTHEST);
        grClipWindow(0, 0, 640, 480);
      }
      grBufferClear(colors[frame], 0, frame == 2 ? 0x1234 : GR_WDEPTHVALUE_FARTHEST);
      const float x = 40.0f * static_cast<float>(frame);
      GrVertex a{}, b{}, c{};
      a.x = 20 + x, a.y = 30, b.x = 300 + x, b.y = 60, c.x = 90 + x, c.y = 400;
      a.oow = b.oow = c.oow = 0.5f;
      a.r = 250, b.g = 200, c.b = 150;
      grDrawTriangle(&a, &b, &c);
      grBufferSwap(0);
    }
    glide_shim::GlRenderer &renderer = *glide_shim::current().renderer;
    copied = renderer.colors_copied();
    using GetString = const GLubyte *(*)(GLenum);
    auto get_string = reinterpret_cast<GetString>(renderer.proc_address("glGetString"));
    const char *name = reinterpret_cast<const char *>(get_string(GL_RENDERER));
    llvmpipe = name != nullptr && std::string(name).find("llvmpipe") != std::string::npos;
  };
  for (GrBuffer_t buffer : {GR_BUFFER_FRONTBUFFER, GR_BUFFER_BACKBUFFER}) {
    const std::string what = buffer == GR_BUFFER_FRONTBUFFER ? "front buffer" : "back buffer";
    const Buffers exact = render(true, buffer, draw);
    EXPECT_EQ(copied, 0u) << "GLIDESHIM_EXACT=1 clears through GL";
    const Buffers fast = render(false, buffer, draw);
    // Frames 1, 2, 4, 5 and 7, and frame 6's clipped clear; a whole clear of a colour the
    // whole target was not cleared to just before is a glClear (frame 6's too: the clipped
    // clear's side buffer is not the whole target's).
    if (llvmpipe) {
      EXPECT_EQ(copied, 6u) << what << ": colour clears copied";
    }
    expect_drawn(exact, what);
    expect_same(fast, exact, what);
  }
}

// demo_bench's three frames: no shadows, projected shadows through the LFB, and through texture
// memory directly; three moments of the fight, each after two frames before it.
class FightFrames : public ::testing::TestWithParam<int> {};

TEST_P(FightFrames, FastPathsGiveTheExactBytes) {
  const int mode = GetParam();
  auto draw = [&] {
    gs::FightScene fight(640, 480, 256);
    gs::ProjectedShadowOptions options;
    options.direct_path = mode == 2;
    for (int frame : {0, 1, 31, 32, 63}) {
      const gs::Scene &scene = fight.at(static_cast<float>(frame) / 30.0f);
      if (mode == 0) {
        gs::render_scene(scene, gs::project_scene(scene));
      } else {
        gs::render_projected_shadows(scene, options, false);
      }
      grBufferSwap(0);
    }
  };
  const char *names[3] = {"no shadows", "LFB path", "direct path"};
  const Buffers fast = render(false, GR_BUFFER_FRONTBUFFER, draw);
  const Buffers exact = render(true, GR_BUFFER_FRONTBUFFER, draw);
  expect_drawn(exact, names[mode]);
  expect_same(fast, exact, names[mode]);
}

INSTANTIATE_TEST_SUITE_P(Modes, FightFrames, ::testing::Values(0, 1, 2), mode_name);

class Figures : public ::testing::TestWithParam<const gs::FigureEntry *> {};

TEST_P(Figures, FastPathsGiveTheExactBytes) {
  const gs::FigureEntry &entry = *GetParam();
  auto make = [&](bool exact) {
    ExactSwitch exact_switch(exact);
    grGlideInit();
    gs::Figure figure;
    std::string error;
    EXPECT_TRUE(gs::make_figure(entry, figure, error)) << error;
    EXPECT_EQ(glide_shim::current().fast_paths, !exact);
    grGlideShutdown();
    return figure.image.rgb;
  };
  const std::vector<std::uint8_t> fast = make(false), exact = make(true);
  ASSERT_FALSE(exact.empty());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < exact.size() && i < fast.size(); ++i) differing += fast[i] != exact[i];
  EXPECT_EQ(fast.size(), exact.size());
  EXPECT_EQ(differing, 0u) << entry.name << ": bytes that differ";
}

std::vector<const gs::FigureEntry *> every_figure() {
  std::vector<const gs::FigureEntry *> all;
  for (const gs::FigureEntry &entry : gs::figure_table()) all.push_back(&entry);
  return all;
}

INSTANTIATE_TEST_SUITE_P(Articles, Figures, ::testing::ValuesIn(every_figure()), figure_name);

std::string file_bytes(const fs::path &path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs tests/sdk/<name> for 2 frames in tests/sdk/data with every swap dumped; returns the dump
// directory's frames as files.
std::vector<std::string> run_sdk_program(const std::string &name, bool exact) {
  const fs::path dir = fs::path(test_output_path(name + (exact ? "_exact" : "_fast")));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string command = std::string("cd ") + SDK_DATA_DIR + " && GLIDESHIM_EXACT=" +
                              (exact ? "1" : "0") + " GLIDESHIM_DUMP_DIR=" + dir.string() + " " +
                              SDK_PROGRAM_DIR + "/sdk_" + name + " -n 2 > " +
                              (dir / "log.txt").string() + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command << "\n" << file_bytes(dir / "log.txt");
  std::vector<std::string> frames;
  for (int i = 0; fs::exists(dir / ("frame_0000" + std::to_string(i) + ".png")); ++i) {
    frames.push_back(file_bytes(dir / ("frame_0000" + std::to_string(i) + ".png")));
  }
  return frames;
}

class SdkPrograms : public ::testing::TestWithParam<const char *> {};

TEST_P(SdkPrograms, FastPathsGiveTheExactBytes) {
  const std::vector<std::string> fast = run_sdk_program(GetParam(), false);
  const std::vector<std::string> exact = run_sdk_program(GetParam(), true);
  ASSERT_FALSE(exact.empty()) << "no frame dumped";
  ASSERT_EQ(fast.size(), exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i) {
    EXPECT_TRUE(fast[i] == exact[i]) << GetParam() << ": frame " << i << " differs";
  }
}

INSTANTIATE_TEST_SUITE_P(Programs, SdkPrograms,
                         ::testing::Values("fog_ramp", "polygon_fans", "state_round_trip",
                                           "lfb_formats", "aa_lines", "lfb_pipeline",
                                           "mip_levels", "palette_texture", "load_3df",
                                           "gu_texture_manager"),
                         [](const ::testing::TestParamInfo<const char *> &param) {
                           return std::string(param.param);
                         });

// The fidelity knobs' list: the known names set their bits; a name the shim does not know is
// reported at grSstWinOpen (naming it) and the window opens with the others applied.
TEST(FidelityKnobs, KnownNamesSetTheirBits) {
  std::string unknown;
  EXPECT_EQ(glide_shim::parse_fidelity_knobs(nullptr, unknown), 0);
  EXPECT_EQ(glide_shim::parse_fidelity_knobs("", unknown), 0);
  EXPECT_EQ(glide_shim::parse_fidelity_knobs("write,bilinear", unknown),
            glide_shim::kPlainWrite | glide_shim::kPlainBilinear);
  EXPECT_EQ(unknown, "");
  EXPECT_EQ(glide_shim::parse_fidelity_knobs("all", unknown),
            glide_shim::kPlainWrite | glide_shim::kPlainIterators | glide_shim::kPlainCombine |
                glide_shim::kPlainBilinear);
}

TEST(FidelityKnobs, AnUnknownNameIsReportedAndTheOthersApply) {
  setenv("GLIDESHIM_PLAIN_GL", "combine,dithr", 1);
  setenv("GLIDESHIM_QUIET", "1", 1);
  grGlideInit();
  glideShimClearError();
  const bool opened = grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                                   GR_ORIGIN_UPPER_LEFT, 2, 1);
  unsetenv("GLIDESHIM_PLAIN_GL");
  unsetenv("GLIDESHIM_QUIET");
  EXPECT_TRUE(opened);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_VALUE);
  EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find("'dithr'"), std::string::npos)
      << glideShimGetLastErrorMessage();
  EXPECT_EQ(glide_shim::current().fidelity_knobs, glide_shim::kPlainCombine);
  grGlideShutdown();
}

}  // namespace

// Frames rendered through the shim against reference_images/. Tolerances: llvmpipe's output
// depends on the CPU's vector ISA (measured on this Mesa: up to ~2.5k pixels by <= 3 levels between
// SSE4.1 and AVX2), so a pixel may differ by 4/255 and 1% of pixels may differ more.
#include "glide_window.h"
#include "image_compare.h"

#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace {

const ImageTolerance kAcrossCpus{4.0f / 255.0f, 0.01};

TEST(SampleProgram, HelloGlideWritesTheExpectedFrame) {
  // The plain-C sample program, run as a user would; it must write its PNG and say so.
  const std::string png = output_path("hello_glide.png");
  std::remove(png.c_str());
  const std::string command = std::string(HELLO_GLIDE_PATH) + " " + png + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  EXPECT_TRUE(matches_reference("hello_glide", png, kAcrossCpus));
}

std::string file_bytes(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(SampleProgram, ArticlePortRendersItsShadow) {
  // The article's five steps as plain C Glide code (examples/article_port.c), run as a user would.
  const std::string png = output_path("article_port.png");
  std::remove(png.c_str());
  const std::string command = std::string(ARTICLE_PORT_PATH) + " " + png + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  EXPECT_TRUE(matches_reference("article_port", png, kAcrossCpus));
}

// examples/crate_3df.c, an SDK-style program, run as a user would from examples/data (where its .3df
// textures are) with the frame dump on into its own directory `run` (tests may run at once).
// Returns that directory; the program's output is in log.txt there, its exit status in `status`.
std::filesystem::path run_crate_3df(const std::string &run, const std::string &arguments,
                                    int &status) {
  const std::filesystem::path dir = std::filesystem::path(output_path("crate_3df_" + run));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string command = "cd " + std::string(EXAMPLES_DATA_DIR) + " && GLIDESHIM_DUMP_DIR=" +
                              dir.string() + " " + CRATE_3DF_PATH + " " + arguments + " > " +
                              (dir / "log.txt").string() + " 2>&1";
  status = std::system(command.c_str());
  return dir;
}

TEST(SampleProgram, Crate3dfRendersItsTexturesFromDotThreeDfFiles) {
  int status = -1;
  const std::filesystem::path dir = run_crate_3df("frames", "-n 12", status);
  const std::string log = file_bytes((dir / "log.txt").string());
  ASSERT_EQ(status, 0) << log;
  EXPECT_NE(log.find("crate_3df: 12 frames at 640x480"), std::string::npos) << log;
  EXPECT_TRUE(std::filesystem::exists(dir / "frame_00011.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_00012.png")) << "-n 12 draws 12 frames";
  EXPECT_TRUE(matches_reference("crate_3df", (dir / "frame_00011.png").string(), kAcrossCpus));
  // The crate turns from frame to frame.
  EXPECT_NE(file_bytes((dir / "frame_00000.png").string()),
            file_bytes((dir / "frame_00011.png").string()));
}

TEST(SampleProgram, Crate3dfNamesATextureItCannotRead) {
  int status = -1;
  const std::filesystem::path dir = run_crate_3df("missing_texture", "-n 1 -d /nonexistent/textures", status);
  const std::string log = file_bytes((dir / "log.txt").string());
  EXPECT_NE(status, 0);
  EXPECT_NE(log.find("/nonexistent/textures/crate.3df"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_00000.png")) << "nothing drawn";
}

TEST(FightDemo, FramesMatchTheirReferences) {
  // Two moments of the fight (guard, and the red fighter's punch) at 320x240, run through the
  // command-line tool exactly as a user would.
  const std::filesystem::path dir = std::filesystem::path(output_path("fight"));
  std::filesystem::remove_all(dir);
  const std::string command = std::string(GLIDESHADOWS_PATH) + " demo --frames 64 --fps 30 --size 320x240 --out " +
                              dir.string() + " --shadow-size 128 > /dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  EXPECT_TRUE(matches_reference("fight_frame_0010", (dir / "frame_0010.png").string(), kAcrossCpus));
  EXPECT_TRUE(matches_reference("fight_frame_0063", (dir / "frame_0063.png").string(), kAcrossCpus));
}

TEST(FightDemo, SpotlightBeamMapCastsTheGobosBarsOnTheRing) {
  // The demo's spotlight as a projective-texture light: the window gobo's bars take the light
  // off bands of the ring that the plain cone lights; exact attenuation needs a beam map.
  const std::filesystem::path plain = output_path("fight_plain"), gobo = output_path("fight_gobo");
  const std::string base = std::string(GLIDESHADOWS_PATH) + " demo --frames 1 --size 320x240 --out ";
  ASSERT_EQ(std::system((base + plain.string() + " > /dev/null 2>&1").c_str()), 0);
  ASSERT_EQ(std::system((base + gobo.string() + " --beam gobo --attenuation exact > /dev/null 2>&1").c_str()), 0);
  OIIO::ImageBuf a((plain / "frame_0000.png").string()), b((gobo / "frame_0000.png").string());
  ASSERT_TRUE(a.read(0, 0, true, OIIO::TypeDesc::FLOAT) && b.read(0, 0, true, OIIO::TypeDesc::FLOAT));
  long barred = 0;
  for (int y = 0; y < 240; ++y) {
    for (int x = 0; x < 320; ++x) {
      float lit[3], cut[3];
      a.getpixel(x, y, lit, 3);
      b.getpixel(x, y, cut, 3);
      barred += lit[1] - cut[1] > 0.25f;  // a lit pixel (green) the bars turned dark
    }
  }
  EXPECT_GT(barred, 300) << "the gobo's bars should darken bands of the lit ring";
  const std::string log = output_path("fight_exact_without_beam.log");
  EXPECT_NE(std::system((base + output_path("fight_bad") + " --attenuation exact 2> " + log).c_str()), 0);
  EXPECT_NE(file_bytes(log).find("--attenuation exact needs a beam map"), std::string::npos);
}

TEST(SceneFiles, EverySampleSceneRendersWithItsMask) {
  // `glideshadows render` on each file in scenes/, as a user would run it.
  int scenes = 0;
  for (const auto &entry : std::filesystem::directory_iterator(SCENES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    ++scenes;
    const std::string stem = entry.path().stem().string();
    const std::string png = output_path("scene_" + stem + ".png"), mask = output_path("scene_" + stem + "_mask.png");
    std::remove(png.c_str());
    std::remove(mask.c_str());
    const std::string command = std::string(GLIDESHADOWS_PATH) + " render " + entry.path().string() +
                                " --out " + png + " --mask " + mask + " > /dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    EXPECT_TRUE(std::filesystem::exists(png) && std::filesystem::exists(mask)) << stem;
  }
  EXPECT_GE(scenes, 4);
}

TEST(SceneFiles, EveryTechniqueRendersAndMasksFromTheCommandLine) {
  // The same scene through every technique name the tool offers, with their options, as a user
  // comparing them would run it; each must shadow the floor.
  const std::string scene = std::string(SCENES_DIR) + "/box_on_plane.json";
  for (const std::string technique :
       {"projected", "projected-chroma --point", "planar", "depth-map --nearest --bias-units 8",
        "stencil-volume --volume zfail"}) {
    const std::string tag = technique.substr(0, technique.find(' '));
    const std::string png = output_path("technique_" + tag + ".png");
    const std::string mask = output_path("technique_" + tag + "_mask.png");
    std::remove(mask.c_str());
    const std::string command = std::string(GLIDESHADOWS_PATH) + " render " + scene +
                                " --technique " + technique + " --out " + png + " --mask " + mask +
                                " > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    OIIO::ImageBuf image(mask);
    ASSERT_TRUE(image.read()) << mask;
    std::vector<unsigned char> pixels(static_cast<std::size_t>(image.spec().image_pixels()) * 3);
    image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, pixels.data());
    // White scans out as 254: the Voodoo's 33-entry CLUT at gamma 1 maps 255 to 254.
    const long white = std::count_if(pixels.begin(), pixels.end(), [](unsigned char v) { return v >= 250; });
    EXPECT_GT(white, 3 * 1000) << technique << ": no shadow in its mask";
  }
}

TEST(SceneFiles, TruthAndCompareMeasureATechniqueAgainstRayCasting) {
  // glideshadows truth writes the exact mask; compare reports the technique's errors against it.
  const std::string scene = std::string(SCENES_DIR) + "/box_on_plane.json";
  const std::string truth = output_path("truth_mask.png"), image = output_path("truth_image.png");
  const std::string mask = output_path("projected_mask.png"), report = output_path("compare.txt");
  const std::string heat = output_path("compare_heat.png");
  const std::string tool = GLIDESHADOWS_PATH;
  ASSERT_EQ(std::system((tool + " truth " + scene + " --mask " + truth + " --image " + image + " > /dev/null").c_str()), 0);
  ASSERT_EQ(std::system((tool + " render " + scene + " --out " + output_path("projected.png") + " --mask " + mask + " > /dev/null").c_str()), 0);
  ASSERT_EQ(std::system((tool + " compare " + mask + " " + truth + " --diff " + heat + " > " + report).c_str()), 0);
  const std::string text = file_bytes(report);
  const std::size_t at = text.find("as masks (B the truth): ");
  ASSERT_NE(at, std::string::npos) << text;
  const double misclassified = std::atof(text.c_str() + at + std::strlen("as masks (B the truth): "));
  // The projected texture on this scene is wrong only along the shadow's edge.
  EXPECT_LT(misclassified, 0.5) << text;
  EXPECT_TRUE(std::filesystem::exists(heat) && std::filesystem::exists(image));
}

TEST(SceneFiles, QuickBenchWritesTableCsvPlotAndBudget) {
  const std::string csv = output_path("bench.csv"), plot = output_path("bench.png"),
                    out = output_path("bench.txt");
  const std::string command = std::string(GLIDESHADOWS_PATH) + " bench --quick --repeats 2 --csv " +
                              csv + " --plot " + plot + " --budget 0.05 > " + out + " 2> /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::string table = file_bytes(out), rows = file_bytes(csv);
  for (const char *technique : {"projected", "planar", "depth-map", "stencil-volume", "none"}) {
    EXPECT_NE(table.find(technique), std::string::npos) << technique << " missing from\n" << table;
  }
  EXPECT_EQ(rows.rfind("frame,technique,settings,frame_ms,ratio_to_none,misclassified", 0), 0u);
  EXPECT_NE(table.find("budget 0.0500, fight t=2.1: "), std::string::npos) << table;
  EXPECT_TRUE(std::filesystem::exists(plot));
}

TEST(SceneFiles, ABadSceneIsRefusedWithTheFieldNamed) {
  const std::string bad = output_path("bad_scene.json");
  std::FILE *file = std::fopen(bad.c_str(), "w");
  ASSERT_NE(file, nullptr);
  std::fputs("{\"camera\": {\"position\": [0, 1, 5], \"target\": [0, 0, 0]},"
             " \"objects\": [{\"mesh\": {\"shape\": \"cube\"}}]}", file);
  std::fclose(file);
  const std::string log = output_path("bad_scene.log");
  const std::string command = std::string(GLIDESHADOWS_PATH) + " render " + bad + " --out " +
                              output_path("bad_scene.png") + " 2> " + log;
  EXPECT_NE(std::system(command.c_str()), 0);
  EXPECT_NE(file_bytes(log).find("objects[0].mesh.shape"), std::string::npos) << file_bytes(log);
}

TEST(SampleProgram, RunsAreByteIdentical) {
  const std::string first = output_path("determinism_1.png"), second = output_path("determinism_2.png");
  for (const std::string &png : {first, second}) {
    const std::string command = std::string(HELLO_GLIDE_PATH) + " " + png + " > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
  }
  const std::string a = file_bytes(first), b = file_bytes(second);
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << first << " and " << second << " differ";
}

TEST(SampleProgram, DumpDirectoryGetsEveryDisplayedFrame) {
  // GLIDESHIM_DUMP_DIR makes grBufferSwap write the displayed buffer, with no code change.
  const std::filesystem::path dir = std::filesystem::path(output_path("dump"));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string png = output_path("dump_reference.png");
  const std::string command = "GLIDESHIM_DUMP_DIR=" + dir.string() + " " + HELLO_GLIDE_PATH + " " +
                              png + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::string dumped = (dir / "frame_00000.png").string();
  ASSERT_TRUE(std::filesystem::exists(dumped));
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_00001.png"));  // the program swaps once
  EXPECT_TRUE(file_bytes(dumped) == file_bytes(png)) << "the dump differs from the front buffer";
}

class ShimImageTest : public GlideWindowTest {
 protected:
  std::string write_front(const std::string &name) {
    grBufferSwap(1);
    const std::string png = output_path(name + ".png");
    EXPECT_TRUE(glideShimWritePng(GR_BUFFER_FRONTBUFFER, png.c_str())) << glideShimGetLastErrorMessage();
    return png;
  }
};

TEST_F(ShimImageTest, GouraudWithFourByFourDitherAndGamma) {
  // The hardware defaults: 4x4 dither on, gamma 1.7 at scan-out.
  GrVertex a = vertex(), b = vertex(), c = vertex();
  a.x = 2, a.y = 2, a.r = 255;
  b.x = 62, b.y = 10, b.g = 255;
  c.x = 20, c.y = 62, c.b = 255, c.r = 60;
  grBufferClear(0x00202020u, 0, 0);
  grDrawTriangle(&a, &b, &c);
  EXPECT_TRUE(matches_reference("gouraud_dither_gamma", write_front("gouraud_dither_gamma"), kAcrossCpus));
}

TEST_F(ShimImageTest, ShadowPassOverAReceiver) {
  // A miniature of the article's step 5: a flat 4444 mask (alpha F inside a disc), projected
  // with bilinear filtering, blended at iterated alpha 170 over a Gouraud floor.
  grDitherMode(GR_DITHER_DISABLE);
  grGammaCorrectionValue(0.8f);
  std::vector<FxU16> mask(32 * 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      mask[static_cast<std::size_t>(y * 32 + x)] =
          (x - 16) * (x - 16) + (y - 16) * (y - 14) < 100 ? 0xF000 : 0x0000;
  GrVertex floor_style = vertex();
  floor_style.r = 200, floor_style.g = 180, floor_style.b = 120;
  draw_rect(0, 0, kWidth, kHeight, floor_style);

  GrTexInfo info{GR_LOD_32, GR_LOD_32, GR_ASPECT_1x1, GR_TEXFMT_ARGB_4444, mask.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  guAlphaSource(GR_ALPHASOURCE_TEXTURE_ALPHA_TIMES_ITERATED_ALPHA);
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO);
  GrVertex shadow = vertex();
  shadow.a = 170;
  GrVertex v[4] = {shadow, shadow, shadow, shadow};
  const float xs[4] = {4, 60, 60, 4}, ys[4] = {8, 8, 56, 56}, s[4] = {0, 256, 256, 0},
              t[4] = {0, 0, 256, 256};
  for (int k = 0; k < 4; ++k) {
    v[k].x = xs[k], v[k].y = ys[k], v[k].tmuvtx[0].sow = s[k], v[k].tmuvtx[0].tow = t[k];
  }
  grDrawTriangle(&v[0], &v[1], &v[2]);
  grDrawTriangle(&v[0], &v[2], &v[3]);
  EXPECT_TRUE(matches_reference("shadow_pass", write_front("shadow_pass"), kAcrossCpus));
  expect_no_error();
}

}  // namespace

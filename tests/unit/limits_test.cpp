// Resource limits: absurd sizes are refused with a message naming the limit, before anything is
// allocated or read (docs/cli.md, docs/scene_format.md). The scene file, the OBJ loader, the
// command line and the Glide window each get the request a careless or hostile input would make.
// Limits already covered elsewhere: divisions, triangle budget, screen and shadow sizes in scene
// files (scene_file_test.cpp, tests/data/bad_scenes); texture LODs, TMU memory, LFB regions and
// coordinates in the shim (bad_input_*_test.cpp).
#include "scene/mesh.h"
#include "scene/scene.h"

#include "tool_run.h"

#include <gtest/gtest.h>
#include <glide.h>
#include <glide_shim.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

// A fresh scratch directory for one test.
std::string scratch(const std::string &name) {
  const fs::path path = fs::path(::testing::TempDir()) / ("limits_" + name);
  fs::remove_all(path);
  fs::create_directories(path);
  return path.string();
}

std::string write_file(const std::string &path, const std::string &contents) {
  std::ofstream(path, std::ios::binary) << contents;
  return path;
}

// A file of `bytes` bytes that takes no disk space (a hole), for the size limits.
std::string sparse_file(const std::string &path, std::uintmax_t bytes) {
  write_file(path, "");
  fs::resize_file(path, bytes);
  return path;
}

std::string fifo(const std::string &path) {
  EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0) << path;
  return path;
}

std::string scene_with_lights(int count) {
  std::string lights;
  for (int i = 0; i < count; ++i)
    lights += std::string(i > 0 ? ", " : "") + R"({"position": [0, 5, 0], "target": [0, 0, 0]})";
  return R"({"camera": {"position": [0, 2, 5], "target": [0, 0, 0]}, "lights": [)" + lights +
         R"(], "objects": [{"mesh": {"shape": "box"}}]})";
}

// ---- scene files ---------------------------------------------------------------------------

TEST(SceneFileLimits, SixteenLightsLoad) {
  const std::string path = write_file(scratch("16_lights") + "/scene.json", scene_with_lights(16));
  gs::Scene scene;
  std::string error;
  ASSERT_TRUE(gs::load_scene(path, scene, error)) << error;
  EXPECT_EQ(scene.lights.size(), 16u);
}

TEST(SceneFileLimits, SeventeenLightsAreRefusedNamingTheLimit) {
  const std::string path = write_file(scratch("17_lights") + "/scene.json", scene_with_lights(17));
  gs::Scene scene;
  std::string error;
  ASSERT_FALSE(gs::load_scene(path, scene, error));
  EXPECT_EQ(error, path + ": lights: has 17 lights, more than the limit of 16");
  EXPECT_TRUE(scene.lights.empty());
}

TEST(SceneFileLimits, FileOverSixteenMebibytesIsRefusedUnread) {
  const std::string path = sparse_file(scratch("big_scene") + "/scene.json", (16u << 20) + 1);
  gs::Scene scene;
  std::string error;
  ASSERT_FALSE(gs::load_scene(path, scene, error));
  EXPECT_EQ(error, path + ": the file has 16777217 bytes, more than the limit of 16777216");
}

TEST(SceneFileLimits, DeviceFifoAndDirectoryAreRefusedNotRead) {
  gs::Scene scene;
  std::string error;
  ASSERT_FALSE(gs::load_scene("/dev/zero", scene, error));  // would never end if read
  EXPECT_EQ(error, "/dev/zero: is not a regular file");
  const std::string pipe = fifo(scratch("fifo_scene") + "/scene.json");  // would block if opened
  ASSERT_FALSE(gs::load_scene(pipe, scene, error));
  EXPECT_EQ(error, pipe + ": is not a regular file");
  const std::string directory = scratch("directory_scene");
  ASSERT_FALSE(gs::load_scene(directory, scene, error));
  EXPECT_EQ(error, directory + ": is a directory, not a file");
}

TEST(SceneFileLimits, ObjMeshOnADeviceIsRefusedNamingTheField) {
  const std::string path = write_file(scratch("obj_device") + "/scene.json",
                                      R"({"camera": {"position": [0, 2, 5], "target": [0, 0, 0]},
                                          "objects": [{"mesh": {"obj": "/dev/zero"}}]})");
  gs::Scene scene;
  std::string error;
  ASSERT_FALSE(gs::load_scene(path, scene, error));
  EXPECT_EQ(error, path + ": objects[0].mesh.obj: /dev/zero: is not a regular file");
}

// ---- OBJ meshes ----------------------------------------------------------------------------

TEST(ObjLimits, MoreThanTwoMillionTrianglesAreRefusedBeforeTheMeshIsBuilt) {
  // 2,000,001 triangles over three vertices: a 16 MB file.
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  text.reserve(text.size() + 8 * 2'000'001);
  for (int i = 0; i < 2'000'001; ++i) text += "f 1 2 3\n";
  const std::string path = write_file(scratch("obj_triangles") + "/huge.obj", text);
  gs::Mesh mesh = gs::make_box(glm::vec3(1.0f));
  std::string error;
  ASSERT_FALSE(gs::load_obj(path, mesh, error));
  EXPECT_EQ(error, path + ": 2000001 triangles, more than the limit of 2000000");
  EXPECT_EQ(mesh.triangle_count(), 12u);  // the box, untouched
}

TEST(ObjLimits, FileOver256MebibytesIsRefusedUnread) {
  const std::string path = sparse_file(scratch("obj_big") + "/big.obj", (256u << 20) + 1);
  gs::Mesh mesh;
  std::string error;
  ASSERT_FALSE(gs::load_obj(path, mesh, error));
  EXPECT_EQ(error, path + ": the file has 268435457 bytes, more than the limit of 268435456");
}

TEST(ObjLimits, DeviceAndFifoAreRefusedNotRead) {
  gs::Mesh mesh;
  std::string error;
  ASSERT_FALSE(gs::load_obj("/dev/zero", mesh, error));
  EXPECT_EQ(error, "/dev/zero: is not a regular file");
  const std::string pipe = fifo(scratch("obj_fifo") + "/mesh.obj");
  ASSERT_FALSE(gs::load_obj(pipe, mesh, error));
  EXPECT_EQ(error, pipe + ": is not a regular file");
}

TEST(ObjLimits, MaterialLibraryIsNeverOpened) {
  // Opening a FIFO without a writer blocks: the load finishing shows mtllib was not followed.
  const std::string dir = scratch("obj_mtllib");
  const std::string pipe = fifo(dir + "/materials.mtl");
  const std::string path = write_file(dir + "/mesh.obj", "mtllib " + pipe +
                                                             "\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                             "usemtl red\nf 1 2 3\n");
  gs::Mesh mesh;
  std::string error;
  ASSERT_TRUE(gs::load_obj(path, mesh, error)) << error;
  EXPECT_EQ(mesh.triangle_count(), 1u);
}

// ---- the command line ----------------------------------------------------------------------

ToolRun run_tool(const std::string &arguments) { return ::run_tool(GLIDESHADOWS_PATH, arguments); }

TEST(CommandLineLimits, AbsurdScreenSizesAreRefusedNamingTheRange) {
  const std::string out = scratch("cli_size");
  for (const std::string size : {"100000x100000", "99999999999999999999x480", "640x-480",
                                 "2049x2048", "63x480", "640x480x", "640"}) {
    const ToolRun run = run_tool("demo --frames 1 --size " + size + " --out " + out);
    EXPECT_EQ(run.exit_code, 2) << size << ": " << run.output;
    EXPECT_NE(run.output.find("--size '" + size + "' must be WxH with each side 64..2048"),
              std::string::npos)
        << run.output;
  }
  EXPECT_TRUE(fs::is_empty(out)) << "a refused size still wrote frames";
}

TEST(CommandLineLimits, ShadowSizesBeyondFiveHundredTwelveAreRefused) {
  for (const std::string size : {"1024", "4096", "1000000000", "0", "100"}) {
    const ToolRun run = run_tool("demo --frames 1 --shadow-size " + size + " --out " + scratch("cli_shadow"));
    EXPECT_EQ(run.exit_code, 2) << size;  // a usage error (CLI11's 105 is mapped, docs/cli.md)
    EXPECT_NE(run.output.find("--shadow-size"), std::string::npos) << run.output;
  }
}

TEST(CommandLineLimits, FrameCountsBeyondOneHundredThousandAreRefused) {
  const ToolRun run = run_tool("demo --frames 1000000000 --out " + scratch("cli_frames"));
  EXPECT_NE(run.exit_code, 0);
  EXPECT_NE(run.output.find("--frames"), std::string::npos) << run.output;
}

TEST(CommandLineLimits, SceneOverTheLightLimitIsRefusedByRender) {
  const std::string dir = scratch("cli_lights");
  const std::string scene = write_file(dir + "/scene.json", scene_with_lights(100));
  const ToolRun run = run_tool("render " + scene + " --out " + dir + "/out.png");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("has 100 lights, more than the limit of 16"), std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(dir + "/out.png"));
}

// ---- the Glide window ----------------------------------------------------------------------

TEST(GlideLimits, AbsurdWindowSizeIsRefusedAndTheDefaultStays) {
  grGlideInit();
  glideShimClearError();
  EXPECT_EQ(glideShimSetWindowSize(100000, 100000), FXFALSE);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  EXPECT_STREQ(glideShimGetLastErrorMessage(),
               "glideShimSetWindowSize: 100000x100000 is outside 1..2048 per side");
  ASSERT_EQ(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                         GR_ORIGIN_UPPER_LEFT, 2, 1),
            FXTRUE)
      << glideShimGetLastErrorMessage();
  GrLfbInfo_t info{};
  info.size = sizeof info;
  ASSERT_EQ(grLfbLock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_ANY,
                      GR_ORIGIN_UPPER_LEFT, FXFALSE, &info),
            FXTRUE);
  EXPECT_EQ(info.strideInBytes, 640u * 2u);  // still the default 640 pixels wide
  grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER);
  grGlideShutdown();
}

TEST(GlideLimits, PolygonOfABillionVerticesIsRefusedWithoutReadingThem) {
  grGlideInit();
  ASSERT_EQ(glideShimSetWindowSize(64, 64), FXTRUE);
  ASSERT_EQ(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                         GR_ORIGIN_UPPER_LEFT, 2, 1),
            FXTRUE)
      << glideShimGetLastErrorMessage();
  const GrVertex triangle[3] = {};  // the only vertices there are: reading past them is a bug
  const int ilist[3] = {0, 1, 2};
  glideShimClearError();
  grDrawPolygonVertexList(1'000'000'000, triangle);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  EXPECT_STREQ(glideShimGetLastErrorMessage(),
               "grDrawPolygonVertexList: 1000000000 vertices, more than the limit of 65536");
  glideShimClearError();
  grDrawPolygon(1'000'000'000, ilist, triangle);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  EXPECT_STREQ(glideShimGetLastErrorMessage(),
               "grDrawPolygon: 1000000000 vertices, more than the limit of 65536");
  glideShimClearError();
  guDrawPolygonVertexListWithClip(1'000'000'000, triangle);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  EXPECT_STREQ(glideShimGetLastErrorMessage(),
               "guDrawPolygonVertexListWithClip: 1000000000 vertices, more than the limit of 65536");
  grGlideShutdown();
}

}  // namespace

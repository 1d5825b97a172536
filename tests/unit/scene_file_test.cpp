// The JSON scene-file loader (docs/scene_format.md): the sample scenes in scenes/ load with the
// values they were written with; transforms compose as documented; every file in
// tests/data/bad_scenes is refused with a message naming the file and the broken field's JSON
// path, and a refused load leaves the caller's Scene as it was.
#include "scene/scene.h"
#include "scene_file_test_support.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace {

using scene_file_test::kSourceDir;
using scene_file_test::load_or_fail;
using scene_file_test::write_scene;

const std::string kBadScenesDir = kSourceDir + "/tests/data/bad_scenes";

constexpr float kTolerance = 1e-5f;  // float round-off of the matrix products, metres

// A valid scene around one object, for the tests of a single object field.
std::string one_object_scene(const std::string &object) {
  return R"({"camera": {"position": [0, 2, 5], "target": [0, 0, 0]}, "objects": [)" + object + "]}";
}

glm::vec3 world_point(const gs::SceneObject &object, const glm::vec3 &model_point) {
  return glm::vec3(object.model_to_world * glm::vec4(model_point, 1.0f));
}

glm::vec3 translation(const gs::SceneObject &object) { return world_point(object, glm::vec3(0)); }

bool all_colors_are(const gs::Mesh &mesh, const glm::vec3 &color) {
  for (const glm::vec3 &c : mesh.colors)
    if (glm::length(c - color) > kTolerance) return false;
  return !mesh.colors.empty();
}

::testing::AssertionResult vec3_near(const glm::vec3 &expected, const glm::vec3 &actual) {
  if (glm::length(expected - actual) < kTolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "expected (" << expected.x << ", " << expected.y << ", " << expected.z << "), got ("
         << actual.x << ", " << actual.y << ", " << actual.z << ")";
}

// ---- the sample scenes -----------------------------------------------------------------------

TEST(SceneFile, BoxOnPlaneLoads) {
  const gs::Scene scene = load_or_fail(kSourceDir + "/scenes/box_on_plane.json");
  ASSERT_EQ(scene.objects.size(), 2u);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.width, 640);
  EXPECT_EQ(scene.height, 480);

  const gs::SceneObject &floor = scene.objects[0];
  EXPECT_EQ(floor.name, "floor");
  EXPECT_EQ(floor.mesh.triangle_count(), 2u * 16u * 16u);
  EXPECT_FALSE(floor.casts_shadow);
  EXPECT_TRUE(floor.receives_shadow);

  const gs::SceneObject &box = scene.objects[1];
  EXPECT_EQ(box.name, "box");
  EXPECT_TRUE(box.casts_shadow);
  EXPECT_FALSE(box.receives_shadow);
  EXPECT_TRUE(box.shadow_mesh.positions.empty());
  EXPECT_TRUE(all_colors_are(box.mesh, {0.9f, 0.5f, 0.2f}));
  EXPECT_TRUE(vec3_near(glm::vec3(0.0f, 1.5f, 0.0f), translation(box)));

  const gs::SpotLight &light = scene.lights[0];
  EXPECT_TRUE(vec3_near(glm::vec3(0.0f, 6.0f, 0.0f), light.position));  // straight above the box
  EXPECT_TRUE(vec3_near(glm::vec3(0.0f), light.target));
  EXPECT_FLOAT_EQ(light.cone_degrees, 60.0f);
  EXPECT_FLOAT_EQ(light.shadow_strength, 0.667f);
  EXPECT_EQ(light.shadow_size, 256);
}

TEST(SceneFile, FightersLoads) {
  const gs::Scene scene = load_or_fail(kSourceDir + "/scenes/fighters.json");
  ASSERT_EQ(scene.objects.size(), 3u);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_TRUE(vec3_near(glm::vec3(3.5f, 3.0f, 5.117f), scene.camera.position));
  EXPECT_TRUE(vec3_near(glm::vec3(0.0f, 1.55f, 0.0f), scene.camera.target));
  EXPECT_FLOAT_EQ(scene.camera.fov_degrees, 50.0f);

  const gs::SceneObject &ring = scene.objects[0];
  EXPECT_EQ(ring.name, "ring");
  EXPECT_GE(ring.mesh.triangle_count(), 2000u);  // ring.h: at least 2,000
  EXPECT_FALSE(ring.casts_shadow);
  EXPECT_TRUE(ring.shadow_mesh.positions.empty());

  for (std::size_t i : {1u, 2u}) {
    const gs::SceneObject &fighter = scene.objects[i];
    EXPECT_TRUE(fighter.casts_shadow) << fighter.name;
    // One mesh, drawn and casting: a simplified caster's shadow lies off the true one.
    EXPECT_GT(fighter.mesh.triangle_count(), 1000u) << fighter.name;
    EXPECT_TRUE(fighter.shadow_mesh.triangles.empty()) << fighter.name;
  }
  EXPECT_EQ(scene.objects[1].name, "red fighter");
  EXPECT_EQ(scene.objects[2].name, "blue fighter");
  // The fighters face each other: model +z turns to +x on the left, to -x on the right.
  EXPECT_TRUE(vec3_near(glm::vec3(-0.85f, 0.984f, 0.0f), translation(scene.objects[1])));
  EXPECT_TRUE(vec3_near(glm::vec3(0.15f, 0.984f, 0.0f), world_point(scene.objects[1], {0, 0, 1})));
  EXPECT_TRUE(vec3_near(glm::vec3(-0.15f, 0.98f, 0.0f), world_point(scene.objects[2], {0, 0, 1})));
}

TEST(SceneFile, ReceiverBetweenLoads) {
  const gs::Scene scene = load_or_fail(kSourceDir + "/scenes/receiver_between.json");
  ASSERT_EQ(scene.objects.size(), 3u);
  ASSERT_EQ(scene.lights.size(), 1u);
  const gs::SceneObject &caster = scene.objects[1];
  const gs::SceneObject &panel = scene.objects[2];
  EXPECT_EQ(caster.name, "caster");
  EXPECT_EQ(panel.name, "panel");
  EXPECT_TRUE(caster.casts_shadow);
  EXPECT_FALSE(panel.casts_shadow);
  EXPECT_TRUE(panel.receives_shadow);
  // World y: the panel lies between the caster and the light.
  EXPECT_GT(translation(panel).y, translation(caster).y);
  EXPECT_LT(translation(panel).y, scene.lights[0].position.y);
}

TEST(SceneFile, ObjMeshLoadsRelativeToTheSceneFile) {
  const gs::Scene scene = load_or_fail(kSourceDir + "/scenes/obj_mesh.json");
  ASSERT_EQ(scene.objects.size(), 2u);
  ASSERT_EQ(scene.lights.size(), 1u);
  const gs::SceneObject &tetrahedron = scene.objects[1];
  EXPECT_EQ(tetrahedron.name, "tetrahedron");
  EXPECT_EQ(tetrahedron.mesh.triangle_count(), 4u);
  EXPECT_TRUE(all_colors_are(tetrahedron.mesh, {0.3f, 0.7f, 0.3f}));
}

// ---- fields ----------------------------------------------------------------------------------

TEST(SceneFile, OmittedFieldsTakeTheirDocumentedDefaults) {
  const gs::Scene scene =
      load_or_fail(write_scene("defaults.json", one_object_scene(R"({"mesh": {"shape": "box"}})")));
  const gs::Scene defaults;
  EXPECT_EQ(scene.width, 640);
  EXPECT_EQ(scene.height, 480);
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_TRUE(vec3_near(defaults.ambient, scene.ambient));
  EXPECT_TRUE(vec3_near(defaults.background, scene.background));
  EXPECT_TRUE(vec3_near(glm::vec3(0.0f, 1.0f, 0.0f), scene.camera.up));
  EXPECT_FLOAT_EQ(scene.camera.fov_degrees, 50.0f);
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].name, "objects[0]");
  EXPECT_TRUE(scene.objects[0].casts_shadow);
  EXPECT_TRUE(scene.objects[0].receives_shadow);
  EXPECT_EQ(scene.objects[0].model_to_world, glm::mat4(1.0f));
  EXPECT_TRUE(all_colors_are(scene.objects[0].mesh, glm::vec3(1.0f)));
}

// Scale, then rotation about x, then y, then z, then translation (docs/scene_format.md).
TEST(SceneFile, TransformComposesScaleRotateXYZTranslate) {
  const gs::Scene scene = load_or_fail(write_scene(
      "transform.json", one_object_scene(R"({"mesh": {"shape": "box"}, "scale": [2, 3, 4],
          "rotation_degrees": [90, 90, 90], "position": [10, 20, 30]})")));
  ASSERT_EQ(scene.objects.size(), 1u);
  // Model (0,1,0): scaled (0,3,0); about x (0,0,3); about y (3,0,0); about z (0,3,0).
  EXPECT_TRUE(vec3_near(glm::vec3(10.0f, 23.0f, 30.0f), world_point(scene.objects[0], {0, 1, 0})));
  // Model (1,0,0): scaled (2,0,0); about x unchanged; about y (0,0,-2); about z unchanged.
  EXPECT_TRUE(vec3_near(glm::vec3(10.0f, 20.0f, 28.0f), world_point(scene.objects[0], {1, 0, 0})));
}

TEST(SceneFile, ScalarScaleIsUniform) {
  const gs::Scene scene = load_or_fail(write_scene(
      "uniform_scale.json", one_object_scene(R"({"mesh": {"shape": "box"}, "scale": 2.5})")));
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_TRUE(vec3_near(glm::vec3(2.5f, -5.0f, 7.5f), world_point(scene.objects[0], {1, -2, 3})));
}

// height(x, z) = amplitude * sin(2 pi x / wavelength) * cos(2 pi z / wavelength), model space.
TEST(SceneFile, HeightfieldFollowsTheDocumentedHeightFunction) {
  const gs::Scene scene = load_or_fail(write_scene(
      "heightfield.json", one_object_scene(R"({"mesh": {"shape": "heightfield", "size": 4,
          "divisions": 8, "amplitude": 0.5, "wavelength": 3}})")));
  ASSERT_EQ(scene.objects.size(), 1u);
  const gs::Mesh &mesh = scene.objects[0].mesh;
  ASSERT_FALSE(mesh.positions.empty());
  const float k = glm::two_pi<float>() / 3.0f;
  float highest = 0.0f;
  for (const glm::vec3 &p : mesh.positions) {
    EXPECT_NEAR(p.y, 0.5f * std::sin(k * p.x) * std::cos(k * p.z), kTolerance)
        << "at x " << p.x << ", z " << p.z;
    highest = std::max(highest, std::abs(p.y));
  }
  EXPECT_GT(highest, 0.1f);  // the grid samples the relief, not only its zeros
}

TEST(SceneFile, ColorReplacesAFightersOwnColours) {
  const gs::Scene scene = load_or_fail(write_scene(
      "fighter_color.json",
      one_object_scene(R"({"mesh": {"shape": "fighter", "pose": "kick"}, "color": [0, 1, 0]})")));
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_TRUE(all_colors_are(scene.objects[0].mesh, {0.0f, 1.0f, 0.0f}));
}

// ---- refused files ---------------------------------------------------------------------------

struct BadScene {
  const char *file;       // in tests/data/bad_scenes
  const char *json_path;  // of the broken field; empty when the file as a whole is wrong
  const char *problem;    // a fragment of the message after the path
};

void PrintTo(const BadScene &bad, std::ostream *out) { *out << bad.file; }

const BadScene kBadScenes[] = {
    {"unknown_shape.json", "objects[1].mesh.shape",
     "unknown shape 'cube' (expected box, sphere, plane, heightfield, cylinder, fighter, ring or "
     "an obj path)"},
    {"cone_too_wide.json", "lights[0].cone_degrees", "must be a number in (0, 179]"},
    {"screen_width_too_large.json", "screen.width", "must be an integer in 1..2048"},
    {"screen_height_is_string.json", "screen.height", "must be an integer in 1..2048"},
    {"missing_camera.json", "camera", "required field is missing"},
    {"missing_objects.json", "objects", "required field is missing"},
    {"empty_objects.json", "objects", "at least one object"},
    {"casts_shadow_not_boolean.json", "objects[0].casts_shadow", "must be true or false"},
    {"negative_box_size.json", "objects[0].mesh.size[1]", "must be a number > 0"},
    {"shadow_size_not_power_of_two.json", "lights[0].shadow_size",
     "must be a power of two in 32..512"},
    {"shadow_size_too_large.json", "lights[0].shadow_size", "must be a power of two in 32..512"},
    {"unknown_top_level_key.json", "lihgts", "unknown field"},
    {"unknown_object_key.json", "objects[0].cast_shadow", "unknown field"},
    {"unknown_mesh_key.json", "objects[0].mesh.radius", "unknown field (expected shape or size)"},
    {"huge_divisions.json", "objects[0].mesh.divisions", "must be an integer in 1..1000"},
    {"too_many_triangles.json", "objects[2].mesh", "more than the limit of 2000000"},
    {"float_overflow.json", "objects[0].position[1]", "must be a finite number"},
    {"ambient_out_of_range.json", "ambient[0]", "must be a number in [0, 1]"},
    {"camera_position_two_numbers.json", "camera.position", "must be an array of 3 numbers"},
    {"camera_target_is_position.json", "camera.target", "must differ from camera.position"},
    {"camera_up_along_view.json", "camera.up", "parallel to the view direction"},
    {"camera_far_before_near.json", "camera.far", "must be greater than near"},
    {"light_without_target.json", "lights[0].target", "required field is missing"},
    {"lights_not_array.json", "lights", "must be an array"},
    {"shape_and_obj.json", "objects[0].mesh", "either \"shape\" or \"obj\""},
    {"mesh_without_shape.json", "objects[0].mesh", "needs a \"shape\" or an \"obj\" path"},
    {"missing_obj_file.json", "objects[0].mesh.obj", "no_such_mesh.obj"},
    {"unknown_pose.json", "objects[0].mesh.pose", "unknown pose 'jump'"},
    {"phase_out_of_range.json", "objects[0].mesh.phase", "must be a number in [0, 1]"},
    {"fighter_color_and_body_color.json", "objects[0].color", "body_color or color, not both"},
    {"zero_scale.json", "objects[0].scale", "must be a number > 0"},
    {"duplicate_key.json", "objects[0].color", "field given twice"},
    {"duplicate_name.json", "objects[1].name", "'box' is already the name of objects[0]"},
    {"top_level_array.json", "", "must hold a JSON object"},
    {"malformed_trailing_comma.json", "", "malformed JSON: parse error at line 3, column"},
    {"nan_literal.json", "", "malformed JSON: parse error at line 3, column"},
    {"unknown_beam.json", "lights[0].beam",
     "must be one of the built-in patterns (round, square, gobo, lens) or an image file's path"},
    {"exact_without_beam.json", "lights[0].attenuation.mode", "\"exact\" needs a beam map"},
    {"two_exact_lights.json", "lights[1].attenuation.mode",
     "\"exact\" is already used by lights[0]: one light per scene"},
    {"slide_and_beam.json", "lights[0].beam", "give slide or beam"},
    {"attenuation_all_zero.json", "lights[0].attenuation", "all 0"},
    {"attenuation_unknown_mode.json", "lights[0].attenuation.mode",
     "must be \"none\", \"vertex\" or \"exact\""},
    {"missing_beam_image.json", "lights[0].beam", "no_such_beam.png: cannot read the image"},
    // The second audit (issue 14): values tinyobjloader read as 0 or infinity without a word,
    // and world coordinates that reached the shim as NaN or infinity while render exited 0.
    {"obj_nan_vertex.json", "objects[0].mesh.obj",
     "nan_vertex.obj: line 4: 'nan' is not a number finite as a 32-bit float"},
    {"obj_float_overflow_vertex.json", "objects[0].mesh.obj",
     "float_overflow_vertex.obj: line 3: '1e39' is not a number finite"},
    {"obj_comma_normal.json", "objects[0].mesh.obj", "comma_normal.obj: line 5: '0,5' is not a number"},
    {"scale_beyond_world.json", "objects[0]", "beyond 1e7 m from the origin (the limit)"},
    {"position_beyond_world.json", "objects[0]", "beyond 1e7 m from the origin (the limit)"},
    {"heightfield_not_finite.json", "objects[0]", "not a finite number"},
    {"light_beyond_world.json", "lights[0].position[1]", "must be a number in [-1e7, 1e7]"},
    {"camera_target_beyond_world.json", "camera.target[0]", "must be a number in [-1e7, 1e7]"},
};

class BadSceneFile : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneFile, IsRefusedNamingTheFieldsJsonPath) {
  const BadScene &bad = GetParam();
  const std::string path = kBadScenesDir + "/" + bad.file;
  gs::Scene scene;
  std::string error;
  ASSERT_FALSE(gs::load_scene(path, scene, error));
  const std::string prefix =
      path + ": " + (*bad.json_path ? std::string(bad.json_path) + ": " : "");
  EXPECT_EQ(error.rfind(prefix, 0), 0u) << "message: " << error << "\nexpected prefix: " << prefix;
  EXPECT_NE(error.find(bad.problem, prefix.size()), std::string::npos)
      << "message: " << error << "\nexpected to contain: " << bad.problem;
}

INSTANTIATE_TEST_SUITE_P(SceneFile, BadSceneFile, ::testing::ValuesIn(kBadScenes),
                         [](const ::testing::TestParamInfo<BadScene> &param) {
                           const std::string file = param.param.file;
                           return file.substr(0, file.find('.'));  // without ".json"
                         });

// A broken file added to tests/data/bad_scenes without an entry above would test nothing.
TEST(SceneFile, EveryBadSceneFileHasAnExpectedMessage) {
  std::set<std::string> listed;
  for (const BadScene &bad : kBadScenes) listed.insert(bad.file);
  std::set<std::string> on_disk;
  for (const auto &entry : std::filesystem::directory_iterator(kBadScenesDir))
    on_disk.insert(entry.path().filename().string());
  EXPECT_EQ(listed, on_disk);
}

TEST(SceneFile, SpotlightBeamsAndAttenuationLoad) {
  const gs::Scene scene = load_or_fail(kSourceDir + "/scenes/spotlight.json");
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].beam, "gobo");
  EXPECT_EQ(scene.lights[0].beam_image, nullptr);
  EXPECT_EQ(scene.lights[0].attenuation.mode, gs::AttenuationMode::PerPixel);
  EXPECT_FLOAT_EQ(scene.lights[0].attenuation.constant, 0.2f);
  EXPECT_FLOAT_EQ(scene.lights[0].attenuation.linear, 0.0f);
  EXPECT_FLOAT_EQ(scene.lights[0].attenuation.quadratic, 0.03f);
}

TEST(SceneFile, BeamAndSlideImagesLoadRelativeToTheSceneFile) {
  // tests/data/beam_gradient.png: 16 x 16, white at the top row fading to black at the bottom.
  // The scene in a scratch directory beside a copy of the image: a path relative to the scene.
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "image_lights";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(std::string(GLIDESHADOWS_TEST_DATA_DIR) + "/beam_gradient.png",
                             dir / "beam_gradient.png",
                             std::filesystem::copy_options::overwrite_existing);
  const std::string path = (dir / "scene.json").string();
  std::ofstream(path) << R"({"camera": {"position": [0, 2, 5], "target": [0, 0, 0]},
    "lights": [{"position": [0, 5, 0], "target": [0, 0, 0], "beam": "beam_gradient.png"},
               {"position": [0, 5, 1], "target": [0, 0, 0], "slide": "beam_gradient.png"}],
    "objects": [{"mesh": {"shape": "box"}}]})";
  const gs::Scene scene = load_or_fail(path);
  ASSERT_EQ(scene.lights.size(), 2u);
  ASSERT_NE(scene.lights[0].beam_image, nullptr);
  ASSERT_NE(scene.lights[1].slide_image, nullptr);
  const gs::ProjectedImage &image = *scene.lights[0].beam_image;
  ASSERT_EQ(image.side, 128);
  EXPECT_GT(image.rgb[0].r, 0.9f);                      // top row: white
  EXPECT_LT(image.rgb[127 * 128].r, 0.1f);              // bottom row: black
  EXPECT_GT(image.rgb[64 * 128].r, image.rgb[96 * 128].r);  // fading downwards
}

TEST(SceneFile, FailedLoadLeavesTheSceneUnchanged) {
  gs::Scene scene = load_or_fail(kSourceDir + "/scenes/box_on_plane.json");
  ASSERT_EQ(scene.objects.size(), 2u);
  scene.width = 123;
  std::string error;
  // duplicate_name.json fails only after its camera, light and first object were read.
  ASSERT_FALSE(gs::load_scene(kBadScenesDir + "/duplicate_name.json", scene, error));
  EXPECT_EQ(scene.width, 123);
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(scene.objects[0].name, "floor");
  EXPECT_EQ(scene.objects[1].name, "box");
  EXPECT_TRUE(vec3_near(glm::vec3(0.0f, 3.0f, 6.0f), scene.camera.position));
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_TRUE(vec3_near(glm::vec3(0.0f, 6.0f, 0.0f), scene.lights[0].position));
}

TEST(SceneFile, MissingFileIsNamedInTheMessage) {
  const std::string path = kSourceDir + "/scenes/no_such_scene.json";
  gs::Scene scene;
  std::string error;
  ASSERT_FALSE(gs::load_scene(path, scene, error));
  EXPECT_EQ(error.rfind(path + ": cannot open", 0), 0u) << error;
}

TEST(SceneFile, MalformedJsonNamesTheFileLineAndColumn) {
  const std::string path =
      write_scene("malformed.json", "{\n  \"camera\": {\n    \"position\" [0, 1, 2]\n");
  gs::Scene scene;
  std::string error;
  ASSERT_FALSE(gs::load_scene(path, scene, error));
  EXPECT_EQ(error.rfind(path + ": malformed JSON: ", 0), 0u) << error;
  EXPECT_NE(error.find("line 3, column 16"), std::string::npos) << error;
}

}  // namespace

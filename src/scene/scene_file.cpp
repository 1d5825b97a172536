// The JSON scene-file reader behind load_scene (format: docs/scene_format.md). Every field is
// checked against its documented type and range; the first problem ends the load with a message
// naming the file and the field's JSON path, and nothing reaches the caller's Scene.
#include "scene/fighter.h"
#include "scene/scene_json.h"
#include "scene/input_file.h"
#include "scene/projected_image_file.h"
#include "scene/ring.h"
#include "scene/scene.h"
#include "scene/slides.h"
#include "scene/spotlight.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <set>
#include <utility>

namespace gs {
namespace {

using namespace scene_json;

// The scene's triangle budget, shadow meshes included: enough for a 1000 x 1000 plane, and far
// below what would exhaust memory or stall a frame for minutes.
constexpr std::size_t kMaxSceneTriangles = 2'000'000;
constexpr unsigned kMaxDivisions = 1000;  // plane, heightfield: 2 * 1000^2 triangles
constexpr unsigned kMaxSlices = 1000;     // sphere, cylinder
constexpr unsigned kMaxStacks = 1000;     // sphere: 2 * 1000 * 1000 triangles at most
constexpr unsigned kMaxScreenSide = 2048;
constexpr std::size_t kMaxLights = 16;  // each light is at least one more pass over the scene
constexpr int kProjectedImageSide = 128;  // slides and beams from files: 128 x 128 texels

// ---- scene parts -----------------------------------------------------------------------------

void read_screen(const Field &f, Scene &scene) {
  f.require_object_with_keys({"width", "height"});
  if (f.has("width")) scene.width = integer(f["width"], 1, kMaxScreenSide);
  if (f.has("height")) scene.height = integer(f["height"], 1, kMaxScreenSide);
}

// A camera or spotlight must look somewhere: its target differs from its position.
void check_aim(const Field &f, const glm::vec3 &from, const glm::vec3 &to, const char *what) {
  if (glm::length(to - from) <= 0.0f) f["target"].fail(std::string("must differ from ") + what);
}

void read_camera(const Field &f, Camera &camera) {
  f.require_object_with_keys({"position", "target", "up", "fov_degrees", "near", "far"});
  camera.position = world_point(f["position"]);
  camera.target = world_point(f["target"]);
  check_aim(f, camera.position, camera.target, "camera.position");
  if (f.has("up")) camera.up = position(f["up"]);
  // World space; a zero up, or one along the view, leaves the camera's roll undefined.
  const glm::vec3 view = glm::normalize(camera.target - camera.position);
  if (!(glm::length(glm::cross(view, camera.up)) > 1e-6f * glm::length(camera.up))) {
    if (f.has("up")) f["up"].fail("must not be zero or parallel to the view direction");
    f["target"].fail("the view is vertical, parallel to the default up [0, 1, 0]: give \"up\"");
  }
  if (f.has("fov_degrees"))
    camera.fov_degrees = number(f["fov_degrees"], "a number in (0, 180)",
                                [](float v) { return v > 0.0f && v < 180.0f; });
  if (f.has("near")) camera.near_plane = number(f["near"], "a number > 0", positive);
  if (f.has("far")) camera.far_plane = number(f["far"], "a number > 0", positive);
  if (!(camera.far_plane > camera.near_plane)) {
    if (f.has("far")) f["far"].fail("must be greater than near");
    f["near"].fail("must be less than far");
  }
}

// A slide or beam: a built-in pattern's name, or an image file relative to the scene file.
std::shared_ptr<const ProjectedImage> read_light_image(const Field &f, bool (*is_pattern)(const std::string &),
                                                       const char *patterns,
                                                       const std::filesystem::path &scene_dir,
                                                       std::string &name) {
  name = text(f);
  if (is_pattern(name)) return nullptr;
  if (name.empty() || std::filesystem::path(name).extension().empty())
    f.fail(std::string("must be one of the built-in patterns (") + patterns +
           ") or an image file's path");
  const std::string path = (scene_dir / name).lexically_normal().string();
  auto image = std::make_shared<ProjectedImage>();
  std::string error;
  if (!load_projected_image(path, kProjectedImageSide, *image, error)) f.fail(error);
  return image;
}

DistanceAttenuation read_attenuation(const Field &f) {
  f.require_object_with_keys({"mode", "constant", "linear", "quadratic"});
  DistanceAttenuation attenuation;
  const std::string mode = text(f["mode"]);
  if (mode == "vertex") {
    attenuation.mode = AttenuationMode::PerVertex;
  } else if (mode == "exact") {
    attenuation.mode = AttenuationMode::PerPixel;
  } else if (mode == "none") {
    attenuation.mode = AttenuationMode::None;
  } else {
    f["mode"].fail("must be \"none\", \"vertex\" or \"exact\"");
  }
  auto non_negative = [](float v) { return v >= 0.0f; };
  if (f.has("constant")) attenuation.constant = number(f["constant"], "a number >= 0", non_negative);
  if (f.has("linear")) attenuation.linear = number(f["linear"], "a number >= 0", non_negative);
  if (f.has("quadratic"))
    attenuation.quadratic = number(f["quadratic"], "a number >= 0", non_negative);
  if (!(attenuation.constant > 0.0f) && !(attenuation.linear > 0.0f) &&
      !(attenuation.quadratic > 0.0f))
    f.fail("constant, linear and quadratic are all 0: the light would be infinitely bright");
  return attenuation;
}

SpotLight read_light(const Field &f, const std::filesystem::path &scene_dir) {
  f.require_object_with_keys({"position", "target", "cone_degrees", "color", "shadow_strength",
                              "shadow_size", "slide", "beam", "attenuation"});
  SpotLight light;
  light.position = world_point(f["position"]);
  light.target = world_point(f["target"]);
  check_aim(f, light.position, light.target, "the light's position");
  if (f.has("cone_degrees"))
    light.cone_degrees = number(f["cone_degrees"], "a number in (0, 179]",
                                [](float v) { return v > 0.0f && v <= 179.0f; });
  if (f.has("color")) light.color = color(f["color"]);
  if (f.has("shadow_strength"))
    light.shadow_strength = number(f["shadow_strength"], "a number in [0, 1]", unit_interval);
  if (f.has("shadow_size")) {
    const Field size = f["shadow_size"];
    const bool is_integer = size.value.is_number_unsigned();
    const std::uint64_t v = is_integer ? size.value.get<std::uint64_t>() : 0;
    if (!is_integer || v < 32 || v > 512 || (v & (v - 1)) != 0)
      size.fail("must be a power of two in 32..512");
    light.shadow_size = static_cast<int>(v);
  }
  if (f.has("slide")) {
    if (f.has("beam")) f["beam"].fail("a slide projector has no beam map: give slide or beam");
    light.slide_image =
        read_light_image(f["slide"], is_slide_pattern, "checker, rings, grid", scene_dir, light.slide);
  }
  if (f.has("beam"))
    light.beam_image =
        read_light_image(f["beam"], is_beam_pattern, "round, square, gobo, lens", scene_dir, light.beam);
  if (f.has("attenuation")) light.attenuation = read_attenuation(f["attenuation"]);
  if (light.attenuation.mode == AttenuationMode::PerPixel && !light.has_beam_map())
    f["attenuation"]["mode"].fail("\"exact\" needs a beam map: give \"beam\" (or use \"vertex\")");
  return light;
}


// Counts the triangles of the scene so far against kMaxSceneTriangles.
// Shapes with a size parameter are checked before they are built, so an absurd request
// allocates nothing; every mesh is counted once built.
class TriangleBudget {
 public:
  // Fails at `where`, the mesh field, if `triangles` more would take the scene over the limit.
  void check(const Field &where, std::size_t triangles) const {
    if (triangles > kMaxSceneTriangles - used_)
      where.fail("the scene would have " + std::to_string(used_ + triangles) +
                 " triangles, more than the limit of " + std::to_string(kMaxSceneTriangles));
  }
  void spend(const Field &where, std::size_t triangles) {
    check(where, triangles);
    used_ += triangles;
  }

 private:
  std::size_t used_ = 0;
};

// The shape's mesh, model space, before its colour and transform are applied.
Mesh read_shape(const Field &f, const std::string &shape, TriangleBudget &budget) {
  Mesh out;
  if (shape == "box") {
    f.require_object_with_keys({"shape", "size"});
    const glm::vec3 size =
        f.has("size") ? vec3(f["size"], "a number > 0", positive) : glm::vec3(1.0f);
    out = make_box(0.5f * size);
  } else if (shape == "sphere") {
    f.require_object_with_keys({"shape", "radius", "slices", "stacks"});
    const float radius = f.has("radius") ? number(f["radius"], "a number > 0", positive) : 0.5f;
    const int slices = f.has("slices") ? integer(f["slices"], 3, kMaxSlices) : 24;
    const int stacks = f.has("stacks") ? integer(f["stacks"], 2, kMaxStacks) : 16;
    budget.check(f, 2 * static_cast<std::size_t>(slices) * static_cast<std::size_t>(stacks));
    out = make_sphere(radius, slices, stacks);
  } else if (shape == "plane" || shape == "heightfield") {
    const bool relief = shape == "heightfield";
    if (relief)
      f.require_object_with_keys({"shape", "size", "divisions", "amplitude", "wavelength"});
    else
      f.require_object_with_keys({"shape", "size", "divisions"});
    const float size = f.has("size") ? number(f["size"], "a number > 0", positive) : 10.0f;
    const int divisions =
        f.has("divisions") ? integer(f["divisions"], 1, kMaxDivisions) : (relief ? 32 : 1);
    budget.check(f, 2 * static_cast<std::size_t>(divisions) * static_cast<std::size_t>(divisions));
    if (relief) {
      const float amplitude =
          f.has("amplitude") ? number(f["amplitude"], "a finite number", any_value) : 0.2f;
      const float wavelength =
          f.has("wavelength") ? number(f["wavelength"], "a number > 0", positive) : 4.0f;
      const float k = glm::two_pi<float>() / wavelength;  // radians per metre, model space
      out = make_heightfield(size, divisions, [amplitude, k](float x, float z) {
        return amplitude * std::sin(k * x) * std::cos(k * z);
      });
    } else {
      out = make_plane(size, divisions);
    }
  } else if (shape == "cylinder") {
    f.require_object_with_keys({"shape", "radius", "length", "slices", "caps"});
    const float radius = f.has("radius") ? number(f["radius"], "a number > 0", positive) : 0.5f;
    const float length = f.has("length") ? number(f["length"], "a number > 0", positive) : 1.0f;
    const int slices = f.has("slices") ? integer(f["slices"], 3, kMaxSlices) : 24;
    const bool caps = f.has("caps") ? boolean(f["caps"]) : true;
    budget.check(f, 4 * static_cast<std::size_t>(slices));
    out = make_cylinder(radius, length, slices, caps);
  } else if (shape == "fighter") {
    f.require_object_with_keys({"shape", "pose", "phase", "body_color"});
    Move move = Move::Guard;
    if (f.has("pose")) {
      const std::string name = text(f["pose"]);
      if (!move_from_name(name, move))
        f["pose"].fail("unknown pose '" + name + "' (expected guard, punch, kick, step or hit)");
    }
    const float phase =
        f.has("phase") ? number(f["phase"], "a number in [0, 1]", unit_interval) : 0.0f;
    const glm::vec3 body =  // default: the demo's red fighter
        f.has("body_color") ? color(f["body_color"]) : glm::vec3(0.75f, 0.12f, 0.1f);
    const FighterPose pose = pose_for(move, phase);
    out = build_fighter(pose, body);  // it casts from this mesh too (fight_scene.cpp says why)
  } else if (shape == "ring") {
    f.require_object_with_keys({"shape"});
    out = build_ring();
  } else {
    f["shape"].fail("unknown shape '" + shape +
                    "' (expected box, sphere, plane, heightfield, cylinder, fighter, ring or an "
                    "obj path)");
  }
  return out;
}

Mesh read_mesh(const Field &f, const std::filesystem::path &scene_dir, TriangleBudget &budget) {
  if (!f.value.is_object()) f.fail("must be an object");
  Mesh out;
  if (f.has("obj")) {
    if (f.has("shape")) f.fail("give either \"shape\" or \"obj\", not both");
    f.require_object_with_keys({"obj"});
    const Field obj = f["obj"];
    const std::string relative = text(obj);
    if (relative.empty()) obj.fail("must be a path to an OBJ file");
    // Relative to the scene file's directory, so a scene loads from any working directory.
    const std::string obj_path = (scene_dir / relative).lexically_normal().string();
    std::string obj_error;
    if (!load_obj(obj_path, out, obj_error)) obj.fail(obj_error);
  } else if (f.has("shape")) {
    out = read_shape(f, text(f["shape"]), budget);
  } else {
    f.fail("needs a \"shape\" or an \"obj\" path");
  }
  budget.spend(f, out.triangle_count());
  return out;
}

// Model to world: scale, then rotations about x, y and z (degrees), then translation.
glm::mat4 model_to_world(const glm::vec3 &scale, const glm::vec3 &rotation_degrees,
                         const glm::vec3 &translation) {
  const glm::vec3 r = glm::radians(rotation_degrees);
  glm::mat4 m = glm::translate(glm::mat4(1.0f), translation);
  m = glm::rotate(m, r.z, glm::vec3(0.0f, 0.0f, 1.0f));
  m = glm::rotate(m, r.y, glm::vec3(0.0f, 1.0f, 0.0f));
  m = glm::rotate(m, r.x, glm::vec3(1.0f, 0.0f, 0.0f));
  return glm::scale(m, scale);
}

// Fails at the object if a vertex of its mesh, placed in the world, is not finite (a heightfield
// whose wavelength is too short for a float, a huge scale) or lies beyond kMaxWorldCoordinate.
void check_world_extent(const Field &f, const SceneObject &object) {
  for (const glm::vec3 &model : object.mesh.positions) {
    const glm::vec3 world = glm::vec3(object.model_to_world * glm::vec4(model, 1.0f));
    const bool finite = std::isfinite(world.x) && std::isfinite(world.y) && std::isfinite(world.z);
    if (finite && glm::all(glm::lessThanEqual(glm::abs(world), glm::vec3(kMaxWorldCoordinate))))
      continue;
    char where[96];
    std::snprintf(where, sizeof where, "(%g, %g, %g)", world.x, world.y, world.z);
    f.fail(std::string("its mesh, placed in the world, has a vertex at ") + where +
           (finite ? ", beyond 1e7 m from the origin (the limit)" : ", not a finite number"));
  }
}

SceneObject read_object(const Field &f, const std::filesystem::path &scene_dir,
                        TriangleBudget &budget) {
  f.require_object_with_keys({"name", "mesh", "position", "rotation_degrees", "scale", "color",
                              "casts_shadow", "receives_shadow"});
  SceneObject object;
  object.name = f.has("name") ? text(f["name"]) : f.path;
  if (object.name.empty()) f["name"].fail("must not be empty");

  // The cheap fields first, so that a mistake in them is reported before any mesh is built.
  glm::vec3 scale(1.0f);
  if (f.has("scale")) {
    const Field s = f["scale"];
    scale = s.value.is_array()
                ? vec3(s, "a number > 0", positive)
                : glm::vec3(number(s, "a number > 0 or an array of 3 such numbers", positive));
  }
  const glm::vec3 rotation =
      f.has("rotation_degrees") ? position(f["rotation_degrees"]) : glm::vec3(0.0f);
  const glm::vec3 translation = f.has("position") ? position(f["position"]) : glm::vec3(0.0f);
  object.model_to_world = model_to_world(scale, rotation, translation);
  if (f.has("casts_shadow")) object.casts_shadow = boolean(f["casts_shadow"]);
  if (f.has("receives_shadow")) object.receives_shadow = boolean(f["receives_shadow"]);
  const bool recolor = f.has("color");
  const glm::vec3 new_color = recolor ? color(f["color"]) : glm::vec3(1.0f);
  if (recolor && f["mesh"].value.contains("body_color"))  // only fighters accept body_color
    f["color"].fail("a fighter takes body_color or color, not both");

  object.mesh = read_mesh(f["mesh"], scene_dir, budget);
  if (recolor) object.mesh.set_color(new_color);
  check_world_extent(f, object);
  return object;
}

// The Glide renderer forms a per-pixel attenuated spotlight in the frame's cleared accumulation
// (one texture unit cannot sample beam and attenuation at once), so only one light can have it.
void check_one_exact_attenuation(const Field &lights, const std::vector<SpotLight> &read) {
  std::size_t first = read.size();
  for (std::size_t i = 0; i < read.size(); ++i) {
    if (read[i].attenuation.mode != AttenuationMode::PerPixel) continue;
    if (first == read.size()) {
      first = i;
      continue;
    }
    lights.item(i)["attenuation"]["mode"].fail(
        "\"exact\" is already used by " + lights.item(first).path +
        ": one light per scene can have exact attenuation (a Voodoo's single texture unit); use "
        "\"vertex\"");
  }
}

void read_scene(const json &document, const std::filesystem::path &scene_dir, Scene &scene) {
  const Field root{document, ""};
  if (!document.is_object()) root.fail("the file must hold a JSON object");
  root.require_object_with_keys(
      {"description", "screen", "camera", "ambient", "background", "lights", "objects"});
  if (root.has("description")) text(root["description"]);
  if (root.has("screen")) read_screen(root["screen"], scene);
  read_camera(root["camera"], scene.camera);
  if (root.has("ambient")) scene.ambient = color(root["ambient"]);
  if (root.has("background")) scene.background = color(root["background"]);

  if (root.has("lights")) {
    const Field lights = root["lights"];
    if (!lights.value.is_array()) lights.fail("must be an array");
    if (lights.value.size() > kMaxLights)
      lights.fail("has " + std::to_string(lights.value.size()) + " lights, more than the limit of " +
                  std::to_string(kMaxLights));
    for (std::size_t i = 0; i < lights.value.size(); ++i)
      scene.lights.push_back(read_light(lights.item(i), scene_dir));
    check_one_exact_attenuation(lights, scene.lights);
  }

  const Field objects = root["objects"];
  if (!objects.value.is_array() || objects.value.empty())
    objects.fail("must be an array of at least one object");
  TriangleBudget budget;
  std::map<std::string, std::string> names;  // object name -> JSON path of its first use
  for (std::size_t i = 0; i < objects.value.size(); ++i) {
    const Field f = objects.item(i);
    SceneObject object = read_object(f, scene_dir, budget);
    const auto inserted = names.emplace(object.name, f.path);
    if (!inserted.second)
      throw SceneError{f.child_path("name"),
                       "'" + object.name + "' is already the name of " + inserted.first->second};
    scene.objects.push_back(std::move(object));
  }
}

}  // namespace

bool load_scene(const std::string &path, Scene &scene, std::string &error) {
  try {
    Scene loaded;
    read_scene(parse_file(path), std::filesystem::path(path).parent_path(), loaded);
    scene = std::move(loaded);
    return true;
  } catch (const SceneError &e) {
    error = path + ": " + (e.where.empty() ? "" : e.where + ": ") + e.problem;
  } catch (const std::bad_alloc &) {
    error = path + ": out of memory while loading";
  } catch (const std::exception &e) {
    error = path + ": " + e.what();
  } catch (...) {
    error = path + ": unexpected error while loading";
  }
  return false;
}

}  // namespace gs

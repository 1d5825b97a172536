// Reading a JSON file field by field with the field's path for messages: the building blocks of
// the scene-file reader (scene_file.cpp). parse_file reads within a budget of size, nesting and
// values, so any file parses in bounded time and memory, and refuses a key given twice; the
// value readers check type and range. Problems are thrown as SceneError, inside the scene room
// only (load_scene catches them).
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>

namespace gs::scene_json {

using json = nlohmann::json;

// A problem in the file: the JSON path of the field ("objects[2].mesh.shape"; empty for the
// file as a whole) and what is wrong with it. Thrown inside this file only; load_scene catches it.
struct SceneError {
  std::string where;
  std::string problem;
};

// One value of the parsed document together with its JSON path, for messages.
struct Field {
  const json &value;
  std::string path;

  [[noreturn]] void fail(const std::string &problem) const { throw SceneError{path, problem}; }

  std::string child_path(const std::string &key) const {
    return path.empty() ? key : path + "." + key;
  }

  // Requires an object whose keys are all in `allowed`: a misspelt optional field must not be
  // silently ignored.
  void require_object_with_keys(std::initializer_list<const char *> allowed) const {
    if (!value.is_object()) fail("must be an object");
    for (const auto &item : value.items()) {
      bool known = false;
      for (const char *key : allowed) known = known || item.key() == key;
      if (known) continue;
      std::string expected;
      std::size_t index = 0;
      for (const char *key : allowed) {
        if (index > 0) expected += index + 1 == allowed.size() ? " or " : ", ";
        expected += key;
        ++index;
      }
      throw SceneError{child_path(item.key()), "unknown field (expected " + expected + ")"};
    }
  }

  bool has(const char *key) const { return value.contains(key); }

  Field operator[](const char *key) const {
    const auto found = value.find(key);
    if (found == value.end()) throw SceneError{child_path(key), "required field is missing"};
    return {*found, child_path(key)};
  }

  Field item(std::size_t index) const {
    return {value[index], path + "[" + std::to_string(index) + "]"};
  }
};

// The document in `path`, or SceneError naming what is wrong with the file.
json parse_file(const std::string &path);

// Value readers: each checks type and range, and fails naming what the field must be.
bool any_value(float);
bool positive(float v);
bool unit_interval(float v);
// A JSON number within float range (1e39 is a valid double but not a float) that passes
// `accept`; `expected` completes "must be ...".
float number(const Field &f, const char *expected, bool (*accept)(float));
// A non-negative JSON integer in [lo, hi]; 640.0 is a float in JSON and is refused like 640.5.
int integer(const Field &f, unsigned lo, unsigned hi);
bool boolean(const Field &f);
std::string text(const Field &f);
glm::vec3 vec3(const Field &f, const char *element, bool (*accept)(float));
glm::vec3 position(const Field &f);  // three finite numbers
// The largest distance from the origin along any axis, metres, of any point of a scene: the
// camera, the lights, every vertex in the world. A float there still resolves a metre, and the
// renderers' products of coordinates stay far inside float range.
constexpr float kMaxWorldCoordinate = 1e7f;
glm::vec3 world_point(const Field &f);  // three numbers in [-kMaxWorldCoordinate, kMaxWorldCoordinate]
glm::vec3 color(const Field &f);     // three numbers in [0, 1]

}  // namespace gs::scene_json

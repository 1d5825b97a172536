// The field-by-field JSON reading of scene_json.h: the budgeted two-pass parse (a counting pass
// that keeps nothing, then nlohmann's parse with a duplicate-key check) and the value readers.
#include "scene/scene_json.h"

#include "scene/input_file.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <utility>

namespace gs::scene_json {
namespace {

constexpr std::size_t kMaxSceneFileBytes = 16u << 20;  // far above any hand-written scene
// The parse's budget, checked while reading (before any value is kept), so that any file under
// the size limit parses in bounded time and memory: a scene nests 5 levels and holds a few
// thousand values (meshes are shapes or OBJ files, never inline arrays).
constexpr std::size_t kMaxJsonDepth = 32;
constexpr std::size_t kMaxJsonValues = 100'000;

// nlohmann keeps the last of two equal keys; a field given twice is a mistake like a misspelt
// one, so the parse callback follows the JSON path and remembers the first repeated key.
class DuplicateKeyFinder {
 public:
  std::string first_duplicate;  // its JSON path; empty if every object's keys are distinct

  bool operator()(int, json::parse_event_t event, const json &parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
        frames_.push_back({false, 0, {}, {}});
        break;
      case json::parse_event_t::array_start:
        frames_.push_back({true, 0, {}, {}});
        break;
      case json::parse_event_t::key:
        frames_.back().key = parsed.get<std::string>();
        if (!frames_.back().keys.insert(frames_.back().key).second && first_duplicate.empty())
          first_duplicate = path();
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames_.pop_back();
        element_done();
        break;
      case json::parse_event_t::value:
        element_done();
        break;
    }
    return true;  // keep every value
  }

 private:
  struct Frame {
    bool array;
    std::size_t index;  // array: the element being read
    std::string key;    // object: the member being read
    std::set<std::string> keys;
  };
  std::vector<Frame> frames_;

  void element_done() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
  }
  std::string path() const {
    std::string result;
    for (const Frame &frame : frames_) {
      if (frame.array)
        result += "[" + std::to_string(frame.index) + "]";
      else
        result += (result.empty() ? "" : ".") + frame.key;
    }
    return result;
  }
};

// A first pass over the text that keeps nothing: it counts nesting and values and stops at the
// first one over the budget. Syntax errors are left to the second pass, which names them; up to
// one, that pass reads no more values than this one did.
class BudgetCheck : public nlohmann::json_sax<json> {
 public:
  std::string problem;  // empty: within the budget

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t &) override { return value(); }
  bool string(string_t &) override { return value(); }
  bool binary(binary_t &) override { return value(); }
  bool key(string_t &) override { return value(); }
  bool start_object(std::size_t) override { return open(); }
  bool start_array(std::size_t) override { return open(); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string &, const nlohmann::detail::exception &) override {
    return false;
  }

 private:
  std::size_t depth_ = 0, values_ = 0;
  bool value() {
    if (++values_ <= kMaxJsonValues) return true;
    problem = "more than " + std::to_string(kMaxJsonValues) +
              " JSON values (keys, numbers, strings, arrays and objects), the limit";
    return false;
  }
  bool open() {
    if (++depth_ > kMaxJsonDepth) {
      problem = "arrays and objects nested more than " + std::to_string(kMaxJsonDepth) +
                " deep, the limit";
      return false;
    }
    return value();
  }
  bool close() {
    --depth_;
    return true;
  }
};

}  // namespace

json parse_file(const std::string &path) {
  std::string contents, error;
  if (!read_input_file(path, kMaxSceneFileBytes, contents, error)) throw SceneError{{}, error};
  BudgetCheck budget;
  json::sax_parse(contents, &budget);
  if (!budget.problem.empty()) throw SceneError{{}, budget.problem};
  DuplicateKeyFinder duplicates;
  json document;
  try {
    document = json::parse(contents, std::ref(duplicates));
  } catch (const json::exception &e) {
    // what() is "[json.exception.parse_error.101] parse error at line 3, column 5: ...".
    const std::string what = e.what();
    const std::size_t tag_end = what.find("] ");
    throw SceneError{
        {}, "malformed JSON: " + (tag_end == std::string::npos ? what : what.substr(tag_end + 2))};
  }
  if (!duplicates.first_duplicate.empty())
    throw SceneError{duplicates.first_duplicate, "field given twice"};
  return document;
}

bool any_value(float) { return true; }
bool positive(float v) { return v > 0.0f; }
bool unit_interval(float v) { return v >= 0.0f && v <= 1.0f; }

float number(const Field &f, const char *expected, bool (*accept)(float)) {
  if (f.value.is_number()) {
    const double v = f.value.get<double>();
    if (std::abs(v) <= std::numeric_limits<float>::max() && accept(static_cast<float>(v)))
      return static_cast<float>(v);
  }
  f.fail(std::string("must be ") + expected);
}

// Every integer field is positive, so only non-negative JSON integers (nlohmann stores those as
// unsigned) can be in range; 640.0 is a float in JSON and is refused like 640.5.
int integer(const Field &f, unsigned lo, unsigned hi) {
  if (f.value.is_number_unsigned()) {
    const std::uint64_t v = f.value.get<std::uint64_t>();
    if (v >= lo && v <= hi) return static_cast<int>(v);
  }
  f.fail("must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
}

bool boolean(const Field &f) {
  if (!f.value.is_boolean()) f.fail("must be true or false");
  return f.value.get<bool>();
}

std::string text(const Field &f) {
  if (!f.value.is_string()) f.fail("must be a string");
  return f.value.get<std::string>();
}

glm::vec3 vec3(const Field &f, const char *element, bool (*accept)(float)) {
  if (!f.value.is_array() || f.value.size() != 3) f.fail("must be an array of 3 numbers");
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = number(f.item(static_cast<std::size_t>(i)), element, accept);
  return v;
}

glm::vec3 position(const Field &f) { return vec3(f, "a finite number", any_value); }
glm::vec3 world_point(const Field &f) {
  return vec3(f, "a number in [-1e7, 1e7] (metres: a scene lies within 10,000 km of the origin)",
              [](float v) { return std::abs(v) <= kMaxWorldCoordinate; });
}
glm::vec3 color(const Field &f) { return vec3(f, "a number in [0, 1]", unit_interval); }

}  // namespace gs::scene_json

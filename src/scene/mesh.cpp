// Triangle meshes: appending under a transform, the built-in shapes (box, sphere, cylinder, plane,
// heightfield) and the OBJ loader (tinyobjloader). All positions and normals are model space;
// every shape winds counter-clockwise seen from outside and closed shapes share no open edge.
#include "scene/mesh.h"

#include "scene/input_file.h"

#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <glm/gtc/constants.hpp>
#include <map>
#include <sstream>
#include <utility>

namespace gs {
namespace {

// An OBJ file's limits: 256 MiB of text holds a few million faces; the triangle limit is the
// scene's whole budget (scene_file.cpp), so no single mesh can ask for more than a scene may hold.
constexpr std::size_t kMaxObjFileBytes = 256u << 20;
constexpr std::size_t kMaxObjTriangles = 2'000'000;

const glm::vec3 kWhite(1.0f);
const glm::vec3 kUp(0.0f, 1.0f, 0.0f);

// A unit vector along `v`; straight up when `v` has no direction (a degenerate normal).
glm::vec3 unit_or_up(const glm::vec3 &v) {
  const float length = glm::length(v);
  return length > 0.0f && std::isfinite(length) ? v / length : kUp;
}

std::uint32_t add_vertex(Mesh &mesh, const glm::vec3 &position, const glm::vec3 &normal) {
  mesh.positions.push_back(position);
  mesh.normals.push_back(normal);
  mesh.colors.push_back(kWhite);
  return static_cast<std::uint32_t>(mesh.positions.size() - 1);
}

void add_triangle(Mesh &mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  mesh.triangles.emplace_back(a, b, c);
}

// Direction around the y axis at `slice` of `slices`, in the xz plane (model space). Every
// ring of a shape takes its directions from here, so rings that meet share exact positions.
glm::vec3 around_y(int slice, int slices) {
  const float angle = glm::two_pi<float>() * static_cast<float>(slice) / static_cast<float>(slices);
  return {std::sin(angle), 0.0f, std::cos(angle)};
}

// A fan closing a ring of vertices around `centre`; `facing_up` picks the winding that faces +y.
void add_fan(Mesh &mesh, std::uint32_t centre, std::uint32_t first, int count, bool facing_up) {
  for (int j = 0; j < count; ++j) {
    const std::uint32_t a = first + static_cast<std::uint32_t>(j);
    const std::uint32_t b = first + static_cast<std::uint32_t>((j + 1) % count);
    if (facing_up)
      add_triangle(mesh, centre, a, b);
    else
      add_triangle(mesh, centre, b, a);
  }
}

// Quads between an upper and a lower ring of `count` vertices each, facing away from the y axis.
void add_band(Mesh &mesh, std::uint32_t upper, std::uint32_t lower, int count) {
  for (int j = 0; j < count; ++j) {
    const auto j0 = static_cast<std::uint32_t>(j);
    const auto j1 = static_cast<std::uint32_t>((j + 1) % count);
    add_triangle(mesh, upper + j0, lower + j0, lower + j1);
    add_triangle(mesh, upper + j0, lower + j1, upper + j1);
  }
}

std::string trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
    text.pop_back();
  return text;
}

}  // namespace

void Mesh::append(const Mesh &other, const glm::mat4 &model) {
  if (&other == this) {
    const Mesh copy = other;
    append(copy, model);
    return;
  }
  const glm::mat3 linear(model);
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
  // A mirroring transform turns counter-clockwise into clockwise; swapping two corners keeps
  // the triangles facing outside.
  const bool mirrors = glm::determinant(linear) < 0.0f;
  const auto first = static_cast<glm::uint>(positions.size());
  for (std::size_t i = 0; i < other.positions.size(); ++i) {
    positions.emplace_back(model * glm::vec4(other.positions[i], 1.0f));
    normals.push_back(unit_or_up(normal_matrix * other.normals[i]));
    colors.push_back(other.colors[i]);
  }
  for (const glm::uvec3 &triangle : other.triangles) {
    const glm::uvec3 shifted = triangle + glm::uvec3(first);
    triangles.push_back(mirrors ? glm::uvec3(shifted.x, shifted.z, shifted.y) : shifted);
  }
}

void Mesh::set_color(const glm::vec3 &color) { colors.assign(positions.size(), color); }

Mesh make_box(const glm::vec3 &half_extents) {
  const glm::vec3 half = glm::abs(half_extents);
  Mesh mesh;
  // Each face gets its own four corners so its normal stays flat; (u, v) span the face with
  // u x v = normal, which makes the corner order below counter-clockwise from outside.
  for (int axis = 0; axis < 3; ++axis) {
    for (const float sign : {1.0f, -1.0f}) {
      glm::vec3 normal(0.0f), u(0.0f), v(0.0f);
      normal[axis] = sign;
      u[(axis + (sign > 0.0f ? 1 : 2)) % 3] = 1.0f;
      v[(axis + (sign > 0.0f ? 2 : 1)) % 3] = 1.0f;
      const std::uint32_t first = add_vertex(mesh, (normal - u - v) * half, normal);
      add_vertex(mesh, (normal + u - v) * half, normal);
      add_vertex(mesh, (normal + u + v) * half, normal);
      add_vertex(mesh, (normal - u + v) * half, normal);
      add_triangle(mesh, first, first + 1, first + 2);
      add_triangle(mesh, first, first + 2, first + 3);
    }
  }
  return mesh;
}

Mesh make_sphere(float radius, int slices, int stacks) {
  slices = std::max(slices, 3);  // fewer cannot enclose a volume
  stacks = std::max(stacks, 2);
  Mesh mesh;
  // One vertex per pole and no seam: every edge is shared by two triangles (a closed mesh).
  const std::uint32_t north = add_vertex(mesh, {0.0f, radius, 0.0f}, kUp);
  for (int stack = 1; stack < stacks; ++stack) {
    const float polar = glm::pi<float>() * static_cast<float>(stack) / static_cast<float>(stacks);
    for (int slice = 0; slice < slices; ++slice) {
      const glm::vec3 direction = around_y(slice, slices) * std::sin(polar) + kUp * std::cos(polar);
      add_vertex(mesh, radius * direction, direction);
    }
  }
  const std::uint32_t south = add_vertex(mesh, {0.0f, -radius, 0.0f}, -kUp);
  const auto ring = [slices](int index) { return 1u + static_cast<std::uint32_t>(index * slices); };
  add_fan(mesh, north, ring(0), slices, true);
  for (int band = 0; band + 2 < stacks; ++band) add_band(mesh, ring(band), ring(band + 1), slices);
  add_fan(mesh, south, ring(stacks - 2), slices, false);
  return mesh;
}

Mesh make_cylinder(float radius, float length, int slices, bool caps) {
  slices = std::max(slices, 3);
  Mesh mesh;
  const glm::vec3 top(0.0f, length, 0.0f);
  const auto ring_of = [&](const glm::vec3 &base, bool radial_normals, const glm::vec3 &normal) {
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    for (int slice = 0; slice < slices; ++slice) {
      const glm::vec3 direction = around_y(slice, slices);
      add_vertex(mesh, base + radius * direction, radial_normals ? direction : normal);
    }
    return first;
  };
  const std::uint32_t top_side = ring_of(top, true, {});
  const std::uint32_t bottom_side = ring_of(glm::vec3(0.0f), true, {});
  add_band(mesh, top_side, bottom_side, slices);
  if (caps) {
    // The caps repeat the rim positions with flat normals; the positions are bit-identical, so
    // welding by position closes the mesh.
    const std::uint32_t top_rim = ring_of(top, false, kUp);
    add_fan(mesh, add_vertex(mesh, top, kUp), top_rim, slices, true);
    const std::uint32_t bottom_rim = ring_of(glm::vec3(0.0f), false, -kUp);
    add_fan(mesh, add_vertex(mesh, glm::vec3(0.0f), -kUp), bottom_rim, slices, false);
  }
  return mesh;
}

Mesh make_plane(float size, int divisions) {
  return make_heightfield(size, divisions, [](float, float) { return 0.0f; });
}

Mesh make_heightfield(float size, int divisions, const std::function<float(float, float)> &height) {
  divisions = std::max(divisions, 1);
  const auto height_at = [&height](float x, float z) { return height ? height(x, z) : 0.0f; };
  const float step = size / static_cast<float>(divisions);  // model space, metres per cell
  const float half = 0.5f * size;
  Mesh mesh;
  for (int row = 0; row <= divisions; ++row) {  // rows run along +z
    const float z = -half + static_cast<float>(row) * step;
    for (int column = 0; column <= divisions; ++column) {  // columns along +x
      const float x = -half + static_cast<float>(column) * step;
      // Central differences one cell wide: the surface y = h(x, z) has normal (-dh/dx, 1, -dh/dz).
      const float slope_x = (height_at(x + step, z) - height_at(x - step, z)) / (2.0f * step);
      const float slope_z = (height_at(x, z + step) - height_at(x, z - step)) / (2.0f * step);
      add_vertex(mesh, {x, height_at(x, z), z}, unit_or_up({-slope_x, 1.0f, -slope_z}));
    }
  }
  const auto index = [divisions](int column, int row) {
    return static_cast<std::uint32_t>(row * (divisions + 1) + column);
  };
  for (int row = 0; row < divisions; ++row) {
    for (int column = 0; column < divisions; ++column) {
      // Going +z then +x turns counter-clockwise seen from +y.
      add_triangle(mesh, index(column, row), index(column, row + 1), index(column + 1, row + 1));
      add_triangle(mesh, index(column, row), index(column + 1, row + 1), index(column + 1, row));
    }
  }
  return mesh;
}

namespace {

// The 1-based number of the first line that is a `vw` statement (after leading blanks), 0 if none.
std::size_t first_vertex_weight_line(const std::string &text) {
  std::size_t line = 1;
  for (std::size_t start = 0; start < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::size_t at = start;
    while (at < end && (text[at] == ' ' || text[at] == '\t')) ++at;
    if (end - at >= 3 && text.compare(at, 2, "vw") == 0 && (text[at + 2] == ' ' || text[at + 2] == '\t'))
      return line;
    start = end + 1;
  }
  return 0;
}

// The 1-based number of the first `v` or `vn` line holding a value that is not a number finite as
// a 32-bit float ("nan", "1e39", "1,5", a word), 0 if none: tinyobjloader reads such a value as
// 0 or infinity without a word, which would move a vertex silently. `bad` is set to the value.
std::size_t first_bad_coordinate_line(const std::string &text, std::string &bad) {
  std::size_t line = 1;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  for (std::size_t start = 0; start < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::size_t at = start;
    while (at < end && blank(text[at])) ++at;
    const bool position = end - at >= 2 && text[at] == 'v' && blank(text[at + 1]);
    const bool normal = end - at >= 3 && text.compare(at, 2, "vn") == 0 && blank(text[at + 2]);
    if (position || normal) {
      at += position ? 1 : 2;
      const std::size_t stop = std::min(text.find('#', at), end);
      while (at < stop) {
        while (at < stop && blank(text[at])) ++at;
        std::size_t token_end = at;
        while (token_end < stop && !blank(text[token_end])) ++token_end;
        if (token_end == at) break;
        float value = 0.0f;
        // from_chars takes no '+' sign, which C's strtod (and OBJ writers) allow.
        const std::size_t digits = text[at] == '+' ? at + 1 : at;
        const std::from_chars_result read =
            std::from_chars(text.data() + digits, text.data() + token_end, value);
        if (read.ec != std::errc() || read.ptr != text.data() + token_end || !std::isfinite(value)) {
          bad = text.substr(at, std::min<std::size_t>(token_end - at, 40));
          return line;
        }
        at = token_end;
      }
    }
    start = end + 1;
  }
  return 0;
}

}  // namespace

bool load_obj(const std::string &path, Mesh &mesh, std::string &error) {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warning, message, text;
  if (!read_input_file(path, kMaxObjFileBytes, text, message)) {
    error = path + ": " + message;
    return false;
  }
  // Vertex-weight lines (`vw`, a tinyobjloader extension no mesh here needs) are refused before
  // parsing: tinyobjloader converts their joint id from float to int unchecked, undefined for a
  // huge value (found by fuzz/obj_fuzz).
  const std::size_t weights = first_vertex_weight_line(text);
  if (weights != 0) {
    error = path + ": line " + std::to_string(weights) +
            ": vertex weights ('vw' lines) are not supported";
    return false;
  }
  std::string bad_value;
  const std::size_t bad_line = first_bad_coordinate_line(text, bad_value);
  if (bad_line != 0) {
    error = path + ": line " + std::to_string(bad_line) + ": '" + bad_value +
            "' is not a number finite as a 32-bit float";
    return false;
  }
  std::istringstream stream(text);
  // Faces are read untriangulated so that every index reaches the range check below (tinyobj
  // skips quads with bad indices silently); they are fanned here, as OBJ polygons are convex.
  // No material reader: colours come from the scene file, and an `mtllib` line must not make
  // the loader open another file.
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &message, &stream, nullptr,
                        false)) {
    error = path + ": " + (message.empty() ? "not a readable OBJ file" : trimmed(message));
    return false;
  }
  const auto vertex_count = static_cast<int>(attrib.vertices.size() / 3);
  const auto normal_count = static_cast<int>(attrib.normals.size() / 3);

  // Counted before anything is built: a face of n corners fans into n - 2 triangles.
  std::size_t triangle_total = 0;
  for (const tinyobj::shape_t &shape : shapes) {
    for (const std::size_t face_size : shape.mesh.num_face_vertices)
      triangle_total += face_size >= 3 ? face_size - 2 : 0;
  }
  if (triangle_total > kMaxObjTriangles) {
    error = path + ": " + std::to_string(triangle_total) + " triangles, more than the limit of " +
            std::to_string(kMaxObjTriangles);
    return false;
  }

  std::vector<tinyobj::index_t> corners;  // three per triangle, in file order
  bool every_corner_has_normal = true;
  for (const tinyobj::shape_t &shape : shapes) {
    std::size_t offset = 0;
    for (const std::size_t face_size : shape.mesh.num_face_vertices) {
      for (std::size_t k = 0; k < face_size; ++k) {
        const tinyobj::index_t &corner = shape.mesh.indices[offset + k];
        if (corner.vertex_index < 0 || corner.vertex_index >= vertex_count) {
          error = path + ": a face uses vertex " + std::to_string(corner.vertex_index + 1) +
                  " but the file has " + std::to_string(vertex_count) + " vertices";
          return false;
        }
        if (corner.normal_index >= normal_count) {
          error = path + ": a face uses normal " + std::to_string(corner.normal_index + 1) +
                  " but the file has " + std::to_string(normal_count) + " normals";
          return false;
        }
        every_corner_has_normal = every_corner_has_normal && corner.normal_index >= 0;
      }
      for (std::size_t k = 1; k + 1 < face_size; ++k) {
        corners.push_back(shape.mesh.indices[offset]);
        corners.push_back(shape.mesh.indices[offset + k]);
        corners.push_back(shape.mesh.indices[offset + k + 1]);
      }
      offset += face_size;
    }
  }
  if (corners.empty()) {
    error = path + ": no triangles";
    return false;
  }

  // One output vertex per distinct (position, normal) pair, in order of first use; without
  // normals in the file a position is one vertex and gets a smooth, area-weighted normal.
  Mesh loaded;
  std::map<std::pair<int, int>, std::uint32_t> vertex_of;
  std::vector<std::uint32_t> indices;
  indices.reserve(corners.size());
  const auto file_vector = [](const std::vector<tinyobj::real_t> &values, int index) {
    const auto at = static_cast<std::size_t>(index) * 3;
    return glm::vec3(values[at], values[at + 1], values[at + 2]);
  };
  for (const tinyobj::index_t &corner : corners) {
    const int normal_index = every_corner_has_normal ? corner.normal_index : -1;
    const auto [found, inserted] = vertex_of.try_emplace(
        {corner.vertex_index, normal_index}, static_cast<std::uint32_t>(loaded.positions.size()));
    if (inserted) {
      add_vertex(loaded, file_vector(attrib.vertices, corner.vertex_index),
                 normal_index >= 0 ? unit_or_up(file_vector(attrib.normals, normal_index))
                                   : glm::vec3(0.0f));
    }
    indices.push_back(found->second);
  }
  for (std::size_t i = 0; i < indices.size(); i += 3)
    loaded.triangles.emplace_back(indices[i], indices[i + 1], indices[i + 2]);
  if (!every_corner_has_normal) {
    for (const glm::uvec3 &triangle : loaded.triangles) {
      const glm::vec3 &a = loaded.positions[triangle.x];
      // The cross product's length is twice the area: larger faces weigh more.
      const glm::vec3 face =
          glm::cross(loaded.positions[triangle.y] - a, loaded.positions[triangle.z] - a);
      for (int k = 0; k < 3; ++k) loaded.normals[triangle[k]] += face;
    }
    for (glm::vec3 &normal : loaded.normals) normal = unit_or_up(normal);
  }
  mesh = std::move(loaded);
  return true;
}

}  // namespace gs

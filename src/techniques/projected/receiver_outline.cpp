// The receiver's outline from the light (receiver_outline.h): its vertices filed by world
// position, and the edges of its light-facing triangles found once.
#include "techniques/projected/receiver_outline.h"

#include "techniques/geometry/projection.h"

#include <cstring>

namespace gs {
namespace {

// Per position of `world` (world space), an id shared exactly by the positions that compare
// equal to it as floats (0 and -0 alike, infinities too; a NaN joins none), counted up in order
// of first appearance; `count` is the number of ids. Through a hash table of the positions' bits.
std::vector<std::uint32_t> world_position_ids(const std::vector<glm::vec3> &world,
                                              std::uint32_t &count) {
  int bits = 4;
  while ((std::size_t{1} << bits) < 2 * world.size()) ++bits;
  constexpr std::uint32_t kEmpty = ~std::uint32_t{0};
  std::vector<std::uint32_t> slot(std::size_t{1} << bits, kEmpty);  // a vertex with the position
  std::vector<std::uint32_t> id(world.size());
  count = 0;
  for (std::uint32_t i = 0; i < world.size(); ++i) {
    const glm::vec3 p = world[i] + glm::vec3(0.0f);  // -0 as 0, so equal positions hash alike
    std::uint32_t x, y, z;
    std::memcpy(&x, &p.x, 4), std::memcpy(&y, &p.y, 4), std::memcpy(&z, &p.z, 4);
    const std::uint64_t hash =
        ((std::uint64_t{x} << 32 | y) * 0x9E3779B97F4A7C15u) ^ (std::uint64_t{z} * 0xC2B2AE3D27D4EB4Fu);
    for (std::size_t s = hash >> (64 - bits);; s = (s + 1) & ((std::size_t{1} << bits) - 1)) {
      if (slot[s] == kEmpty) {
        slot[s] = i;
        id[i] = count++;
        break;
      }
      if (world[slot[s]] == world[i]) {
        id[i] = id[slot[s]];
        break;
      }
    }
  }
  return id;
}

}  // namespace

ReceiverOutline outline_of(const LightView &view, const ProjectedObject &receiver,
                           const std::vector<glm::vec4> &clip) {
  ReceiverOutline outline;
  outline.position_id = world_position_ids(receiver.world, outline.id_count);
  std::vector<std::uint64_t> all;
  for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
    const glm::vec3 &a = receiver.world[t.x], &b = receiver.world[t.y], &c = receiver.world[t.z];
    if (glm::dot(glm::cross(b - a, c - a), view.position - a) <= 0.0f) continue;
    all.push_back(outline.key(t.x, t.y));
    all.push_back(outline.key(t.y, t.z));
    all.push_back(outline.key(t.z, t.x));
    ReceiverOutline::Lit lit{{a, b, c}, {}, true, glm::vec2(INFINITY), glm::vec2(-INFINITY)};
    bool near = true;
    int k = 0;
    for (unsigned i : {t.x, t.y, t.z}) {
      lit.in_front = lit.in_front && clip[i].w > 0.0f;
      const GrVertex v = to_screen(clip[i], view.size, view.size);
      lit.screen[k] = glm::vec2(v.x, v.y);
      near = near && std::abs(v.x) < ReceiverOutline::kNear && std::abs(v.y) < ReceiverOutline::kNear;
      lit.low = glm::min(lit.low, lit.screen[k]), lit.high = glm::max(lit.high, lit.screen[k]);
      ++k;
    }
    if (!lit.in_front || !near) lit.low = glm::vec2(-INFINITY), lit.high = glm::vec2(INFINITY);
    outline.lit.push_back(lit);
  }
  outline.size = view.size;
  // The edges filed under their lower id (a counting sort), each id's few then sorted: an edge
  // on the outline is one found once.
  std::vector<std::uint32_t> start(outline.id_count + 1, 0), higher(all.size());
  for (const std::uint64_t edge : all) ++start[(edge >> 32) + 1];
  for (std::uint32_t id = 0; id < outline.id_count; ++id) start[id + 1] += start[id];
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  for (const std::uint64_t edge : all) higher[next[edge >> 32]++] = static_cast<std::uint32_t>(edge);
  outline.start.assign(outline.id_count + 1, 0);
  for (std::uint32_t id = 0; id < outline.id_count; ++id) {
    const auto first = higher.begin() + start[id], last = higher.begin() + start[id + 1];
    std::sort(first, last);
    for (auto i = first; i != last;) {
      auto j = i + 1;
      while (j != last && *j == *i) ++j;
      if (j == i + 1) outline.higher.push_back(*i);
      i = j;
    }
    outline.start[id + 1] = static_cast<std::uint32_t>(outline.higher.size());
  }
  return outline;
}

}  // namespace gs

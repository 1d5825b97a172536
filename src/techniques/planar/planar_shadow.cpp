// The planar shadow technique's drawing: the scene pass, then step 1's shadow polygons
// (planar_casting.cpp) drawn over their receivers with depth levels that darken each pixel once.
// Spaces: world (the shadow polygons); Glide screen through the camera (pixels, y down,
// oow = 1/w) in step 3.
#include "techniques/planar/planar_shadow.h"
#include "techniques/step_clock.h"

#include "scene/lighting.h"
#include "scene/local_origin.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/projection.h"
#include "techniques/light_passes/scene_pass.h"
#include "techniques/planar/planar_rows.h"

#include <glide.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <tuple>

namespace gs {
namespace {

// Step 3's depth levels, in W-buffer codes (4096 per octave of w, so n codes nearer is 1/w times
// 2^(n/4096): the same on the Voodoo and in the shim). Every polygon is drawn twice, with depth
// writes on and GR_CMP_LESS (strictly nearer passes):
//   - the cover, kCoverCodes nearer than its receiver: it passes the receiver the scene pass left
//     in the depth buffer and darkens the pixel;
//   - the seal, kCoverSealCodes nearer again, at alpha 0 (the colour is left as it is): it writes a
//     depth that every later cover on that pixel, lying on the same plane, fails.
// A single level (the cover with depth writes on) is not enough: two polygons on one plane would
// have to interpolate exactly the same depth at a pixel they share for the second to fail, and
// the rounding of their different vertices makes either one the nearer as often as not.
// The levels go in the vertices' oow rather than through grDepthBiasLevel, so the thousands of
// alternating covers and seals stay one batch of triangles instead of two state changes each.
// Each light's covers must pass the scene pass's depths and not the previous lights' seals, so
// before a light's polygons, once an earlier light has left seals, the scene pass's depth buffer
// is drawn again (render_scene_depth, depth only). Each light used to get a band of codes
// above the previous one's seals instead: 24 codes more margin per light, which let the second
// light's covers pass whatever lay within 0.44% of its distance in front of their receiver
// (tests/hard_cases/audit/pl6: a crumpled sheet lying on the floor, in both lights' shadow on
// the floor, drawn over along a line of 23 pixels where it comes within 2 cm of the floor,
// 0.131% of the receiver pixels).
// The cover's margin is 2 codes (w times 1.0003): a margin of 1 left speckled holes in shadows
// near the camera (0.06 to 0.27% of the receiver pixels, interior, on
// tests/hard_cases/terminator_*.json; 2 codes: under 0.03%). A larger margin lets covers on a
// floor pass the feet of what stands on it, a pixel or two of the contact line (4 codes: 5
// pixels on a fighter's foot).
// Over a receiver the scene pass clipped through the camera it is 8 codes (w times 1.0014): the
// scene pass drew that receiver as a fan of its clipped polygon, whose triangles stray from the
// plane of the largest by up to 4 codes on a floor seen at a grazing angle from 0.3 m
// (tests/hard_cases/eye_near_plane.json).
// Over a receiver triangle that reaches past the screen (guard band or camera-clipped) the margin
// also holds what its 1/w changes over kCoverPixels along x plus along y (Level below): the
// shim's guDrawTriangleWithClip clips it to the window and snaps the vertices it makes there to
// 1/16 px while keeping their interpolated depth, so the scene pass's depth strays from the plane
// by up to 1/32 px of its gradient (measured: 1.8 to 2.8 codes at the right edge of
// tests/hard_cases/audit/y4, where 2 codes left single lit pixels, 0.100%). The margin is twice
// that stray; the covers and seals themselves do not stray, since clip_to_window cuts them to
// the window first with their depths on the plane. Receivers inside the window get none of it:
// on a receiver seen edge-on it would let covers pass what lies close in front of it (with it on
// every receiver, the interior error of tests/hard_cases/audit/v7 rose from 0.023% to 0.084%).
// An occluder closer to the receiver than 0.03% (0.14%) of its distance, plus that 1/16 px of its
// gradient near the screen's edges, may let a cover show through, unless it is a caster passing
// through the receiver's plane: step 1 leaves out what that caster hides of the plane from the
// camera (planar_casting.cpp, HiddenRegion).
// The seal stands half a code above its cover, less than any cover's margin, and never more: a
// seal on a receiver writes its depth over whatever visible surface lies within the seal's reach
// in front of that receiver, and that surface's own cover then fails. Where the seal's reach
// is no more than its cover's, the seal passes such a surface only where its own cover has
// passed it and darkened the pixel already (but for a fraction of a code of W-buffer rounding).
// The seal used to be 16 codes above the cover (and 1/8 px of the gradient above it past the
// window, against the shim's strays of two covers clipped there): it left lines of lit pixels
// where one part of a fighter passes into another (tests/hard_cases/audit/
// stencil17_sv4_camera_in_ball_round_fighters_head: 0.105% of the receiver pixels), and along
// the edges of dune triangles seen edge-on just in front of a cylinder at the bottom of the
// screen (/work/aud17 sunk-extra-lights-narrow-cones-camera-behind_17248: 0.306%).
// Half a code (w times 1.00008) is far above the float rounding of two polygons' depths on one
// plane (about 1e-7 of 1/w), so a later cover there still fails.
constexpr float kCoverCodes = 2.0f;
constexpr float kClippedCoverCodes = 8.0f;
constexpr float kCoverSealCodes = 0.5f;
// In pixels of the receiver's gradient, over receivers past the window only.
constexpr float kCoverPixels = 1.0f / 16.0f;

// The depth (oow) a triangle's screen vertices give across the screen once snapped, which is what
// the rasteriser interpolates: oow = a x + b y + c, in Glide screen pixels.
struct DepthPlane {
  double a = 0.0, b = 0.0, c = 0.0;
  double at(float x, float y) const { return a * x + b * y + c; }
};

bool depth_plane(const GrVertex &p, const GrVertex &q, const GrVertex &r, DepthPlane &plane) {
  const double px = snap_to_subpixel(p.x), py = snap_to_subpixel(p.y);
  const double qx = snap_to_subpixel(q.x) - px, qy = snap_to_subpixel(q.y) - py;
  const double rx = snap_to_subpixel(r.x) - px, ry = snap_to_subpixel(r.y) - py;
  const double qw = static_cast<double>(q.oow) - p.oow, rw = static_cast<double>(r.oow) - p.oow;
  const double det = qx * ry - rx * qy;
  if (det == 0.0) return false;  // edge-on: the scene pass drew nothing of it either
  plane.a = (qw * ry - rw * qy) / det;
  plane.b = (rw * qx - qw * rx) / det;
  plane.c = p.oow - plane.a * px - plane.b * py;
  return true;
}

// Whether the shim clips a triangle with this vertex to the screen (guDrawTriangleWithClip):
// the rasteriser's clip window is the whole screen, and the shim tests the snapped vertex.
bool outside_window(const GrVertex &v, const Scene &scene) {
  const float x = snap_to_subpixel(v.x), y = snap_to_subpixel(v.y);
  return !(x >= 0.0f && x < static_cast<float>(scene.width) && y >= 0.0f &&
           y < static_cast<float>(scene.height));
}

// `polygon` (Glide screen, snapped, oow on the receiver's depth `plane`) cut to the screen, short
// of its right and bottom sides by 1/16 px (the shim's window test wants x < width, y < height;
// every pixel centre stays inside), each vertex made on a side snapped and given the plane's
// oow there. The shim then draws it unclipped: its own clip would keep the depth it interpolates
// at the vertices it snaps, away from the plane by up to 1/32 px of the gradient, and two covers
// clipped there could each stray their own way past the other's seal.
void clip_to_window(std::vector<GrVertex> &polygon, const DepthPlane &plane, const Scene &scene,
                    std::vector<GrVertex> &scratch) {
  const float right = static_cast<float>(scene.width) - 1.0f / 16.0f;
  const float bottom = static_cast<float>(scene.height) - 1.0f / 16.0f;
  // Keeps the part where sign * (coordinate - bound) >= 0.
  auto clip = [&](bool use_x, float bound, float sign) {
    scratch.clear();
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
      const GrVertex &a = polygon[i], &b = polygon[(i + 1) % n];
      const float da = sign * ((use_x ? a.x : a.y) - bound);
      const float db = sign * ((use_x ? b.x : b.y) - bound);
      if (da >= 0.0f) scratch.push_back(a);
      if ((da >= 0.0f) != (db >= 0.0f)) {
        // From the same end whichever way the edge is walked, so neighbours sharing it agree.
        const bool forward = std::tie(a.x, a.y) < std::tie(b.x, b.y);
        const GrVertex &p = forward ? a : b, &q = forward ? b : a;
        const double dp = forward ? da : db, dq = forward ? db : da;
        const double t = dp / (dp - dq);
        GrVertex cut = a;
        cut.x = use_x ? bound : snap_to_subpixel(static_cast<float>(p.x + (q.x - p.x) * t));
        cut.y = use_x ? snap_to_subpixel(static_cast<float>(p.y + (q.y - p.y) * t)) : bound;
        cut.oow = static_cast<float>(plane.at(cut.x, cut.y));
        scratch.push_back(cut);
      }
    }
    std::swap(polygon, scratch);
  };
  clip(true, 0.0f, 1.0f);
  clip(true, right, -1.0f);
  if (polygon.size() >= 3) clip(false, 0.0f, 1.0f);
  if (polygon.size() >= 3) clip(false, bottom, -1.0f);
}

// A depth level over a receiver: 1/w raised by `codes` W-buffer codes (a share of the depth)
// plus what the receiver's depth changes over `pixels` pixels of screen along x and along y
// (an absolute amount, so 1/w stays affine in screen space).
struct Level {
  float codes = 0.0f, pixels = 0.0f;
};

// Draws `polygon` (Glide screen, snapped, oow on the receiver's depth `plane`) at `level` above
// that plane, at alpha `alpha`. Clip w counts near-plane distances (projection.cpp), so the
// receiver's 1/w reaches 1 at the camera's near plane, and the W-buffer holds nothing nearer: the
// shim clamps each vertex's 1/w to 1. A vertex pushed past 1 would lower the depth the whole
// polygon iterates, so that its interior near the near plane kept a fraction of the margin
// (tests/hard_cases/audit/y3: well under a code, 9 px from the near plane's line on the floor).
// So the polygon is cut along the line on which its raised 1/w is 1 (1/w is affine in screen
// space): the part short of it keeps the whole margin, the part past it (receiver depths within
// the level of the near plane) is drawn at 1.
void draw_at_level(const std::vector<GrVertex> &polygon, const DepthPlane &plane, Level level,
                   float alpha, std::vector<GrVertex> &short_part,
                   std::vector<GrVertex> &past_part) {
  const float scale = std::exp2(level.codes / 4096.0f);
  const float offset =
      static_cast<float>((std::abs(plane.a) + std::abs(plane.b)) * level.pixels);
  auto raise = [&](double oow) { return static_cast<float>(oow) * scale + offset; };
  short_part.clear();
  past_part.clear();
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    GrVertex a = polygon[i];
    const GrVertex &b = polygon[(i + 1) % n];
    const float da = raise(a.oow), db = raise(b.oow);
    a.a = alpha;
    a.oow = std::min(da, 1.0f);
    if (da <= 1.0f) short_part.push_back(a);
    if (da >= 1.0f) past_part.push_back(a);
    if ((da < 1.0f) != (db < 1.0f) && da != 1.0f && db != 1.0f) {
      // From the same end whichever way the edge is walked, so neighbours sharing it agree.
      const bool forward = std::tie(a.x, a.y) < std::tie(b.x, b.y);
      const GrVertex &p = forward ? polygon[i] : b, &q = forward ? b : polygon[i];
      const double dp = forward ? da : db, dq = forward ? db : da;
      const double t = (1.0 - dp) / (dq - dp);  // where the raised 1/w is 1
      GrVertex cut = a;
      cut.x = snap_to_subpixel(static_cast<float>(p.x + (q.x - p.x) * t));
      cut.y = snap_to_subpixel(static_cast<float>(p.y + (q.y - p.y) * t));
      cut.oow = std::min(raise(plane.at(cut.x, cut.y)), 1.0f);
      short_part.push_back(cut);
      past_part.push_back(cut);
    }
  }
  if (short_part.size() >= 3) draw_fan(short_part);
  if (past_part.size() >= 3) draw_fan(past_part);
}

// The state the covers and seals are drawn in: flat `color`, iterated alpha blended.
void set_polygon_state(GrColor_t color) {
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  grCullMode(GR_CULL_POSITIVE);  // wound like their receivers, whose back faces were culled
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  grConstantColorValue(color);
  grAlphaCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                       GR_BLEND_ZERO);
}

// Every light's polygons, flat `color` at the lights' strengths (or opaque) over the back
// buffer, whose depth buffer holds the scene pass's surfaces.
void draw_shadow_polygons(const Scene &scene, const FrameGeometry &frame,
                          const PlanarShadows &shadows, GrColor_t color, bool opaque) {
  set_polygon_state(color);
  std::vector<ClipVertex> polygon, receiver_polygon, scratch;
  std::vector<GrVertex> screen, receiver_screen, short_part, past_part, rectangle;
  std::vector<GrVertex> drawn;
  std::vector<planar::RowSpan> spans, drawn_spans;
  bool sealed = false;  // some light's seals are in the depth buffer
  for (std::size_t l = 0; l < shadows.lights.size(); ++l) {
    const ShadowPolygons &light = shadows.lights[l];
    const float alpha = opaque ? 255.0f : scene.lights[l].shadow_strength * 255.0f;
    if (sealed && !light.polygons.empty()) {
      render_scene_depth(scene, frame);
      set_polygon_state(color);
      sealed = false;
    }
    for (const ShadowPolygons::Polygon &p : light.polygons) {
      polygon.clear();
      for (std::uint32_t i = 0; i < p.count; ++i) {
        polygon.push_back({{}, light.vertices[p.first + i], {}});
      }
      project_camera_polygon(frame, scene, polygon, scratch, screen);
      if (screen.size() < 3) continue;
      // The depth is taken from the receiver triangle's own snapped vertices as the scene pass
      // drew them, so cover and receiver differ by kCoverCodes and not by the rounding of two
      // sets of vertices (on a grazing surface that rounding is worth many codes). A triangle
      // the scene pass clipped through the camera was drawn as a fan of its clipped polygon,
      // all in one plane: its largest fan triangle gives that plane.
      const ProjectedObject &receiver = frame.objects[p.receiver];
      const glm::uvec3 &t = receiver.object->mesh.triangles[p.triangle];
      DepthPlane plane;
      bool has_plane = false;
      const bool clipped =
          (receiver.outside[t.x] | receiver.outside[t.y] | receiver.outside[t.z]) != 0;
      bool past_window = false;
      if (!clipped) {
        has_plane =
            depth_plane(receiver.screen[t.x], receiver.screen[t.y], receiver.screen[t.z], plane);
        for (unsigned index : {t.x, t.y, t.z}) {
          past_window = past_window || outside_window(receiver.screen[index], scene);
        }
      } else {
        receiver_polygon.clear();
        for (unsigned index : {t.x, t.y, t.z}) {
          receiver_polygon.push_back({{}, receiver.world[index], {}});
        }
        project_camera_polygon(frame, scene, receiver_polygon, scratch, receiver_screen);
        float largest = 0.0f;
        for (std::size_t i = 2; i < receiver_screen.size(); ++i) {
          const GrVertex &a = receiver_screen[0], &b = receiver_screen[i - 1],
                         &c = receiver_screen[i];
          const float area = std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
          if (area > largest && depth_plane(a, b, c, plane)) largest = area, has_plane = true;
        }
        for (const GrVertex &v : receiver_screen) {
          past_window = past_window || outside_window(v, scene);
        }
      }
      if (!has_plane) continue;  // edge-on: the scene pass drew nothing of it either
      // The receiver triangle as the scene pass drew it, its corners snapped.
      drawn.clear();
      if (!clipped) {
        for (unsigned index : {t.x, t.y, t.z}) drawn.push_back(receiver.screen[index]);
      } else {
        drawn = receiver_screen;
      }
      for (GrVertex &v : drawn) v.x = snap_to_subpixel(v.x), v.y = snap_to_subpixel(v.y);
      // The gradient's share only where the shim clipped the receiver to the window.
      const float strays = past_window ? 1.0f : 0.0f;
      const Level cover = {clipped ? kClippedCoverCodes : kCoverCodes, strays * kCoverPixels};
      const Level seal = {cover.codes + kCoverSealCodes, cover.pixels};
      // Drawn a row of pixel centres at a time (planar_rows.h), each rectangle wound as the
      // polygon is on screen (its shoelace sum's sign: positive is the order of a rectangle's
      // corners listed below, y down).
      double area = 0.0;
      for (std::size_t i = 0; i < screen.size(); ++i) {
        const GrVertex &a = screen[i], &b = screen[(i + 1) % screen.size()];
        area += static_cast<double>(a.x) * b.y - static_cast<double>(b.x) * a.y;
      }
      planar::row_spans(screen, scene.height, spans);
      planar::row_spans(drawn, scene.height, drawn_spans);
      for (const planar::RowSpan &span : spans) {
        // The pixels of the row whose centres (x + 0.5) lie from span.left to span.right, and
        // that the receiver triangle drew (its snapped edges' crossings, ties included).
        if (drawn_spans.empty() || span.row < drawn_spans.front().row ||
            span.row > drawn_spans.back().row) {
          continue;
        }
        const planar::RowSpan &receiver_span =
            drawn_spans[static_cast<std::size_t>(span.row - drawn_spans.front().row)];
        const double first = std::max(
            {std::ceil(span.left - 0.5), std::ceil(receiver_span.left - 0.5), 0.0});
        const double last = std::min({std::floor(span.right - 0.5),
                                      std::floor(receiver_span.right - 0.5), scene.width - 1.0});
        if (first > last) continue;
        const float left = static_cast<float>(first), right = static_cast<float>(last + 1.0);
        const float top = static_cast<float>(span.row), bottom = top + 1.0f;
        rectangle.assign(4, screen[0]);
        const float xs[4] = {left, right, right, left}, ys[4] = {top, top, bottom, bottom};
        for (std::size_t k = 0; k < 4; ++k) {
          GrVertex &v = rectangle[area > 0.0 ? k : 3 - k];
          v.x = xs[k], v.y = ys[k];
          v.oow = static_cast<float>(plane.at(v.x, v.y));
        }
        clip_to_window(rectangle, plane, scene, receiver_screen);
        if (rectangle.size() < 3) continue;
        draw_at_level(rectangle, plane, cover, alpha, short_part, past_part);
        draw_at_level(rectangle, plane, seal, 0.0f, short_part, past_part);
        sealed = true;
      }
    }
  }
  set_scene_state();
}

using Clock = std::chrono::steady_clock;

class PlanarShadow final : public ShadowTechnique {
 public:
  FrameReport render(const Scene &world_scene, bool synchronous) override {
    // Every step in local coordinates (local_origin.h): far from the world's origin a caster
    // projected onto a receiver's plane in float lost its corners (a NaN vertex at 3.6 km).
    const Scene &scene = in_local_coordinates(world_scene, moved_);
    moved_used_ = &scene == &moved_;
    FrameReport report;
    const auto frame_start = Clock::now();
    auto start = frame_start;
    auto finish_step = [&](const char *name) {
      if (synchronous) grSstIdle();
      report.steps.emplace_back(name, elapsed_ms(start));
      start = Clock::now();
    };
    grRenderBuffer(GR_BUFFER_BACKBUFFER);
    shadows_ = project_and_clip_casters(scene);
    finish_step("1 project and clip caster polygons");
    frame_ = project_scene(scene);
    render_scene(scene, frame_);
    finish_step("2 render the scene");
    draw_shadow_polygons(scene, frame_, shadows_, 0x00000000u, false);
    finish_step("3 draw the shadow polygons");
    report.total_ms = elapsed_ms(frame_start);
    if (shadows_.pairs_skipped > 0) {
      report.errors.push_back(
          "planar: " + std::to_string(shadows_.pairs_skipped) +
          " caster/receiver triangle pairs beyond the limit of " +
          std::to_string(kMaxClippedPairs) +
          " per frame were not clipped, so part of the shadows is missing (fewer caster "
          "triangles, e.g. a simpler shadow_mesh, bring it under the limit)");
      report.warnings.push_back(report.errors.back());
    }
    return report;
  }

  void render_mask(const Scene &world_scene) override {
    // The scene render drew, in its local coordinates: frame_ points at its objects.
    const Scene &scene = moved_used_ ? moved_ : world_scene;
    // Step 3 left its seals in the depth buffer, which its covers would fail. The scene pass's
    // depth is drawn again (colour writes off; the same vertices give the same depths), so the
    // covers pass exactly where they darkened the frame.
    render_scene_depth(scene, frame_);
    grDepthMask(FXFALSE);
    grBufferClear(0, 0, 0);  // colour only
    draw_shadow_polygons(scene, frame_, shadows_, 0xFFFFFFFFu, true);  // white, opaque
  }

 private:
  PlanarShadows shadows_;
  FrameGeometry frame_;
  Scene moved_;              // the last frame's scene in local coordinates, when it was moved
  bool moved_used_ = false;  // whether render drew moved_ (else the scene it was given)
};

}  // namespace

std::unique_ptr<ShadowTechnique> make_planar_shadow(const TechniqueOptions &) {
  return std::make_unique<PlanarShadow>();
}

}  // namespace gs

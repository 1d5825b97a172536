// Hubert Nguyen's projected shadow texture (Game Developer, 1999) in Glide, as the article's five
// steps: the caster flat from the light; an ARGB_4444 texture of it; (s, t) for the receivers; the
// scene; the flagged triangles again with the texture. A texture per caster and light (one more
// per receiver it reaches through: pierced_receivers.h), no shadow on the caster itself or
// beyond the beam (light_beam.h), and none from a texture too coarse (texel_footprint.h).
#pragma once

#include "scene/scene.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/light_passes/scene_pass.h"
#include "techniques/projected/shadow_texture_memory.h"
#include "techniques/texel_error/shadow_edge_error.h"
#include "techniques/texel_error/surface_cuts.h"
#include "techniques/texel_error/texel_footprint.h"

#include <glide.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gs {

class CasterSurfacesFromLight;  // caster_surface_from_light.h

enum class ShadowAlpha { Constant, Distance };  // iterated alpha: the light's strength, or it
                                                // fading with the receiver's distance

struct ProjectedShadowOptions {
  int size = 0;                // shadow map side in texels, 32..512, for every light; 0: each
                               // light's shadow_size. Above 256 (a Voodoo 1 texture's limit)
                               // the map is split into 256x256 tiles
  bool auto_size = false;      // pick the size from the caster's size on screen (LOD)
  // A caster's shadow refused as too coarse for the screen (its texel footprint or the error
  // along its edges, below) is fitted and drawn again at the smallest larger size up to 512
  // that the estimates accept, for that caster in that frame: a note, not an error. Checked
  // again at that size; when no size is accepted, the refusal stands.
  bool grow_to_accepted = false;
  bool bilinear = true;
  bool direct_path = false;    // step 1 renders straight into texture memory (no LFB read)
  bool chroma_key = false;     // the article's Figure 15 alternative to the alpha mask
  bool projective = true;      // per-pixel s/q (W_DIFF_TMU0); false: the article's per-vertex s
  ShadowAlpha alpha = ShadowAlpha::Constant;
  int border_texels = 2;       // clean border the light's view keeps around the caster
  // A shadow whose texels span more screen pixels than this on a receiver it falls on is
  // refused (a per-frame error, nothing cast): its edge would stray more than a pixel from the
  // true one. 0: the measured default for the filter (texel_footprint.h); infinity: no check
  // (neither this one nor the error along the shadow's edges, shadow_edge_error.h).
  float largest_texel_footprint_px = 0.0f;
};

// The light's view of one caster (step 1's camera). Fitted to the caster's bounding sphere when
// the whole caster lies in the light's beam and the sphere fits a view; otherwise to what the
// beam holds of the caster (its triangles clipped to the beam's outer pyramid, light_beam.h),
// which keeps the shadow of a caster wider than the beam, or one the light sits beside or behind.
struct LightView {
  glm::mat4 view{1.0f};             // world to light view space (the light looks down -z)
  glm::mat4 projection{1.0f};       // light view to light clip space
  glm::vec3 position{0.0f};         // world
  float caster_front = 0.0f;        // light-view distance to the caster's nearest bound
  float caster_distance = 0.0f;     // light to the caster's centre
  int size = 256;                   // texels of this texture
  // A tile of a larger map: the light view space planes of its seams with its neighbours, which
  // step 3 clips receivers to. Taken from the whole map's projection, so a neighbour's plane is
  // this one negated to the bit and both cut a receiver at the very same points (no crack).
  std::vector<glm::vec4> tile_planes;
  bool surrounds_light = false;     // a closed caster around the light: drawn from both sides
  bool direct_path = false;         // the path step 1 took (the LFB path needs the region to fit
                                    // in the back buffer; a larger one goes direct)
  // False: no texture for this caster. Then either `outside_beam` (nothing of the caster is in
  // the beam, so it has no shadow to cast: right, and silent) or `problem` says why a shadow the
  // frame should have is missing (an error: the frame is wrong).
  bool usable = false;
  bool outside_beam = false;
  std::string problem;
  std::string note;                 // a change the user asked for did not get (path fallback)
  // Light view space planes step 1 clips the caster to (a plane just in front of the light and
  // the view's square inside its clean border); empty when the whole caster is inside them.
  std::vector<glm::vec4> caster_planes;
  // Those of caster_planes whose cut through the caster is an edge of its shadow (a pierced
  // receiver's plane, pierced_receivers.h), light view space.
  std::vector<glm::vec4> edge_planes;
  // The light's beam (light_beam.h): step 3 clips receivers to its lit regions, so step 5
  // darkens nothing the light does not reach.
  LightBeam beam;
  // Which 16x16 cells of the texture the caster's triangles touch (a bounding-box cover, so
  // conservative): step 3 skips receiver triangles that see only empty cells, where step 5
  // would blend alpha 0 and change nothing.
  // Per cell also the caster's nearest light-view depth (w): a receiver wholly nearer the light
  // than that, in every cell it sees, lies between the light and the caster and stays lit.
  static constexpr int kCells = 16;
  std::vector<bool> occupied = std::vector<bool>(kCells * kCells, false);
  std::vector<float> nearest = std::vector<float>(kCells * kCells, INFINITY);
  // The same cover on a finer grid (2x2 texels at 256), which selects no triangle (the 16x16
  // depth test above stays as it is): step 5 skips a selected triangle none of whose fine cells
  // within reach is covered (ShadowTriangle::reaches_caster), which changes no byte.
  static constexpr int kFineCells = 128;
  std::vector<bool> covered = std::vector<bool>(kFineCells * kFineCells, false);
  // The fine cell (column or row) holding a light-screen coordinate in texels, clamped to the grid
  // (truncated, not floored: the two differ only below 0, which the clamp takes to cell 0).
  int fine_cell_of(float texels) const {
    const float side = static_cast<float>(size) / kFineCells;  // texels
    return std::clamp(static_cast<int>(texels / side), 0, kFineCells - 1);
  }
  // Whether a covered fine cell lies within `reach` texels of the box low..high (light screen,
  // texels); true for a box that is not finite, which the callers then keep as it is.
  bool covered_near(const glm::vec2 &low, const glm::vec2 &high, float reach) const;
  // The fine cells the caster's silhouette from the light crosses (and its cut by edge_planes):
  // where the shadow's edge can lie (texel_footprint.h).
  std::vector<bool> silhouette = std::vector<bool>(kFineCells * kFineCells, false);
  // The same silhouette's edges (world space), for the error along the shadow's edges
  // (shadow_edge_error.h); the cut by a SurfaceMask's surface is not among them.
  std::vector<SilhouetteSegment> silhouette_segments;
  // The caster's rim: its edges that one triangle walks (world space, each edge's ends in the
  // order of their model positions), for mark_rims (shadow_edge_error.h).
  std::vector<std::pair<glm::vec3, glm::vec3>> rims;
  // A SurfaceMask's strips beside the caster's cut by the receiver (contact_strips.h; the
  // light's screen, texels): step 1 keeps the caster out of them.
  std::vector<std::array<GrVertex, 4>> contact_strips;
  // The caster's faces that a masking receiver's surface cuts (surface_cuts.h; world), made by
  // the first texture of this view whose step 3 needs them and shared by the view's copies, the
  // plain and masked textures of one cover (cover_caster_from_light makes the holder; without
  // one, step 3 makes its own).
  std::shared_ptr<std::optional<SurfaceCuts::Faces>> cut_faces;
};

struct ShadowTexture {
  FxU32 address = 0;  // in TMU memory (for render_projected_shadows' textures, where it was
                      // placed: ShadowFrame::textures says whether it is there)
  GrTexInfo info{};
  std::size_t id = 0;  // the frame's name for it in ShadowFrame::textures
  // The LFB path: step 2's read-back (system memory, size x size words, rows from the top),
  // which loads it into TMU memory again.
  std::vector<FxU16> texels;
};

// A receiver triangle the texture is projected onto, ready for step 5 (screen vertices with
// sow, tow and the projective divisor; colour unused).
struct ShadowTriangle {
  GrVertex v[3];
  // False: no texel within bilinear reach of the triangle's (s, t) (and half a texel more) is
  // covered by the caster (LightView::covered), so every pixel of it samples alpha 0, which
  // step 5's alpha test rejects; step 5 does not draw it (its result would be the same bytes).
  bool reaches_caster = true;
};

struct ReceiverCoords {
  std::vector<ShadowTriangle> triangles;      // unclipped: the step-4 screen vertices
  std::vector<std::vector<GrVertex>> clipped;  // clipped by the caster's front plane or camera
  // Per receiver polygon the shadow can fall on: how many screen pixels a texel spans there,
  // and over how many pixels (texel_footprint.h).
  std::vector<FootprintSample> footprints;
  // The interior error the texels can make along the shadow's edges on those polygons, and the
  // receiver (index into scene.objects) with the most of it (shadow_edge_error.h).
  EdgeErrorEstimate edge_error;
  std::size_t edge_error_receiver = 0;
  float edge_error_receiver_pixels = 0.0f;
  // Depth band -1: a receiver triangle nearer the light than the band's plane was left to the
  // texture masked by the receiver's farthest surface (band -2), its own surface hiding it.
  bool hidden_left = false;
};

struct StepTimes {
  double ms[5] = {};  // steps 1..5
  double total_ms = 0.0;
};

// Step 1, in three parts. The light's view fitted to the caster (LightView), keeping a clean
// border; a map larger than a Voodoo 1 texture split into 256x256 tiles; and the caster
// drawn flat into one texture (565 red 11110b on 0, depth test off, back faces culled unless
// the caster is an open mesh; only its part inside LightView::caster_planes, and with a
// SurfaceMask only where it is nearer the light than that receiver's surface) in a
// size x size region: the back buffer's top-left corner (the whole back buffer is cleared to 0,
// and its depth too with a SurfaceMask), or texture memory at
// `texture_address` on the direct path.
// The Glide LOD of a size x size shadow texture (size a power of two, 1..256).
inline GrLOD_t shadow_lod(int size) {
  GrLOD_t lod = GR_LOD_256;
  for (int side = 256; side > size; side /= 2) ++lod;
  return lod;
}
LightView fit_light_view(const Scene &scene, std::size_t caster, std::size_t light,
                         const ProjectedShadowOptions &options);
std::vector<LightView> split_into_textures(const LightView &view);
// ProjectedShadowOptions::grow_to_accepted's note (a warning, not an error): the first size's
// refusal, its `reason` (texel_footprint_reason, shadow_edge_error_reason), with its shadow
// drawn at `size` texels instead of none.
std::string grown_shadow_note(const std::string &reason, int size);
// A non-planar receiver the caster reaches through (pierced_receivers.h): step 1 draws the
// caster only where it is nearer the light than the receiver's light-facing surface, and marks
// the caster's triangles that pass through that surface (caster_crossing, per caster_mesh
// triangle) as silhouette, since the cut is an edge of the shadow.
// With `farthest`, the caster is drawn where it is nearer the light than the receiver's
// farthest light-facing surface instead: the texture for the receiver's parts that its own
// nearer surface hides from the light (receiver_coords.cpp, depth band -2).
// With `triangles`, only the receiver's triangles whose entry (per mesh triangle) is not 0 are
// drawn: the hidden ones' nearest surface, for their middle layer (band -3, hidden_layers.h).
struct SurfaceMask {
  const ProjectedObject *receiver = nullptr;
  const std::vector<std::uint8_t> *caster_crossing = nullptr;
  bool farthest = false;
  const std::vector<std::uint8_t> *triangles = nullptr;
};
void render_caster_from_light(const Scene &scene, std::size_t caster, LightView &view,
                              const ProjectedShadowOptions &options, FxU32 texture_address,
                              const SurfaceMask *mask = nullptr);
// render_caster_from_light in parts, so that step 3 (which needs only the cover) can run before
// the drawing and a texture no receiver triangle would show is never drawn, and so that a
// caster's textures for the same view share one cover. cover_caster_from_light sets the view's
// path and cover and returns the triangles to draw; mask_caster_cover turns a copy of both into
// a SurfaceMask's (W from depth_oow, the cut by the surface on the silhouette);
// draw_caster_from_light draws them.
struct CasterDraw {
  std::vector<GrVertex> vertices;     // the light's Glide screen: the caster_mesh vertices, then
                                      // those of its triangles clipped to the caster planes
  std::vector<float> light_w;         // per vertex, its light clip w
  std::vector<glm::vec4> caster_clip;  // per caster_mesh vertex, light clip space
  std::vector<glm::uvec3> triangles;  // into vertices, in the mesh's order
  bool closed = true;                 // back faces culled (a closed caster_mesh not around the light)
};
CasterDraw cover_caster_from_light(const Scene &scene, std::size_t caster, LightView &view,
                                   const ProjectedShadowOptions &options);
void mask_caster_cover(const Scene &scene, std::size_t caster, LightView &view,
                       const SurfaceMask &mask, CasterDraw &draw);
void draw_caster_from_light(const Scene &scene, LightView &view, FxU32 texture_address,
                            const SurfaceMask *mask, const CasterDraw &draw);
// The same drawing, leaving the clip window as the path left it (the LFB path's on the region).
void draw_caster_flat(LightView &view, FxU32 texture_address, const SurfaceMask *mask,
                      const CasterDraw &draw);

// One shadow: a caster under a light.
struct ShadowJob {
  std::size_t caster = 0;  // index into scene.objects
  std::size_t light = 0;   // index into scene.lights
  LightView view;
  ShadowTexture texture;
  ReceiverCoords receivers;
  // The direct path: step 1's drawing (and the receiver whose surface masked it, an index into
  // FrameGeometry::objects) and the Glide state it began in, which load the texture into TMU
  // memory again the very same way.
  CasterDraw draw;
  std::optional<std::size_t> mask_receiver;
  // Every path: whether step 1 masked the caster by a receiver's farthest surface
  // (SurfaceMask::farthest), which the direct path's drawing again needs too.
  bool mask_farthest = false;
  std::vector<std::uint8_t> mask_triangles;  // SurfaceMask::triangles of that mask; empty: all
  GrState step1_state{};
};

// Step 2. The region read back with grLfbReadRegion and downloaded, the same 16-bit words, as
// GR_TEXFMT_ARGB_4444 (Listing 5); on the direct path the words are already in texture memory.
ShadowTexture make_shadow_texture(const LightView &view, const ProjectedShadowOptions &options,
                                  FxU32 texture_address);
// Step 2 without the download (ShadowTexture::texels; nothing on the direct path), for a texture
// step 2 could not place in TMU memory.
ShadowTexture read_shadow_texture(const LightView &view, const ProjectedShadowOptions &options);
// The TMU0 address of `job`'s texture for a pass about to draw with it, loaded there first when
// `memory` says so (its read-back downloaded, or on the direct path step 1 drawn again, masked
// by `geometry`'s receiver); nothing when step 1 could not draw it (the shim's error says why).
std::optional<FxU32> bind_shadow_texture(const ShadowJob &job, ShadowTextureMemory &memory,
                                         const FrameGeometry &geometry);
// Step 3. Every receiver but the caster in the light's space: Listing 2's flags (facing the
// light, not wholly outside its view), clipped where it is nearer the light than the caster, and
// (s, t) from the light-space x, y in Glide's 0..256 units.
// `receivers`, when given, marks (per scene object) the receivers this texture is for.
// `depth_bands`, when given, keeps of each receiver only the part nearer the light than
// `caster_back` (light view depth, metres; -1), or only the part beyond it (+1), or all (0):
// a receiver whose surface masks the caster (pierced_receivers.h) takes the masked texture
// nearer than the caster's farthest point and the whole caster's beyond it, where every caster
// point on the light's ray lies in front of the receiver and shadows it. A triangle across that
// depth which no part of its receiver hides from the light takes the masked texture, uncut.
// Nearer than that depth, -1 keeps only the triangles no part of the receiver hides from the
// light (the texture masked by its nearest surface) and -2 only the others (the texture masked
// by its farthest light-facing surface, SurfaceMask::farthest). With `hidden` (hidden_layers'
// classes of the receiver in band -2 or -3, per mesh triangle), -2 keeps only kHiddenTwice and
// -3 only kHiddenOnce (the texture masked by the hidden triangles' nearest surface).
// `surfaces`, when given, holds the caster's surfaces from the light built by earlier textures.
// `over_buried`, when given, marks per triangle of the receiver in band -1 or -2 those in front of
// a caster part with a farther layer of it behind (ReceiverLayers::over_buried): band -1's.
// `caster_plane`, when given, is the caster's planar_caster for `light` (pierced_receivers.h),
// which the caller has; found here otherwise.
ReceiverCoords compute_receiver_coords(const Scene &scene, const FrameGeometry &frame,
                                       std::size_t caster, const SpotLight &light,
                                       const LightView &view, const ProjectedShadowOptions &options,
                                       const std::vector<bool> *receivers = nullptr,
                                       const std::vector<signed char> *depth_bands = nullptr,
                                       float caster_back = 0.0f,
                                       CasterSurfacesFromLight *surfaces = nullptr,
                                       const std::vector<std::uint8_t> *hidden = nullptr,
                                       const std::vector<std::uint8_t> *over_buried = nullptr,
                                       const std::optional<glm::vec4> *caster_plane = nullptr);
// Step 4 is render_scene (scene_pass.h).
// Step 5. The flagged triangles again with the shadow texture: clamp, bilinear, W-buffer a few
// codes nearer than step 4 with GR_CMP_LESS, alpha = texture alpha x iterated alpha, blended
// over the scene; every pixel it darkens is marked in the depth buffer, so the next shadow of
// the same light leaves it as it is (one darkening per light, however many shadows overlap).
// render_projected_shadows restores step 4's depth between lights.
void render_shadow_pass(const ShadowJob &job, const ProjectedShadowOptions &options);
// Step 5 for the shadows of one light, in order, each pixel darkened once (shadow_pass.cpp's
// depth levels); with filtered edges and overlapping shadows, every shadow's core (full texture
// alpha) before any shadow's soft edge, so an edge inside another's core leaves no lighter seam. Leaves marks in the depth buffer, a few codes nearer than step 4's surfaces.
// `bind` gives the TMU address of a job's texture, loading it there first if it must (nothing:
// it could not, and the job is left out).
using BindShadowTexture = std::function<std::optional<FxU32>(const ShadowJob &)>;
void render_light_shadow_passes(const std::vector<const ShadowJob *> &jobs,
                                const ProjectedShadowOptions &options,
                                const BindShadowTexture &bind);

// The side (texels) of the map the shadow of a caster (index into scene.objects) from a light
// (index into scene.lights) was drawn at.
struct DrawnShadowSize {
  std::size_t light = 0;
  std::size_t caster = 0;
  int size = 0;
};
// The size `sizes` holds for the caster and light; 0 when it holds none.
int drawn_shadow_size(const std::vector<DrawnShadowSize> &sizes, std::size_t light,
                      std::size_t caster);

struct ShadowFrame {
  StepTimes times;
  FrameGeometry geometry;             // step 4's projection of the scene
  std::vector<ShadowJob> jobs;        // one per caster and light that got a shadow
  std::vector<std::string> warnings;  // what the user should know, `errors` included
  std::vector<std::string> errors;    // casters left without a shadow they should cast, and why
  // Per caster and light whose shadow the frame casts (in `jobs`, or in none where no receiver
  // shows it): the size it was drawn at, the fitted one (LightView::size of the whole map) or
  // the larger one grow_to_accepted drew it at instead (a note among `warnings` says so).
  std::vector<DrawnShadowSize> sizes;
  // The most screen pixels a shadow texel spanned on its receivers (shadow_footprint), over
  // every caster and light, cast or refused (at the size cast: an attempt grown past,
  // grow_to_accepted, is not counted): what largest_texel_footprint_px bounds.
  float texel_footprint_px = 0.0f;
  // Where step 2 placed the jobs' textures in TMU0 memory (ShadowTexture::id). When they did not
  // all fit, or the slide textures took the memory of one, step 5 loaded textures
  // (`textures_loaded`), and each mask pass loads them again as it draws.
  ShadowTextureMemory textures;
  bool textures_loaded = false;
};

// The whole frame in the article's order, into the back buffer. With `synchronous`, each step
// ends with grSstIdle so its time includes the rendering it queued.
ShadowFrame render_projected_shadows(const Scene &scene, const ProjectedShadowOptions &options,
                                     bool synchronous);

// The shadow mask of a frame just rendered: white where the pixel is in shadow (technique.h: the
// filtered texture alpha at least half), black elsewhere, drawn into the back buffer over the
// frame's depth buffer (call before the next clear). Step 5 leaves marks in the depth buffer
// (one darkening per light), so this version draws the receivers a little nearer than step 4
// did (kSealCodes and a margin: about 0.2% of the distance), enough to pass them.
void render_shadow_mask(const ProjectedShadowOptions &options, const ShadowFrame &frame);
// The same for a frame of render_projected_shadows(scene, ...): step 4's depth is drawn again
// first (its frame.geometry), so the receivers are drawn at step 5's own depths.
void render_shadow_mask(const Scene &scene, const ProjectedShadowOptions &options,
                        const ShadowFrame &frame);

}  // namespace gs

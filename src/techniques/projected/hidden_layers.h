// The layers of a masked receiver that its own surface hides from the light (step 3's depth
// bands -2 and -3, projected_shadow.h). A triangle its own drawn surface hides (in part) takes a
// texture masked by another surface than the receiver's nearest; the texture masked by its
// farthest light-facing surface is exact only for the farthest layer on the light's ray. With a
// third layer (three stacked plates of one mesh, a pole through the middle one, or a triangle
// only partly hidden by a nearer plate), a caster part between a middle layer and the farthest
// would shadow the middle one, which the light reaches. The middle layer's triangles are those
// no other hidden triangle hides: for them the texture masked by the hidden triangles' own
// nearest surface is exact (at each of their texels that surface is the triangle itself).
// Spaces: light clip (the texture's LightView::projection * view; w in metres along the light's
// axis).
#pragma once

#include "techniques/projected/projected_shadow.h"

#include <cstdint>
#include <vector>

namespace gs {

class CasterSurfacesFromLight;

enum HiddenLayer : std::uint8_t {
  kNotHidden = 0,    // no part of the receiver's drawn surface hides it: band -1
  kHiddenOnce = 1,   // hidden by its surface, but by no other hidden triangle: band -3
  kHiddenTwice = 2,  // hidden by a hidden triangle too: band -2
};

// Per triangle of `receiver`'s mesh (in its order), for the texture of `view`: the triangles
// that face the light and reach beyond the caster's front inside the view's square (those
// draw_mask_surface draws), classified as HiddenLayer; the rest kNotHidden. Empty when no
// triangle is kHiddenTwice or none kHiddenOnce may be in the caster's shadow: then the texture
// masked by the farthest surface serves every hidden triangle (band -2 alone), as it is exact
// for a second layer. `surfaces`: the caster's, whose receiver surface step 3 shares.
std::vector<std::uint8_t> hidden_layers(const ProjectedObject &receiver, const LightView &view,
                                        CasterSurfacesFromLight &surfaces);

// Band -1's triangles (`marks`, per triangle of `receiver`'s mesh, possibly shorter: those the
// caster passes through, or in front of a caster part with a farther layer behind,
// ReceiverLayers::over_buried) that face the light and that the receiver's own drawn surface
// hides in part, as step 3 asks it for the texture of `view`. Band -1's texture (masked by the
// receiver's nearest surface) drops the caster's part between the nearer surface and such a
// triangle, which shadows it (a cylinder through a dune crest and the dune's trough behind it
// from the light, sunk-extra-lights_18418): they take band -4's textures instead, one per
// layer, peeled from the light: layer 1 the ones no other of them hides, layer 2 those no
// other of the rest hides, and so on, each with the texture masked by the surface of its
// layer and the layers after it (exact for it: at each of its texels that surface is the
// triangle itself). Per triangle its layer (1 to kMarkedLayers; the last takes all that are
// left), kMarkedNeighbour, or 0 for the rest; empty when there is none.
inline constexpr std::uint8_t kMarkedLayers = 4;
// The light-facing triangles in no layer within two rings of neighbours (a corner shared) of
// one in a layer: they join every layer's mask, so that the filter's reach beyond a layer's
// triangle reads texels masked by the surface next to it, not the whole caster behind it (the
// layers' triangles alone left strips of false shadow along their sides: 0.296% interior in
// sk1_two_cylinders_lying_through_dunes against 0.064% before, 0.141% with one ring, 0.064%
// with two). A neighbour that hides a layer's triangle drops the caster's part behind it again,
// as band -1's texture did.
inline constexpr std::uint8_t kMarkedNeighbour = 0x80;
std::vector<std::uint8_t> hidden_marked(const ProjectedObject &receiver, const LightView &view,
                                        CasterSurfacesFromLight &surfaces,
                                        const std::vector<std::uint8_t> &marks);

// Band -4's passes over one texture, from hidden_marked's answer for `marks`.
struct MarkedPasses {
  std::vector<std::uint8_t> marked;          // hidden_marked's
  std::vector<std::uint8_t> band_one_marks;  // `marks` but the layers' triangles: band -1's
  int layers = 0;                            // 0: no band -4
  std::vector<std::uint8_t> taken, masking;  // set by layer_pass
  // The triangles layer `layer` (1 to `layers`) takes, and those whose surface masks its
  // texture (SurfaceMask::triangles): that layer's, the later ones' and kMarkedNeighbour's.
  void layer_pass(int layer);
};
MarkedPasses marked_passes(const ProjectedObject &receiver, const LightView &view,
                           CasterSurfacesFromLight &surfaces,
                           const std::vector<std::uint8_t> &marks);

}  // namespace gs

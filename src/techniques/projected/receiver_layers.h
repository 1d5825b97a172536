// A receiver that is not planar can lie between the light and part of a caster it does not
// touch (a drum's cap in front of a stick beside it), or hold a caster part between two of its
// own layers (a pole reaching over a ridge, its middle behind the ridge and above the floor; a
// plate buried whole in a shelf's slab over the floor of the same mesh).
// Seen from the light, per sample of the caster's edges: the first needs the texture masked by
// the receiver's surface (pierced_receivers.h) so the nearer layer stays lit; the second no
// single texture can serve: the projected technique gives the farther layer a texture masked by
// the receiver's farthest surface when the receiver casts nothing, and refuses one that casts by
// name (projected_shadow.cpp).
#pragma once

#include "techniques/projected/pierced_receivers.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gs {

struct ReceiverLayers {
  // Receivers (indices into scene.objects) whose light-facing surface, beyond the caster's
  // front, hides a sample of the caster from the light.
  std::vector<std::size_t> hiding;
  // Of those, the receivers where such a hidden sample lies outside the receiver (the nearest
  // surface in front of it faces away from the light) with a light-facing surface of the same
  // receiver behind it: that surface is in the sample's shadow, the nearer one is not.
  std::vector<std::size_t> between;
  // Per receiver the caster passes through (PiercedReceiver::receiver) with a caster sample
  // inside it: per triangle of its mesh, 1 where the triangle faces the light and lies in front
  // of such a sample that has a light-facing surface of the same receiver behind it. The
  // texture masked by the farthest surface (band -2) holds that sample, which is behind the
  // triangle and cannot shadow it (compute_receiver_coords' `over_buried`).
  std::vector<std::pair<std::size_t, std::vector<std::uint8_t>>> over_buried;
};

// Tests every non-planar receiver of `caster`'s shadow not already in `pierced` (and the
// non-planar pierced ones, for `between`) in the light's view `view` (step 1's, world in);
// none for a flat caster (`caster_plane`, its planar_caster for this light).
ReceiverLayers receiver_layers(const Scene &scene, const FrameGeometry &frame, std::size_t caster,
                               const LightView &view,
                               const std::vector<PiercedReceiver> &pierced,
                               const std::optional<glm::vec4> &caster_plane);

// The per-frame error for a receiver in ReceiverLayers::between.
std::string receiver_layers_error(const Scene &scene, std::size_t light, std::size_t caster,
                                  std::size_t receiver);

// The receivers `caster` reaches through (pierced_receivers.h), or that hide part of it from
// `light` (receiver_layers, in the light's view `view`): each takes a texture of its own, masked
// by its surface. One holding a caster part between two of its layers takes it too when it
// casts nothing: its nearer layer the texture masked by its nearest surface, the farther layer
// that its own surface hides the one masked by its farthest (step 3's depth band -2). One that
// casts gets no shadow, by name (a pole over a ridge of a floor that casts: 0.111% interior
// error served with the two textures): `refused`, named in `errors` (receiver_layers_error).
struct ReachedReceivers {
  std::vector<PiercedReceiver> pierced;
  ReceiverLayers layers;
  std::vector<std::size_t> refused;
};
ReachedReceivers reached_receivers(const Scene &scene, const FrameGeometry &frame,
                                   std::size_t light, std::size_t caster, const LightView &view,
                                   const std::optional<glm::vec4> &caster_plane,
                                   std::vector<std::string> &errors);

}  // namespace gs

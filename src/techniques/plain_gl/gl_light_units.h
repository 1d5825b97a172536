// A spotlight's beam map and exact distance attenuation, or a projector's slide, for the plain-GL
// techniques' lit passes (depth-map, stencil-volume), per pixel, as Segal et al. 3.1 and 3.2
// describe them on texture hardware: texture unit 2 holds the beam map (or the slide), projected by EYE_LINEAR texgen from the light's
// view (s/q, t/q over the cone); unit 3 holds the attenuation as a function of the light-space
// depth (s affine in the world), whose first texel is black so that nothing behind the light's
// near plane is lit (no back projection). Both modulate the fragment's colour. Spaces: the
// texgen planes act on the vertex arrays' coordinates (world positions, or world positions
// relative to an origin), given while the modelview matrix is the camera's view of them.
#pragma once

#include "techniques/plain_gl/gl_api.h"
#include "scene/scene.h"

namespace gs {

class GlLightUnits {
 public:
  // `farthest` is the largest light-space depth the attenuation must cover, metres; `origin` the
  // world point the vertex arrays' (0, 0, 0) stands for, when they hold world positions relative
  // to it. Makes the textures on unit 2 and leaves unit 0 active.
  GlLightUnits(const GlApi &gl, const SpotLight &light, float farthest,
               const glm::vec3 &origin = glm::vec3(0.0f));
  ~GlLightUnits();
  GlLightUnits(const GlLightUnits &) = delete;
  GlLightUnits &operator=(const GlLightUnits &) = delete;

  void bind();     // units 2 and 3; leaves unit 0 active
  void release();  // unbinds them, texgen off; leaves unit 0 active

  // Whether a light needs these units: it has a beam map or a slide.
  static bool needed_for(const SpotLight &light) {
    return light.has_beam_map() || light.is_projector();
  }

 private:
  const GlApi &gl_;
  const SpotLight &light_;
  float nearest_, farthest_;  // light-space depth range of the attenuation texture, metres
  glm::vec3 origin_;          // world
  GLuint beam_ = 0, attenuation_ = 0;
};

}  // namespace gs

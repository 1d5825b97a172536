// Where a light shines, per pixel, for the plain-GL techniques' shadow masks: texture unit
// `first` holds the light's footprint on its beam plane (the cone's disc, or where a beam map is
// not 0), projected by EYE_LINEAR texgen from the light's view; unit `first + 1` is the q gate, 0
// behind the light's plane so nothing there is projected back into the footprint. Both modulate
// the fragment's alpha, so with the alpha test at 1/2 a mask pass marks only pixels the light
// reaches. The footprint's texels hold 1/2 plus a share of their signed distance to the lit
// region's edge, so that bilinear filtering cuts on the edge itself, to within about 1/80 of a
// texel for a straight edge (a texel is about 1/500 of the beam plane's width). The texgen
// planes act on the vertex arrays' coordinates (world positions, or world positions relative to
// `origin`), given while the modelview matrix is the camera's view of them.
#pragma once

#include "scene/scene.h"
#include "techniques/plain_gl/gl_api.h"

namespace gs {

class GlBeamMask {
 public:
  // Makes the textures on unit `first`; leaves unit 0 active.
  GlBeamMask(const GlApi &gl, const SpotLight &light, int first,
             const glm::vec3 &origin = glm::vec3(0.0f));
  ~GlBeamMask();
  GlBeamMask(const GlBeamMask &) = delete;
  GlBeamMask &operator=(const GlBeamMask &) = delete;

  void bind();     // units first and first + 1; leaves unit 0 active
  void release();  // unbinds them, texgen off; leaves unit 0 active

 private:
  const GlApi &gl_;
  const SpotLight &light_;
  int first_;
  glm::vec3 origin_;
  GLuint footprint_ = 0, gate_ = 0;
};

}  // namespace gs

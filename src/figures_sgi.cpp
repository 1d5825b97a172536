// Segal et al. 1992's figures, drawn by the slide projector's passes (slide_projector.h) on the
// Glide shim. Spaces: world; the projector's square view (pixels, y down), whose 256 pixels
// span the 64-texel slide; the camera's screen.
#include "figures_kit.h"

#include "scene_pass.h"
#include "slide_projector.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace gs {
namespace {

// The scene of scenes/slide_projector.json: a floor, a box and a pillar, a checker slide from
// above-left and a rings slide from the right, a dim ambient light.
Scene projector_scene() {
  Scene scene;
  scene.width = kFigureWindowWidth;
  scene.height = kFigureWindowHeight;
  scene.ambient = glm::vec3(0.2f);
  scene.camera.position = glm::vec3(0.0f, 4.0f, 7.0f);
  scene.camera.target = glm::vec3(0.0f, 0.6f, 0.0f);
  scene.camera.fov_degrees = 50.0f;
  SpotLight checker;
  checker.position = glm::vec3(-2.5f, 5.0f, 2.0f);
  checker.target = glm::vec3(0.0f);
  checker.cone_degrees = 50.0f;
  checker.slide = "checker";
  SpotLight rings;
  rings.position = glm::vec3(3.0f, 4.0f, 1.0f);
  rings.target = glm::vec3(0.5f, 0.0f, 0.0f);
  rings.cone_degrees = 40.0f;
  rings.color = glm::vec3(1.0f, 0.9f, 0.7f);
  rings.slide = "rings";
  scene.lights = {checker, rings};
  SceneObject floor;
  floor.name = "floor";
  floor.mesh = make_plane(8.0f, 16);
  floor.mesh.set_color(glm::vec3(0.9f));
  SceneObject box;
  box.name = "box";
  box.mesh = make_box(glm::vec3(0.5f));
  box.mesh.set_color(glm::vec3(0.9f, 0.5f, 0.3f));
  box.model_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.5f, 0.0f));
  SceneObject pillar;
  pillar.name = "pillar";
  pillar.mesh = make_cylinder(0.3f, 1.6f, 24, true);
  pillar.mesh.set_color(glm::vec3(0.4f, 0.6f, 0.9f));
  pillar.model_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(1.6f, 0.0f, -0.5f));
  scene.objects = {floor, box, pillar};
  return scene;
}

}  // namespace

void figure_sgi_3(Figure &figure) {
  const Scene scene = projector_scene();
  render_scene(scene, project_scene(scene));
  const figures::Words frame = figures::read_back(scene.width, scene.height);
  figures::Words slide;
  int side = 0;
  slide.data = slide_texels(scene.lights[0], side);
  slide.width = slide.height = side;
  // The check: the scene seen from the checker projector itself, lit by it alone and by the
  // ambient light alone. Every surface it sees must be brightened exactly where the slide's
  // texel under that pixel is bright (its 256 pixels span the slide's side).
  Scene from_projector = figures::seen_from(scene, scene.lights[0].position, scene.lights[0].target,
                                            scene.lights[0].cone_degrees, 256);
  from_projector.lights.resize(1);
  from_projector.background = glm::vec3(0.0f);
  render_scene(from_projector, project_scene(from_projector));
  const figures::Words lit = figures::read_back(256, 256);
  Scene ambient_only = from_projector;
  ambient_only.lights.clear();
  render_scene(ambient_only, project_scene(ambient_only));
  const figures::Words ambient = figures::read_back(256, 256);
  long surfaces = 0, agree = 0;
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      if (ambient.at(x, y) == 0) continue;  // background
      // Away from the slide's edges, where bilinear filtering blends two texels: the texels
      // a texel either side are the same.
      const FxU16 texel = slide.at(x * side / 256, y * side / 256);
      const int reach = 256 / side;
      bool uniform = true;
      for (int dy = -reach; dy <= reach; dy += reach) {
        for (int dx = -reach; dx <= reach; dx += reach) {
          const int sx = std::clamp(x + dx, 0, 255) * side / 256, sy = std::clamp(y + dy, 0, 255) * side / 256;
          uniform = uniform && slide.at(sx, sy) == texel;
        }
      }
      if (!uniform) continue;
      ++surfaces;
      // The slide adds 1 to the ambient 0.2, six times the ambient level.
      const int before = (ambient.at(x, y) >> 5) & 0x3F, after = (lit.at(x, y) >> 5) & 0x3F;
      const bool brightened = 2 * after >= 5 * before;
      agree += brightened == (texel != 0);
    }
  }
  figure.image = figures::compose({{figures::magnified(figures::to_image(slide, 1.0f), 256 / std::max(side, 1)), "THE CHECKER SLIDE"},
                                   {figures::to_image(frame, figures::kListing4Gamma), "THE SCENE THROUGH TWO SLIDES"}});
  figure.shows = "Left: the 64x64 RGB 565 checker slide (its outer texel black, so clamp adds "
                 "nothing outside it). Right: the scene of scenes/slide_projector.json in the "
                 "paper's three passes (depth; ambient plus each slide where z is equal; times "
                 "the surface colour): a checker slide from the upper left and a rings slide "
                 "from the right.";
  figure.checks.push_back(figures::check(
      "the slide is projected onto the scene: seen from the projector, surfaces are brightened exactly where the slide is bright (>= 98% of pixels a texel away from the slide's edges)",
      surfaces > 10000 && agree * 100 >= surfaces * 98,
      figures::format("%ld of %ld surface pixels agree with the slide texel under them", agree, surfaces)));
}

}  // namespace gs

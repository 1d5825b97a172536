// The figures' shared helpers. Screen and texture images are read back as the raw 16-bit words
// the pipeline wrote (the LFB is exact), so the checks work on what the hardware stored; only
// the pictures go through the gamma table.
#include "figures/figures_kit.h"

#include "scene/fighter.h"
#include "measure/plot.h"
#include "techniques/light_passes/scene_pass.h"

#include <glide_shim.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdarg>

namespace gs::figures {

Words read_back(int width, int height, GrBuffer_t buffer) {
  Words words;
  words.width = width;
  words.height = height;
  words.data.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  grLfbReadRegion(buffer, 0, 0, static_cast<FxU32>(width), static_cast<FxU32>(height),
                  static_cast<FxU32>(width) * 2, words.data.data());
  return words;
}

long count(const Mask &mask) { return static_cast<long>(std::count(mask.begin(), mask.end(), 1)); }

long count_both(const Mask &a, const Mask &b) {
  long n = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) n += a[i] != 0 && b[i] != 0;
  return n;
}

Mask non_zero(const Words &words) {
  Mask mask(words.data.size());
  for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = words.data[i] != 0;
  return mask;
}

FigureImage to_image(const Words &words, float gamma) {
  std::array<int, 33> clut{};
  for (int i = 0; i < 32; ++i) {
    const double x = (i * 8) / 255.0;
    clut[static_cast<std::size_t>(i)] = static_cast<int>(std::lround(255.0 * std::pow(x, 1.0 / gamma)));
  }
  clut[32] = 255;
  auto scan_out = [&](unsigned channel) {  // an 8-bit channel through the CLUT
    const unsigned entry = channel >> 3, weight = channel & 7;
    return static_cast<std::uint8_t>((static_cast<unsigned>(clut[entry]) * (8 - weight) +
                                      static_cast<unsigned>(clut[entry + 1]) * weight) >> 3);
  };
  FigureImage image;
  image.width = words.width;
  image.height = words.height;
  image.rgb.resize(words.data.size() * 3);
  for (std::size_t i = 0; i < words.data.size(); ++i) {
    const unsigned p = words.data[i];
    const unsigned r5 = p >> 11, g6 = (p >> 5) & 0x3F, b5 = p & 0x1F;
    image.rgb[3 * i + 0] = scan_out((r5 << 3) | (r5 >> 2));
    image.rgb[3 * i + 1] = scan_out((g6 << 2) | (g6 >> 4));
    image.rgb[3 * i + 2] = scan_out((b5 << 3) | (b5 >> 2));
  }
  return image;
}

FigureImage magnified(const FigureImage &image, int factor) {
  FigureImage out = filled(image.width * factor, image.height * factor, 0, 0, 0);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        out.rgb[static_cast<std::size_t>((y * out.width + x) * 3 + c)] =
            image.rgb[static_cast<std::size_t>(((y / factor) * image.width + x / factor) * 3 + c)];
      }
    }
  }
  return out;
}

FigureImage filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  FigureImage image;
  image.width = width;
  image.height = height;
  image.rgb.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    image.rgb[i] = r, image.rgb[i + 1] = g, image.rgb[i + 2] = b;
  }
  return image;
}

FigureImage compose(const std::vector<Panel> &panels) {
  constexpr int kGap = 8, kLabelScale = 2, kLabelHeight = 5 * kLabelScale + 2 * kGap;
  int width = kGap, height = 0;
  for (const Panel &panel : panels) {
    width += std::max(panel.image.width, bitmap_text_width(panel.label, kLabelScale)) + kGap;
    height = std::max(height, panel.image.height);
  }
  FigureImage out = filled(width, height + kGap + kLabelHeight, 24, 24, 28);
  const unsigned char text_colour[3] = {230, 230, 230};
  int x = kGap;
  for (const Panel &panel : panels) {
    const int column = std::max(panel.image.width, bitmap_text_width(panel.label, kLabelScale));
    const int left = x + (column - panel.image.width) / 2;
    for (int row = 0; row < panel.image.height; ++row) {
      std::copy_n(panel.image.rgb.begin() + static_cast<std::ptrdiff_t>(row * panel.image.width * 3),
                  panel.image.width * 3,
                  out.rgb.begin() + static_cast<std::ptrdiff_t>(((row + kGap) * out.width + left) * 3));
    }
    draw_bitmap_text(out.rgb, out.width, out.height,
                     x + (column - bitmap_text_width(panel.label, kLabelScale)) / 2,
                     height + 2 * kGap, panel.label, kLabelScale, text_colour);
    x += column + kGap;
  }
  return out;
}

FigureCheck check(const std::string &claim, bool passed, const std::string &measured) {
  return {claim, measured, passed};
}

std::string format(const char *pattern, ...) {
  char text[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(text, sizeof text, pattern, args);
  va_end(args);
  return text;
}

Words render_frame(const std::string &technique, const TechniqueOptions &options,
                   const Scene &scene, Words *mask) {
  std::string error;
  std::unique_ptr<ShadowTechnique> renderer = make_technique(technique, options, error);
  if (!renderer) return {};
  renderer->render(scene, false);
  Words frame = read_back(scene.width, scene.height);
  if (mask != nullptr) {
    renderer->render_mask(scene);
    *mask = read_back(scene.width, scene.height);
  }
  return frame;
}

std::string shadowed_by(const std::string &technique, FigureFault fault) {
  return fault == FigureFault::ShadowLeftOut ? "none" : technique;
}

Mask coverage(Scene scene, std::size_t index) {
  scene.lights.clear();
  scene.ambient = glm::vec3(1.0f);
  scene.background = glm::vec3(0.0f);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    scene.objects[i].mesh.set_color(glm::vec3(i == index ? 1.0f : 0.0f));
  }
  render_scene(scene, project_scene(scene));
  return non_zero(read_back(scene.width, scene.height));
}

Scene seen_from(Scene scene, const glm::vec3 &eye, const glm::vec3 &target, float fov_degrees,
                int size) {
  scene.camera.position = eye;
  scene.camera.target = target;
  // The same up vector the light's view takes (fit_light_view), so pixels line up with texels.
  const glm::vec3 axis = glm::normalize(target - eye);
  scene.camera.up = std::abs(axis.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  scene.camera.fov_degrees = fov_degrees;
  scene.camera.near_plane = 0.05f;
  scene.width = scene.height = size;
  return scene;
}

Scene article_scene() {
  Scene scene;
  scene.width = kFigureWindowWidth;
  scene.height = kFigureWindowHeight;
  scene.ambient = glm::vec3(0.3f);
  scene.background = glm::vec3(0.05f, 0.06f, 0.1f);
  SceneObject floor;
  floor.name = "floor";
  floor.mesh = make_plane(8.0f, 16);
  floor.mesh.set_color(glm::vec3(0.85f, 0.8f, 0.7f));
  floor.casts_shadow = false;
  scene.objects.push_back(std::move(floor));
  SceneObject step;
  step.name = "step";
  step.mesh = make_box(glm::vec3(0.6f, 0.25f, 0.6f));
  step.mesh.set_color(glm::vec3(0.5f, 0.65f, 0.85f));
  step.model_to_world = glm::translate(glm::mat4(1.0f), glm::vec3(1.1f, 0.25f, -1.0f));
  step.casts_shadow = false;
  scene.objects.push_back(std::move(step));
  SceneObject fighter;
  fighter.name = "fighter";
  const FighterPose pose = pose_for(Move::Guard, 0.0f);
  fighter.mesh = build_fighter(pose, glm::vec3(0.75f, 0.12f, 0.1f));
  fighter.shadow_mesh = build_fighter_lod(pose);
  fighter.receives_shadow = false;
  scene.objects.push_back(std::move(fighter));
  SpotLight light;
  light.position = glm::vec3(-2.2f, 4.2f, 2.6f);
  light.target = glm::vec3(0.0f, 0.9f, 0.0f);
  light.cone_degrees = 75.0f;
  scene.lights.push_back(light);
  scene.camera.position = glm::vec3(1.0f, 2.3f, 3.6f);
  scene.camera.target = glm::vec3(0.5f, 0.6f, -0.5f);
  scene.camera.fov_degrees = 45.0f;
  return scene;
}

double darkening(FxU16 unshadowed, FxU16 shadowed) {
  const int before = (unshadowed >> 5) & 0x3F, after = (shadowed >> 5) & 0x3F;
  return before == 0 ? 0.0 : static_cast<double>(before - after) / static_cast<double>(before);
}

}  // namespace gs::figures

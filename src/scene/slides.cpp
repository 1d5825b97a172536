// The slide projectors' slides (Segal et al. 1992, 3.1) as data: the built-in patterns and image
// files as RGB565 texels for the TMU, and as the colours the TMU reads back, for the renderers
// that sample a slide themselves. Texel rows from the top of the slide.
#include "scene/slides.h"

#include <cmath>

namespace gs {
namespace {

constexpr int kSlideSide = 64;  // built-in slides, texels

std::uint16_t rgb565(float r, float g, float b) {
  return static_cast<std::uint16_t>(static_cast<int>(r * 31.0f) << 11 |
                                    static_cast<int>(g * 63.0f) << 5 | static_cast<int>(b * 31.0f));
}

}  // namespace

bool is_slide_pattern(const std::string &name) {
  return name == "checker" || name == "rings" || name == "grid";
}

std::vector<std::uint16_t> slide_texels(const SpotLight &projector, int &side) {
  if (projector.slide_image) {
    const ProjectedImage &image = *projector.slide_image;
    side = image.side;
    std::vector<std::uint16_t> texels(static_cast<std::size_t>(side * side), 0);
    for (int y = 1; y < side - 1; ++y) {
      for (int x = 1; x < side - 1; ++x) {
        const glm::vec3 &c = image.rgb[static_cast<std::size_t>(y * side + x)];
        texels[static_cast<std::size_t>(y * side + x)] = rgb565(c.r, c.g, c.b);
      }
    }
    return texels;
  }
  side = kSlideSide;
  const std::string &name = projector.slide;
  std::vector<std::uint16_t> texels(kSlideSide * kSlideSide, 0);
  for (int y = 1; y < kSlideSide - 1; ++y) {
    for (int x = 1; x < kSlideSide - 1; ++x) {
      // Slide coordinates in [-1, 1], the centre at 0.
      const float u = (static_cast<float>(x) + 0.5f) / kSlideSide * 2.0f - 1.0f;
      const float v = (static_cast<float>(y) + 0.5f) / kSlideSide * 2.0f - 1.0f;
      std::uint16_t texel = 0;
      if (name == "checker") {
        texel = ((x / 8 + y / 8) % 2 == 0) ? rgb565(1, 1, 1) : 0;
      } else if (name == "rings") {
        const float r = std::sqrt(u * u + v * v);
        texel = r < 1.0f && static_cast<int>(r * 5.0f) % 2 == 0 ? rgb565(1.0f, 0.8f, 0.3f) : 0;
      } else {
        texel = (x % 8 == 0 || y % 8 == 0) ? rgb565(0.3f, 1.0f, 0.4f) : rgb565(0.1f, 0.1f, 0.4f);
      }
      texels[static_cast<std::size_t>(y * kSlideSide + x)] = texel;
    }
  }
  return texels;
}

ProjectedImage slide_image(const SpotLight &projector) {
  ProjectedImage image;
  const std::vector<std::uint16_t> texels = slide_texels(projector, image.side);
  image.rgb.reserve(texels.size());
  for (std::uint16_t t : texels) {
    const unsigned r = t >> 11, g = t >> 5 & 0x3F, b = t & 0x1F;
    image.rgb.emplace_back(static_cast<float>(r << 3 | r >> 2) / 255.0f,
                           static_cast<float>(g << 2 | g >> 4) / 255.0f,
                           static_cast<float>(b << 3 | b >> 2) / 255.0f);
  }
  return image;
}

}  // namespace gs

// The demo's scene at any moment of the fight: the ring, two fighters on its mat going through
// the fight loop, a spotlight above, and a camera circling the ring. The ring is built once.
#pragma once

#include "scene/scene.h"

namespace gs {

class FightScene {
 public:
  FightScene(int width, int height, int shadow_size);
  // The scene at `time` seconds; fighters and camera move, the ring and light stay.
  const Scene &at(float time);
  static constexpr std::size_t kRing = 0, kFighters[2] = {1, 2};

 private:
  Scene scene_;
};

}  // namespace gs

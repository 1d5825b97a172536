// The demo's scene at any moment of the fight: the ring, two fighters on its mat going through
// the fight loop, a low spotlight behind whichever fighter attacks, and a camera on the light's
// side of the pair that dollies in and out. The ring is built once.
#pragma once

#include "scene/scene.h"

namespace gs {

class FightScene {
 public:
  FightScene(int width, int height, int shadow_size);
  // The scene at `time` seconds; fighters, camera and light move, the ring stays.
  const Scene &at(float time);
  static constexpr std::size_t kRing = 0, kFighters[2] = {1, 2};

 private:
  Scene scene_;
};

// Where the spotlight stands at `time`: 0 behind the red fighter (fighter 0), 1 behind the blue
// one, between while it swings round the far side of the ring from one to the other.
float fight_light_side(float time);

}  // namespace gs

// Where a frame's shadow textures are in TMU0 memory (byte addresses). Step 2 places them one
// after another from the bottom while they fit, and each placed one stays there for the frame,
// as the article's frame keeps every texture it made. The rest wait outside TMU memory (step 2's
// read-back in system memory on the LFB path, step 1's draw on the direct path) and are loaded
// just before step 5 or the mask pass draws with them: into the memory after the last texture
// placed, then round from the bottom again over the textures loaded longest before (a placed one
// among them too), each of which is loaded again when a pass next needs it. Step 5 darkens each
// pixel by one texture at a time, so a texture need be in memory only while its own triangles
// are drawn. Plain bookkeeping, no Glide call: the caller loads what bind says to load.
#pragma once

#include <glide.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace gs {

class ShadowTextureMemory {
 public:
  ShadowTextureMemory() = default;
  ShadowTextureMemory(FxU32 low, FxU32 high);  // the memory [low, high)

  // Whether a texture of `bytes` fits the memory at all (with nothing else in it).
  bool can_hold(FxU32 bytes) const { return bytes <= high_ - low_; }
  // Step 2: the place after the last placed texture, kept for `texture` (an id of the caller's);
  // nothing when the rest of the memory is too small, and the texture is then loaded by bind.
  std::optional<FxU32> place(std::size_t texture, FxU32 bytes);
  // The textures placed since `mark` (an address place returned, or the next one) are given
  // up, and their memory is placed again.
  FxU32 mark() const { return next_; }
  void release_from(FxU32 mark);
  // How many times bind has said to load a texture.
  std::size_t loads() const { return loads_; }

  // Step 5 and the mask pass: where `texture` is, and whether the caller must load it there
  // before drawing with it (it was not placed, or something since took its memory).
  struct Slot {
    FxU32 address = 0;
    bool load = false;
  };
  Slot bind(std::size_t texture, FxU32 bytes);
  // [low, high) was written by someone else (slide textures): what was there must be loaded again.
  void forget(FxU32 low, FxU32 high);
  // Nothing is known to be in memory any more (a pass after others that loaded textures).
  void forget_all() { resident_.clear(); }
  // Whether `texture` is in memory now.
  bool holds(std::size_t texture) const;

 private:
  struct Resident {
    std::size_t texture;
    FxU32 address, bytes;
  };
  FxU32 low_ = 0, high_ = 0;
  FxU32 next_ = 0;  // where the next texture goes
  std::size_t loads_ = 0;
  std::vector<Resident> resident_;
};

}  // namespace gs

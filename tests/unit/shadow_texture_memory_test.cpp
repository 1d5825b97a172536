// ShadowTextureMemory (shadow_texture_memory.h): step 2 places textures one after another while
// they fit; the rest are loaded as a pass binds them, round the memory over the textures loaded
// longest before, and a texture whose memory was taken is loaded again when next bound. Byte
// addresses of a small memory, as TMU0's 2 MB would give them at 128 KB a texture.
#include "techniques/projected/shadow_texture_memory.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace {

constexpr FxU32 kTexture = 100;  // bytes of one texture here (a 256x256 ARGB_4444 is 131072)

// Four textures' memory, from 1000 (grTexMinAddress need not be 0).
gs::ShadowTextureMemory four() { return gs::ShadowTextureMemory(1000, 1000 + 4 * kTexture); }

TEST(ShadowTextureMemory, PlacesTexturesInTurnWhileTheyFit) {
  gs::ShadowTextureMemory memory = four();
  for (std::size_t t = 0; t < 4; ++t) {
    const std::optional<FxU32> at = memory.place(t, kTexture);
    ASSERT_TRUE(at) << t;
    EXPECT_EQ(*at, 1000 + t * kTexture);
  }
  EXPECT_FALSE(memory.place(4, kTexture)) << "a fifth does not fit";
  EXPECT_FALSE(memory.holds(4));
  // Placed textures stay where they are: binding them loads nothing.
  for (std::size_t t = 0; t < 4; ++t) {
    const gs::ShadowTextureMemory::Slot slot = memory.bind(t, kTexture);
    EXPECT_EQ(slot.address, 1000 + t * kTexture);
    EXPECT_FALSE(slot.load);
  }
  EXPECT_EQ(memory.loads(), 0u);
}

TEST(ShadowTextureMemory, ReleasedTexturesGiveTheirMemoryBack) {
  gs::ShadowTextureMemory memory = four();
  ASSERT_TRUE(memory.place(0, kTexture));
  const FxU32 mark = memory.mark();
  ASSERT_TRUE(memory.place(1, kTexture));
  ASSERT_TRUE(memory.place(2, kTexture));
  memory.release_from(mark);  // the caster of 1 and 2 is refused
  EXPECT_FALSE(memory.holds(1));
  EXPECT_FALSE(memory.holds(2));
  EXPECT_EQ(memory.place(3, kTexture), std::optional<FxU32>(1000 + kTexture));
}

TEST(ShadowTextureMemory, TexturesLeftOutAreLoadedRoundTheMemoryAndAgainWhenTaken) {
  // Six textures in room for four: 0..3 placed, 4 and 5 not.
  gs::ShadowTextureMemory memory = four();
  for (std::size_t t = 0; t < 6; ++t) memory.place(t, kTexture);
  // A pass draws with 0..5 in turn: 4 takes the bottom (0's memory), 5 the next (1's).
  std::vector<gs::ShadowTextureMemory::Slot> first;
  for (std::size_t t = 0; t < 6; ++t) first.push_back(memory.bind(t, kTexture));
  for (std::size_t t = 0; t < 4; ++t) EXPECT_FALSE(first[t].load) << t;
  EXPECT_TRUE(first[4].load);
  EXPECT_EQ(first[4].address, 1000u);
  EXPECT_TRUE(first[5].load);
  EXPECT_EQ(first[5].address, 1000 + kTexture);
  EXPECT_FALSE(memory.holds(0));
  EXPECT_FALSE(memory.holds(1));
  // A second pass in the same order: 0 and 1 are loaded again (over 2 and 3), then 2 and 3
  // (over 4 and 5), then 4 and 5; every load goes where the bookkeeping said, never over a
  // texture the same bind still needs.
  for (std::size_t t = 0; t < 6; ++t) {
    const gs::ShadowTextureMemory::Slot slot = memory.bind(t, kTexture);
    EXPECT_TRUE(slot.load) << t;
    EXPECT_EQ(slot.address, 1000 + ((t + 2) % 4) * kTexture) << t;
    EXPECT_TRUE(memory.holds(t));
  }
  EXPECT_EQ(memory.loads(), 2u + 6u);
  // Whatever was loaded, at most four textures are held, none two in one place.
  std::size_t held = 0;
  for (std::size_t t = 0; t < 6; ++t) held += memory.holds(t);
  EXPECT_EQ(held, 4u);
}

TEST(ShadowTextureMemory, SmallerTexturesShareTheRoomOfALargerOne) {
  gs::ShadowTextureMemory memory = four();
  for (std::size_t t = 0; t < 4; ++t) memory.place(t, kTexture);
  // Two half-size textures loaded: both in texture 0's memory, which alone is taken.
  const gs::ShadowTextureMemory::Slot a = memory.bind(10, kTexture / 2);
  const gs::ShadowTextureMemory::Slot b = memory.bind(11, kTexture / 2);
  EXPECT_EQ(a.address, 1000u);
  EXPECT_EQ(b.address, 1000 + kTexture / 2);
  EXPECT_FALSE(memory.holds(0));
  for (std::size_t t = 1; t < 4; ++t) EXPECT_TRUE(memory.holds(t)) << t;
}

TEST(ShadowTextureMemory, MemoryWrittenBySomeoneElseIsLoadedAgain) {
  gs::ShadowTextureMemory memory = four();
  for (std::size_t t = 0; t < 4; ++t) memory.place(t, kTexture);
  memory.forget(1000 + 2 * kTexture + 10, 1000 + 2 * kTexture + 20);  // inside texture 2
  EXPECT_FALSE(memory.holds(2));
  EXPECT_TRUE(memory.holds(1));
  EXPECT_TRUE(memory.holds(3));
  const gs::ShadowTextureMemory::Slot slot = memory.bind(2, kTexture);
  EXPECT_TRUE(slot.load);
  memory.forget_all();
  for (std::size_t t = 0; t < 4; ++t) EXPECT_FALSE(memory.holds(t)) << t;
}

TEST(ShadowTextureMemory, OnlyATextureLargerThanTheMemoryCannotBeHeld) {
  const gs::ShadowTextureMemory memory = four();
  EXPECT_TRUE(memory.can_hold(4 * kTexture));
  EXPECT_FALSE(memory.can_hold(4 * kTexture + 8));
}

}  // namespace

// The bookkeeping of shadow_texture_memory.h: byte addresses in TMU0 memory, nothing drawn.
#include "techniques/projected/shadow_texture_memory.h"

#include <algorithm>

namespace gs {

ShadowTextureMemory::ShadowTextureMemory(FxU32 low, FxU32 high)
    : low_(low), high_(std::max(low, high)), next_(low) {}

std::optional<FxU32> ShadowTextureMemory::place(std::size_t texture, FxU32 bytes) {
  if (bytes > high_ - next_) return std::nullopt;
  const FxU32 address = next_;
  resident_.push_back({texture, address, bytes});
  next_ += bytes;
  return address;
}

void ShadowTextureMemory::release_from(FxU32 mark) {
  resident_.erase(std::remove_if(resident_.begin(), resident_.end(),
                                 [mark](const Resident &r) { return r.address >= mark; }),
                  resident_.end());
  next_ = mark;
}

ShadowTextureMemory::Slot ShadowTextureMemory::bind(std::size_t texture, FxU32 bytes) {
  const auto found = std::find_if(resident_.begin(), resident_.end(),
                                  [texture](const Resident &r) { return r.texture == texture; });
  if (found != resident_.end()) return {found->address, false};
  // Round the memory: after the last texture placed or loaded, else from the bottom again.
  if (bytes > high_ - next_) next_ = low_;
  const FxU32 address = next_;
  forget(address, address + bytes);
  resident_.push_back({texture, address, bytes});
  next_ += bytes;
  ++loads_;
  return {address, true};
}

void ShadowTextureMemory::forget(FxU32 low, FxU32 high) {
  resident_.erase(std::remove_if(resident_.begin(), resident_.end(),
                                 [low, high](const Resident &r) {
                                   return r.address < high && low < r.address + r.bytes;
                                 }),
                  resident_.end());
}

bool ShadowTextureMemory::holds(std::size_t texture) const {
  return std::any_of(resident_.begin(), resident_.end(),
                     [texture](const Resident &r) { return r.texture == texture; });
}

}  // namespace gs

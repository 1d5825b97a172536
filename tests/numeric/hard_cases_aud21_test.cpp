// Issue 14, aud21: the fourteenth audit's grazing-extra-lights_21107 (160x120, three lights; a
// box and a sphere both cast and receive, a capped cylinder casts, over the ring). Light 0 stands
// 0.4 m from box1 (cone 24.8 degrees, 256 texels at this screen), and the box's cut through the
// sphere lands up to 674,000 texels past the light's 256-texel screen. The strips beside a cut
// (projected/contact_strips.cpp) cast rays on a half-texel grid along the whole cut: 32 million
// rays for one cut, and the frame did not finish (the audit's sweep stood on it for an hour; a
// render of the projected technique alone was still running after 30 s, where it takes 1 s).
// Now a cut is clipped to the light's screen grown by a ray's reach first. Every technique is
// right here (0.000% interior error), so the check is that each projected technique serves it
// within the budget, or refuses naming a light; before the fix it does not return.
// Scene in tests/hard_cases/audit (aud21_*; README, "A cut far past the light's screen (aud21)").
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

// Three lights: only_in_beam off (shadow_where_unlit asks light 0 alone); the check asks the truth
// for at least 150 shadow pixels.
TEST(HardCases, CutFarPastTheLightsScreenIsCastAndRight) {
  const std::string file = "audit/aud21_cut_far_past_light_screen.json";
  expect_these_right_or_refused(file, load(file), kProjectedTechniques, {}, false,
                                Leeway{150, "light"});
}

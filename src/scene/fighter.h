// The articulated fighters of the demo: a skeleton of rigid limbs (about 1,500 triangles, as
// on the arcade boards of the article), posed by joint angles and animated through a fight loop.
// Model space: feet on y = 0, facing +z, about 1.8 m tall.
#pragma once

#include "scene/mesh.h"

#include <string>

namespace gs {

enum class Move { Guard, Punch, Kick, Step, HitReaction };

// Joint angles in radians; positive x rotation lifts a limb forward.
struct FighterPose {
  float hips_height = 0.95f;   // pelvis above the feet, metres
  float torso_lean = 0.0f;     // about x
  float torso_twist = 0.0f;    // about y
  float head_nod = 0.0f;
  glm::vec2 shoulder[2] = {};  // [left, right]: (forward swing about x, sideways about z)
  float elbow[2] = {};
  glm::vec2 hip[2] = {};       // (forward swing, sideways)
  float knee[2] = {};
  glm::vec3 root_offset = {};  // model-space translation of the whole body (a step)
};

// The pose of `move` at phase 0..1 (0 and 1 are the guard pose, so moves chain smoothly).
FighterPose pose_for(Move move, float phase);
bool move_from_name(const std::string &name, Move &move);  // "guard", "punch", ...

// The fight loop: what fighter 0 or 1 does at `time` seconds. The two fighters face each other
// and alternate attacks and hit reactions; the loop repeats every fight_loop_seconds().
FighterPose fight_loop_pose(int fighter, float time);
float fight_loop_seconds();

// The full mesh (about 1,500 triangles) and a simplified one for the shadow pass (the article's
// LOD mesh, a few hundred triangles), both in model space with the fighter's colours.
Mesh build_fighter(const FighterPose &pose, const glm::vec3 &body_color);
Mesh build_fighter_lod(const FighterPose &pose);

}  // namespace gs

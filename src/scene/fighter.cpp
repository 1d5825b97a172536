// The fighters: a skeleton of rigid parts posed by forward kinematics, the moves as key poses
// eased into one another, the fight loop's schedule, and the full and shadow-pass (LOD) meshes
// built from the same parts at two tessellations. Model space throughout: feet on y = 0,
// facing +z, so the fighter's left is +x.
#include "scene/fighter.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

namespace gs {
namespace {

constexpr int kLeft = 0, kRight = 1;
constexpr float kSideX[2] = {1.0f, -1.0f};  // facing +z, the left side is +x

// Body measurements in metres, bone space (a bone's joint at its origin, its limb along -y).
constexpr float kHipHalfSpacing = 0.095f;  // hip joints either side of the pelvis centre
constexpr float kThighLength = 0.44f;
constexpr float kShinLength = 0.42f;
// The ankle joint above the sole: with straight legs the hips stand 0.44 + 0.42 + 0.09 = 0.95 m
// up, FighterPose's default.
constexpr float kAnkleHeight = 0.09f;
constexpr float kWaistHeight = 0.10f;  // torso pivot above the hip joints
constexpr float kShoulderHalfWidth = 0.20f;
constexpr float kShoulderHeight = 0.43f;  // above the waist
constexpr float kNeckBase = 0.44f;
constexpr float kNeckTop = 0.53f;  // the head's pivot, above the waist
constexpr float kUpperArmLength = 0.29f;
constexpr float kForearmLength = 0.25f;

const glm::vec3 kAxisX(1.0f, 0.0f, 0.0f);
const glm::vec3 kAxisY(0.0f, 1.0f, 0.0f);
const glm::vec3 kAxisZ(0.0f, 0.0f, 1.0f);

// Each frame maps its bone's space to model space.
struct Skeleton {
  glm::mat4 pelvis, torso, head;
  glm::mat4 upper_arm[2], forearm[2], thigh[2], shin[2], foot[2];
};

// A hanging limb at `joint`: (swing, spread) lift it forward (a negative turn about x takes -y
// towards +z) and then away from the body towards its own side (about z).
glm::mat4 limb_frame(const glm::mat4 &joint, const glm::vec2 &swing_and_spread, float side_x) {
  const glm::mat4 spread = glm::rotate(joint, side_x * swing_and_spread.y, kAxisZ);
  return glm::rotate(spread, -swing_and_spread.x, kAxisX);
}

Skeleton solve_skeleton(const FighterPose &pose) {
  Skeleton bones;
  bones.pelvis =
      glm::translate(glm::mat4(1.0f), pose.root_offset + glm::vec3(0.0f, pose.hips_height, 0.0f));
  // A positive lean tips the top of the torso (and a positive nod the head) towards +z; a
  // positive twist brings the right shoulder forward.
  const glm::mat4 waist = glm::translate(bones.pelvis, {0.0f, kWaistHeight, 0.0f});
  bones.torso = glm::rotate(glm::rotate(waist, pose.torso_twist, kAxisY), pose.torso_lean, kAxisX);
  bones.head =
      glm::rotate(glm::translate(bones.torso, {0.0f, kNeckTop, 0.0f}), pose.head_nod, kAxisX);
  for (int side = 0; side < 2; ++side) {
    const float x = kSideX[side];
    bones.upper_arm[side] =
        limb_frame(glm::translate(bones.torso, {x * kShoulderHalfWidth, kShoulderHeight, 0.0f}),
                   pose.shoulder[side], x);
    // The elbow folds the forearm forward and up, the knee folds the shin backwards.
    bones.forearm[side] =
        glm::rotate(glm::translate(bones.upper_arm[side], {0.0f, -kUpperArmLength, 0.0f}),
                    -pose.elbow[side], kAxisX);
    bones.thigh[side] = limb_frame(glm::translate(bones.pelvis, {x * kHipHalfSpacing, 0.0f, 0.0f}),
                                   pose.hip[side], x);
    bones.shin[side] = glm::rotate(glm::translate(bones.thigh[side], {0.0f, -kThighLength, 0.0f}),
                                   pose.knee[side], kAxisX);
    // The ankle keeps the sole level, so the foot only moves with the ankle (model space).
    const glm::vec3 ankle(bones.shin[side] * glm::vec4(0.0f, -kShinLength, 0.0f, 1.0f));
    bones.foot[side] = glm::translate(glm::mat4(1.0f), ankle);
  }
  return bones;
}

// `pose` with hips_height chosen so that the lower sole rests at root_offset.y (model space):
// the legs decide how high the body stands, so every pose keeps a foot on the floor.
FighterPose planted(FighterPose pose) {
  pose.hips_height = 0.0f;
  const Skeleton bones = solve_skeleton(pose);
  const float lowest_sole =
      std::min(bones.foot[kLeft][3].y, bones.foot[kRight][3].y) - kAnkleHeight;
  pose.hips_height = pose.root_offset.y - lowest_sole;
  return pose;
}

// Orthodox stance: left foot and left fist lead, fists in front of the chin, knees soft.
FighterPose guard_pose() {
  FighterPose pose;
  pose.torso_lean = 0.06f;
  pose.head_nod = 0.05f;
  pose.shoulder[kLeft] = {0.65f, 0.22f};
  pose.elbow[kLeft] = 1.85f;
  pose.shoulder[kRight] = {0.5f, 0.25f};
  pose.elbow[kRight] = 2.05f;
  pose.hip[kLeft] = {0.28f, 0.07f};
  pose.knee[kLeft] = 0.38f;
  pose.hip[kRight] = {-0.18f, 0.06f};  // both legs reach 0.841 m down: both feet on the floor
  pose.knee[kRight] = 0.06f;
  return planted(pose);
}

struct Key {
  float phase;  // 0..1 through the move
  FighterPose pose;
};

// The key poses of each move; the first and last are the guard, so moves chain smoothly.
std::vector<Key> keys_of(Move move) {
  const FighterPose guard = guard_pose();
  switch (move) {
    case Move::Guard:
      break;
    case Move::Punch: {  // a right cross: the right arm straight along +z, shoulder turned in
      FighterPose extended = guard;
      extended.torso_twist = 0.22f;
      extended.torso_lean = 0.1f;
      extended.shoulder[kRight] = {1.62f, 0.0f};  // 1.62 - lean 0.1: just below horizontal
      extended.elbow[kRight] = 0.02f;
      extended.shoulder[kLeft] = {0.5f, 0.3f};
      extended.elbow[kLeft] = 2.1f;
      extended.hip[kRight] = {-0.3f, 0.07f};  // the rear leg drives
      extended.knee[kRight] = 0.05f;
      extended.root_offset.z = 0.1f;  // a short lunge
      return {{0.0f, guard}, {0.45f, extended}, {0.6f, extended}, {1.0f, guard}};
    }
    case Move::Kick: {  // a right front kick: chamber the knee, extend, chamber again
      FighterPose chamber = guard;
      chamber.hip[kRight] = {1.2f, 0.05f};
      chamber.knee[kRight] = 1.7f;
      chamber.hip[kLeft] = {0.1f, 0.07f};  // the standing leg
      chamber.knee[kLeft] = 0.35f;
      chamber.torso_lean = -0.1f;
      FighterPose extended = chamber;
      extended.hip[kRight] = {1.45f, 0.0f};
      extended.knee[kRight] = 0.1f;
      extended.torso_lean = -0.28f;  // leaning back for balance
      extended.shoulder[kLeft] = {0.55f, 0.4f};
      extended.shoulder[kRight] = {0.35f, 0.45f};
      extended.elbow[kRight] = 1.7f;
      return {{0.0f, guard},     {0.3f, chamber},  {0.5f, extended},
              {0.62f, extended}, {0.82f, chamber}, {1.0f, guard}};
    }
    case Move::Step: {  // in with the lead (left) foot, 0.4 m forward, out with the rear foot
      FighterPose lead_foot_up = guard;
      lead_foot_up.hip[kLeft] = {0.7f, 0.07f};
      lead_foot_up.knee[kLeft] = 1.3f;
      lead_foot_up.hip[kRight] = {-0.3f, 0.07f};
      lead_foot_up.knee[kRight] = 0.2f;
      lead_foot_up.root_offset.z = 0.2f;
      FighterPose stepped_in = guard;
      stepped_in.root_offset.z = 0.4f;
      FighterPose rear_foot_up = guard;
      rear_foot_up.hip[kRight] = {0.25f, 0.07f};
      rear_foot_up.knee[kRight] = 1.2f;
      rear_foot_up.root_offset.z = 0.2f;
      return {{0.0f, guard},
              {0.25f, lead_foot_up},
              {0.5f, stepped_in},
              {0.75f, rear_foot_up},
              {1.0f, guard}};
    }
    case Move::HitReaction: {  // snapped back: torso and head back, arms dropped, pushed -z
      FighterPose recoil = guard;
      recoil.torso_lean = -0.42f;
      recoil.torso_twist = -0.15f;
      recoil.head_nod = -0.35f;
      recoil.shoulder[kLeft] = {0.15f, 0.35f};
      recoil.shoulder[kRight] = {0.1f, 0.4f};
      recoil.elbow[kLeft] = 0.4f;
      recoil.elbow[kRight] = 0.3f;
      recoil.hip[kLeft] = {0.4f, 0.1f};
      recoil.knee[kLeft] = 0.6f;
      recoil.root_offset.z = -0.12f;
      FighterPose staggered = recoil;
      staggered.torso_lean = -0.3f;
      staggered.head_nod = -0.15f;
      staggered.shoulder[kLeft] = {0.25f, 0.3f};
      staggered.shoulder[kRight] = {0.25f, 0.3f};
      staggered.elbow[kLeft] = 0.6f;
      staggered.elbow[kRight] = 0.5f;
      staggered.root_offset.z = -0.18f;
      return {{0.0f, guard}, {0.3f, recoil}, {0.55f, staggered}, {1.0f, guard}};
    }
  }
  return {{0.0f, guard}};  // the guard, and any value outside the enum: one key, held
}

// a * (1 - t) + b * t, field by field: exactly `a` at t = 0 and exactly `b` at t = 1, so a move
// begins and ends on the guard pose bit for bit.
FighterPose blend(const FighterPose &a, const FighterPose &b, float t) {
  const auto mix = [t](const auto &from, const auto &to) { return from * (1.0f - t) + to * t; };
  FighterPose out;
  out.torso_lean = mix(a.torso_lean, b.torso_lean);
  out.torso_twist = mix(a.torso_twist, b.torso_twist);
  out.head_nod = mix(a.head_nod, b.head_nod);
  for (int side = 0; side < 2; ++side) {
    out.shoulder[side] = mix(a.shoulder[side], b.shoulder[side]);
    out.elbow[side] = mix(a.elbow[side], b.elbow[side]);
    out.hip[side] = mix(a.hip[side], b.hip[side]);
    out.knee[side] = mix(a.knee[side], b.knee[side]);
  }
  out.root_offset = mix(a.root_offset, b.root_offset);
  return planted(out);
}

struct ScheduledMove {
  int fighter;
  Move move;
  float start, duration;  // seconds into the loop
};

// Fighter 0 steps in and throws a right (full reach at 2.05 s) that snaps fighter 1 back;
// fighter 1 steps in and front-kicks (full reach at 5.35 s), fighter 0 reels; both then hold
// their guard until the loop restarts. Every move starts and ends in the guard, so the loop
// is continuous at each boundary and at the wrap.
constexpr ScheduledMove kFightLoop[] = {
    {0, Move::Step, 0.2f, 1.2f},         // 0.4 m in and back out
    {0, Move::Punch, 1.6f, 1.0f},        // full reach 2.05-2.2 s
    {1, Move::HitReaction, 2.0f, 1.2f},  // snapped back hardest at 2.36 s
    {1, Move::Step, 3.4f, 1.2f},         // towards fighter 0
    {1, Move::Kick, 4.6f, 1.5f},         // full reach 5.35-5.53 s
    {0, Move::HitReaction, 5.3f, 1.2f},  // the last move ends at 6.5 s
};
constexpr float kFightLoopSeconds = 8.0f;

// The parts' tessellations: the full mesh for the eye, the coarse one for the shadow pass.
struct Tessellation {
  int head_slices, head_stacks;
  int trunk_slices;                // pelvis, abdomen, chest
  int limb_slices;                 // arms, legs, neck
  int joint_slices, joint_stacks;  // shoulders, elbows, knees
  int glove_slices, glove_stacks;
};
constexpr Tessellation kFullDetail{14, 10, 14, 10, 8, 6, 10, 7};
constexpr Tessellation kShadowDetail{6, 4, 5, 4, 4, 3, 4, 4};

struct Palette {
  glm::vec3 skin, body, dark;  // head and arms; torso, trunks and legs; gloves and feet
};

// A closed cylinder in `bone` space from y = bottom to y = top, elliptical: radii in x and z.
void add_cylinder(Mesh &mesh, const glm::mat4 &bone, float bottom, float top,
                  const glm::vec2 &radii, int slices, const glm::vec3 &color) {
  Mesh part = make_cylinder(1.0f, 1.0f, slices, true);
  part.set_color(color);
  const glm::mat4 placed = glm::translate(bone, {0.0f, bottom, 0.0f});
  mesh.append(part, glm::scale(placed, {radii.x, top - bottom, radii.y}));
}

// A closed ellipsoid centred at `centre` in `bone` space.
void add_ellipsoid(Mesh &mesh, const glm::mat4 &bone, const glm::vec3 &centre,
                   const glm::vec3 &radii, int slices, int stacks, const glm::vec3 &color) {
  Mesh part = make_sphere(1.0f, slices, stacks);
  part.set_color(color);
  mesh.append(part, glm::scale(glm::translate(bone, centre), radii));
}

void add_box(Mesh &mesh, const glm::mat4 &bone, const glm::vec3 &centre,
             const glm::vec3 &half_extents, const glm::vec3 &color) {
  Mesh part = make_box(half_extents);
  part.set_color(color);
  mesh.append(part, glm::translate(bone, centre));
}

// Every part is its own closed primitive; joints are covered by spheres so bent limbs show
// no gaps. Lengths and radii are the same at every tessellation, so the LOD keeps the outline.
Mesh build_parts(const FighterPose &pose, const Tessellation &detail, const Palette &palette) {
  const Skeleton bones = solve_skeleton(pose);
  Mesh mesh;
  add_cylinder(mesh, bones.pelvis, -0.09f, 0.15f, {0.165f, 0.11f}, detail.trunk_slices,
               palette.body);  // trunks
  add_cylinder(mesh, bones.torso, 0.0f, 0.24f, {0.14f, 0.1f}, detail.trunk_slices,
               palette.body);  // abdomen
  add_cylinder(mesh, bones.torso, 0.17f, 0.47f, {0.18f, 0.115f}, detail.trunk_slices,
               palette.body);  // chest
  add_cylinder(mesh, bones.torso, kNeckBase, kNeckTop + 0.05f, {0.05f, 0.05f}, detail.limb_slices,
               palette.skin);  // neck, reaching into the head
  add_ellipsoid(mesh, bones.head, {0.0f, 0.12f, 0.01f}, {0.1f, 0.12f, 0.11f}, detail.head_slices,
                detail.head_stacks, palette.skin);
  for (int side = 0; side < 2; ++side) {
    add_ellipsoid(mesh, bones.upper_arm[side], glm::vec3(0.0f), glm::vec3(0.062f),
                  detail.joint_slices, detail.joint_stacks, palette.skin);  // shoulder
    add_cylinder(mesh, bones.upper_arm[side], -kUpperArmLength, 0.0f, glm::vec2(0.048f),
                 detail.limb_slices, palette.skin);
    add_ellipsoid(mesh, bones.upper_arm[side], {0.0f, -kUpperArmLength, 0.0f}, glm::vec3(0.044f),
                  detail.joint_slices, detail.joint_stacks, palette.skin);  // elbow
    add_cylinder(mesh, bones.forearm[side], -kForearmLength, 0.0f, glm::vec2(0.04f),
                 detail.limb_slices, palette.skin);
    add_ellipsoid(mesh, bones.forearm[side], {0.0f, -kForearmLength - 0.04f, 0.0f},
                  {0.055f, 0.07f, 0.06f}, detail.glove_slices, detail.glove_stacks,
                  palette.dark);  // glove
    add_cylinder(mesh, bones.thigh[side], -kThighLength, 0.0f, glm::vec2(0.072f),
                 detail.limb_slices, palette.body);
    add_ellipsoid(mesh, bones.thigh[side], {0.0f, -kThighLength, 0.0f}, glm::vec3(0.056f),
                  detail.joint_slices, detail.joint_stacks, palette.body);  // knee
    add_cylinder(mesh, bones.shin[side], -kShinLength, 0.0f, glm::vec2(0.052f), detail.limb_slices,
                 palette.body);
    // The sole is kAnkleHeight below the ankle; the toes point along +z.
    add_box(mesh, bones.foot[side], {0.0f, -0.5f * kAnkleHeight, 0.05f},
            {0.05f, 0.5f * kAnkleHeight, 0.12f}, palette.dark);
  }
  return mesh;
}

}  // namespace

FighterPose pose_for(Move move, float phase) {
  if (!(phase > 0.0f)) phase = 0.0f;  // also catches NaN
  if (phase > 1.0f) phase = 1.0f;
  const std::vector<Key> keys = keys_of(move);
  for (std::size_t i = 1; i < keys.size(); ++i) {
    if (phase <= keys[i].phase) {
      const Key &from = keys[i - 1];
      const float t = (phase - from.phase) / (keys[i].phase - from.phase);
      return blend(from.pose, keys[i].pose, t * t * (3.0f - 2.0f * t));  // eased in and out
    }
  }
  return keys.back().pose;
}

bool move_from_name(const std::string &name, Move &move) {
  struct Named {
    const char *name;
    Move move;
  };
  static constexpr Named kNames[] = {{"guard", Move::Guard},
                                     {"punch", Move::Punch},
                                     {"kick", Move::Kick},
                                     {"step", Move::Step},
                                     {"hit", Move::HitReaction}};
  for (const Named &named : kNames) {
    if (name == named.name) {
      move = named.move;
      return true;
    }
  }
  return false;
}

FighterPose fight_loop_pose(int fighter, float time) {
  float loop_time = std::fmod(time, kFightLoopSeconds);  // NaN for a non-finite time: guard
  if (loop_time < 0.0f) loop_time += kFightLoopSeconds;
  for (const ScheduledMove &scheduled : kFightLoop) {
    if (scheduled.fighter == fighter && loop_time >= scheduled.start &&
        loop_time < scheduled.start + scheduled.duration)
      return pose_for(scheduled.move, (loop_time - scheduled.start) / scheduled.duration);
  }
  return guard_pose();
}

float fight_loop_seconds() { return kFightLoopSeconds; }

Mesh build_fighter(const FighterPose &pose, const glm::vec3 &body_color) {
  const Palette palette{{0.87f, 0.66f, 0.52f}, body_color, 0.35f * body_color};
  return build_parts(pose, kFullDetail, palette);
}

Mesh build_fighter_lod(const FighterPose &pose) {
  // The shadow pass only needs the outline; neutral colours stand in for the body colour.
  const Palette palette{{0.87f, 0.66f, 0.52f}, glm::vec3(0.5f), glm::vec3(0.2f)};
  return build_parts(pose, kShadowDetail, palette);
}

}  // namespace gs

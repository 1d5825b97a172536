// The fighters (triangle budgets, closed parts, standing on y = 0, the LOD's outline, the moves
// and the fight loop) and the ring (its size, and a mat that is not flat and agrees with
// ring_mat_height). The built-in shapes and the OBJ loader: shapes_test.cpp.
#include "mesh_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "scene/fighter.h"
#include "scene/mesh.h"
#include "scene/ring.h"

namespace {

using namespace gs;
using namespace gs::mesh_checks;

constexpr Move kAllMoves[] = {Move::Guard, Move::Punch, Move::Kick, Move::Step, Move::HitReaction};
constexpr Move kAttacks[] = {Move::Punch, Move::Kick, Move::Step, Move::HitReaction};

// Lowest y among vertices on one side of the body (model space): +x is the fighter's left.
float lowest_y_on_side(const Mesh &mesh, float side_x) {
  float lowest = std::numeric_limits<float>::max();
  for (const glm::vec3 &p : mesh.positions)
    if (p.x * side_x > 0.02f) lowest = std::min(lowest, p.y);
  return lowest;
}

std::size_t farthest_forward(const Mesh &mesh) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < mesh.positions.size(); ++i)
    if (mesh.positions[i].z > mesh.positions[best].z) best = i;
  return best;
}

std::vector<float> joint_angles(const FighterPose &pose) {
  return {pose.torso_lean,    pose.torso_twist,   pose.head_nod,      pose.shoulder[0].x,
          pose.shoulder[0].y, pose.shoulder[1].x, pose.shoulder[1].y, pose.elbow[0],
          pose.elbow[1],      pose.hip[0].x,      pose.hip[0].y,      pose.hip[1].x,
          pose.hip[1].y,      pose.knee[0],       pose.knee[1]};
}

std::vector<float> placement(const FighterPose &pose) {  // metres, model space
  return {pose.hips_height, pose.root_offset.x, pose.root_offset.y, pose.root_offset.z};
}

float largest_difference(const std::vector<float> &a, const std::vector<float> &b) {
  float largest = 0.0f;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::abs(a[i] - b[i]));
  return largest;
}

bool same_pose(const FighterPose &a, const FighterPose &b) {
  return joint_angles(a) == joint_angles(b) && placement(a) == placement(b);
}

template <typename T>
bool same_bits(const std::vector<T> &a, const std::vector<T> &b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// ---- fighters ----------------------------------------------------------------------------------

TEST(Fighter, FullMeshHasAbout1500Triangles) {
  const std::size_t triangles = build_fighter(pose_for(Move::Guard, 0.0f), kRed).triangle_count();
  EXPECT_GE(triangles, 1300u);
  EXPECT_LE(triangles, 1800u);
}

TEST(Fighter, LodHasAFewHundredTriangles) {
  const std::size_t triangles = build_fighter_lod(pose_for(Move::Guard, 0.0f)).triangle_count();
  EXPECT_GE(triangles, 150u);
  EXPECT_LE(triangles, 450u);
}

// Every part is a closed primitive, so the whole fighter is a union of closed surfaces.
TEST(Fighter, PartsAreClosed) {
  for (const Move move : kAllMoves) {
    const FighterPose pose = pose_for(move, 0.5f);
    EXPECT_EQ(closed_surface_problem(build_fighter(pose, kRed)), "") << "move " << int(move);
    EXPECT_EQ(closed_surface_problem(build_fighter_lod(pose)), "") << "move " << int(move);
  }
}

TEST(Fighter, NormalsAreUnitLength) {
  const FighterPose pose = pose_for(Move::Kick, 0.4f);
  EXPECT_LT(worst_normal_length_error(build_fighter(pose, kRed)), 1e-5f);
  EXPECT_LT(worst_normal_length_error(build_fighter_lod(pose)), 1e-5f);
}

// Tolerance 1 cm: the lower foot's sole is placed on y = 0 exactly; nothing may sink below it.
TEST(Fighter, StandsOnTheFloorThroughEveryMove) {
  for (const Move move : kAllMoves) {
    for (int step = 0; step <= 20; ++step) {
      const float phase = static_cast<float>(step) / 20.0f;
      const Bounds bounds = bounds_of(build_fighter(pose_for(move, phase), kRed));
      EXPECT_NEAR(bounds.low.y, 0.0f, 0.01f) << "move " << int(move) << " phase " << phase;
    }
  }
}

TEST(Fighter, IsAbout1point8MetresTall) {
  const float height = bounds_of(build_fighter(pose_for(Move::Guard, 0.0f), kRed)).high.y;
  EXPECT_GE(height, 1.6f);
  EXPECT_LE(height, 2.0f);
}

// FighterPose's defaults (hips 0.95 m up, straight legs) stand the fighter on y = 0 too.
TEST(Fighter, DefaultPoseStandsOnTheFloor) {
  EXPECT_NEAR(bounds_of(build_fighter(FighterPose{}, kRed)).low.y, 0.0f, 1e-5f);
}

TEST(Fighter, ColoursSkinBodyAndDarkerGlovesAndFeet) {
  const Mesh fighter = build_fighter(pose_for(Move::Guard, 0.0f), kRed);
  const auto highest =
      std::max_element(fighter.positions.begin(), fighter.positions.end(),
                       [](const glm::vec3 &a, const glm::vec3 &b) { return a.y < b.y; });
  const auto lowest =
      std::min_element(fighter.positions.begin(), fighter.positions.end(),
                       [](const glm::vec3 &a, const glm::vec3 &b) { return a.y < b.y; });
  const glm::vec3 head = fighter.colors[highest - fighter.positions.begin()];
  const glm::vec3 foot = fighter.colors[lowest - fighter.positions.begin()];
  EXPECT_NE(head, kRed);
  EXPECT_LT(foot.r + foot.g + foot.b, kRed.r + kRed.g + kRed.b);
  EXPECT_NE(std::find(fighter.colors.begin(), fighter.colors.end(), kRed), fighter.colors.end());
}

// Tolerance 3 cm: the LOD's coarse polygons sit inside the full mesh's rounder ones by at most
// a radius times (1 - cos(pi / slices)), about 2 cm for the thighs at 4 slices.
TEST(Fighter, LodKeepsTheOutlineOfTheFullMesh) {
  for (const Move move : kAllMoves) {
    for (const float phase : {0.0f, 0.3f, 0.5f, 0.75f}) {
      const FighterPose pose = pose_for(move, phase);
      const Bounds full = bounds_of(build_fighter(pose, kRed));
      const Bounds lod = bounds_of(build_fighter_lod(pose));
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(lod.low[axis], full.low[axis], 0.03f) << int(move) << " " << phase;
        EXPECT_NEAR(lod.high[axis], full.high[axis], 0.03f) << int(move) << " " << phase;
      }
    }
  }
}

TEST(Fighter, BuildsAreBitIdentical) {
  const FighterPose pose = fight_loop_pose(1, 4.9f);
  const Mesh first = build_fighter(pose, kRed), second = build_fighter(pose, kRed);
  EXPECT_TRUE(same_bits(first.positions, second.positions));
  EXPECT_TRUE(same_bits(first.normals, second.normals));
  EXPECT_TRUE(same_bits(first.colors, second.colors));
  EXPECT_TRUE(same_bits(first.triangles, second.triangles));
  const Mesh first_lod = build_fighter_lod(pose), second_lod = build_fighter_lod(pose);
  EXPECT_TRUE(same_bits(first_lod.positions, second_lod.positions));
  EXPECT_TRUE(same_bits(first_lod.triangles, second_lod.triangles));
}

// ---- moves and the fight loop ------------------------------------------------------------------

TEST(Moves, StartAndEndInTheGuard) {
  const FighterPose guard = pose_for(Move::Guard, 0.0f);
  for (const Move move : kAllMoves) {
    EXPECT_TRUE(same_pose(pose_for(move, 0.0f), guard)) << "move " << int(move);
    EXPECT_TRUE(same_pose(pose_for(move, 1.0f), guard)) << "move " << int(move);
  }
}

TEST(Moves, EveryMoveLeavesTheGuardOnTheWay) {
  const FighterPose guard = pose_for(Move::Guard, 0.0f);
  for (const Move move : kAttacks)
    EXPECT_GT(largest_difference(joint_angles(pose_for(move, 0.3f)), joint_angles(guard)), 0.3f)
        << "move " << int(move);
}

// The right fist (the fighter's right is -x) leads: the farthest-forward point is at arm
// height on the right, well beyond the guard.
TEST(Moves, PunchExtendsTheRightFistForward) {
  const Mesh guard = build_fighter(pose_for(Move::Guard, 0.0f), kRed);
  const Mesh punch = build_fighter(pose_for(Move::Punch, 0.5f), kRed);
  const glm::vec3 fist = punch.positions[farthest_forward(punch)];
  EXPECT_GT(fist.z, guard.positions[farthest_forward(guard)].z + 0.25f);
  EXPECT_LT(fist.x, 0.0f);
  EXPECT_GT(fist.y, 1.1f);
  EXPECT_LT(fist.y, 1.7f);
}

TEST(Moves, KickRaisesTheRightFootForward) {
  const Mesh kick = build_fighter(pose_for(Move::Kick, 0.5f), kRed);
  const glm::vec3 foot = kick.positions[farthest_forward(kick)];
  EXPECT_GT(foot.z, 0.8f);
  EXPECT_LT(foot.x, 0.0f);
  EXPECT_GT(foot.y, 0.5f);
  EXPECT_GT(lowest_y_on_side(kick, -1.0f), 0.5f);          // the right foot is off the floor
  EXPECT_NEAR(lowest_y_on_side(kick, 1.0f), 0.0f, 1e-4f);  // the left one stands
}

TEST(Moves, StepGoesFortyCentimetresForwardOnAlternateFeet) {
  EXPECT_NEAR(pose_for(Move::Step, 0.5f).root_offset.z, 0.4f, 1e-5f);
  const Mesh lead_foot_up = build_fighter(pose_for(Move::Step, 0.25f), kRed);
  EXPECT_GT(lowest_y_on_side(lead_foot_up, 1.0f), 0.03f);
  EXPECT_NEAR(lowest_y_on_side(lead_foot_up, -1.0f), 0.0f, 1e-4f);
  const Mesh rear_foot_up = build_fighter(pose_for(Move::Step, 0.75f), kRed);
  EXPECT_NEAR(lowest_y_on_side(rear_foot_up, 1.0f), 0.0f, 1e-4f);
  EXPECT_GT(lowest_y_on_side(rear_foot_up, -1.0f), 0.03f);
}

TEST(Moves, HitReactionLeansBackAndDropsTheArms) {
  const FighterPose guard = pose_for(Move::Guard, 0.0f);
  const FighterPose hit = pose_for(Move::HitReaction, 0.3f);
  EXPECT_LT(hit.torso_lean, guard.torso_lean - 0.3f);
  for (int side = 0; side < 2; ++side) {
    EXPECT_LT(hit.elbow[side], guard.elbow[side] - 1.0f);
    EXPECT_LT(hit.shoulder[side].x, guard.shoulder[side].x);
  }
}

TEST(Moves, NamesMapToMoves) {
  Move move = Move::Guard;
  const std::pair<const char *, Move> names[] = {{"guard", Move::Guard},
                                                 {"punch", Move::Punch},
                                                 {"kick", Move::Kick},
                                                 {"step", Move::Step},
                                                 {"hit", Move::HitReaction}};
  for (const auto &[name, expected] : names) {
    EXPECT_TRUE(move_from_name(name, move)) << name;
    EXPECT_EQ(move, expected) << name;
  }
  move = Move::Kick;
  EXPECT_FALSE(move_from_name("uppercut", move));
  EXPECT_EQ(move, Move::Kick);
}

// Between frames 1/30 s apart no joint turns more than 0.35 rad and the body moves less than
// 5 cm: the fastest motion (the kick's knee snapping straight) is about 0.3 rad a frame, while a
// jump between key poses would be 1-2 rad.
TEST(FightLoop, IsContinuousAt30FramesPerSecond) {
  for (int fighter = 0; fighter < 2; ++fighter) {
    const int frames = static_cast<int>(2.0f * fight_loop_seconds() * 30.0f);
    FighterPose previous = fight_loop_pose(fighter, 0.0f);
    for (int frame = 1; frame <= frames; ++frame) {
      const FighterPose pose = fight_loop_pose(fighter, static_cast<float>(frame) / 30.0f);
      EXPECT_LT(largest_difference(joint_angles(pose), joint_angles(previous)), 0.35f)
          << "fighter " << fighter << " frame " << frame;
      EXPECT_LT(largest_difference(placement(pose), placement(previous)), 0.05f)
          << "fighter " << fighter << " frame " << frame;
      previous = pose;
    }
  }
}

TEST(FightLoop, RepeatsEveryLoop) {
  const float period = fight_loop_seconds();
  EXPECT_GE(period, 6.0f);
  EXPECT_LE(period, 10.0f);
  for (int fighter = 0; fighter < 2; ++fighter) {
    for (float time = 0.0f; time < period; time += 0.1f) {
      const FighterPose now = fight_loop_pose(fighter, time);
      const FighterPose next_loop = fight_loop_pose(fighter, time + period);
      EXPECT_LT(largest_difference(joint_angles(now), joint_angles(next_loop)), 1e-3f) << time;
      EXPECT_LT(largest_difference(placement(now), placement(next_loop)), 1e-3f) << time;
    }
  }
}

// The fighters take turns: each one's attack at full reach (fighter 0's right arm straight,
// fighter 1's right leg up) is answered within half a second by the other leaning back.
TEST(FightLoop, EachAttackIsAnsweredByTheOthersHitReaction) {
  const float guard_lean = pose_for(Move::Guard, 0.0f).torso_lean;
  const auto at_full_reach = [](int fighter, const FighterPose &pose) {
    return fighter == 0 ? pose.elbow[1] < 0.1f : pose.hip[1].x > 1.4f;
  };
  for (int attacker = 0; attacker < 2; ++attacker) {
    float reach_time = -1.0f;
    for (float time = 0.0f; time < fight_loop_seconds() && reach_time < 0.0f; time += 1.0f / 30.0f)
      if (at_full_reach(attacker, fight_loop_pose(attacker, time))) reach_time = time;
    ASSERT_GE(reach_time, 0.0f) << "fighter " << attacker << " never attacks";
    float deepest_lean = guard_lean;
    for (float time = reach_time; time < reach_time + 0.5f; time += 1.0f / 30.0f)
      deepest_lean = std::min(deepest_lean, fight_loop_pose(1 - attacker, time).torso_lean);
    EXPECT_LT(deepest_lean, guard_lean - 0.2f) << "fighter " << attacker << "'s attack";
  }
}

TEST(FightLoop, IsDeterministic) {
  for (const float time : {0.0f, 1.93f, 4.2f, 7.99f}) {
    const FighterPose a = fight_loop_pose(0, time), b = fight_loop_pose(0, time);
    EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << time;
  }
}

// ---- the ring ----------------------------------------------------------------------------------

TEST(Ring, HasAtLeast2000Triangles) { EXPECT_GE(build_ring().triangle_count(), 2000u); }

TEST(Ring, NormalsAreUnitLength) { EXPECT_LT(worst_normal_length_error(build_ring()), 1e-5f); }

// The mat's vertices: upward-facing, inside the ropes, near the platform height (world).
std::vector<glm::vec3> mat_vertices(const Mesh &ring, const RingSize &size) {
  std::vector<glm::vec3> mat;
  for (std::size_t i = 0; i < ring.positions.size(); ++i) {
    const glm::vec3 &p = ring.positions[i];
    if (std::abs(p.x) <= size.mat_half_width && std::abs(p.z) <= size.mat_half_width &&
        std::abs(p.y - size.platform_height) < 0.1f && ring.normals[i].y > 0.5f)
      mat.push_back(p);
  }
  return mat;
}

// Tolerance 1 mm: fighters placed with ring_mat_height must stand on the drawn canvas.
TEST(Ring, MatHeightMatchesTheMeshAtItsVertices) {
  const RingSize size;
  const std::vector<glm::vec3> mat = mat_vertices(build_ring(size), size);
  ASSERT_GE(mat.size(), 31u * 31u);
  for (const glm::vec3 &p : mat) EXPECT_NEAR(ring_mat_height(p.x, p.z, size), p.y, 1e-3f);
}

TEST(Ring, MatIsNotFlat) {
  const RingSize size;
  float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
  for (const glm::vec3 &p : mat_vertices(build_ring(size), size)) {
    low = std::min(low, p.y);
    high = std::max(high, p.y);
  }
  EXPECT_GT(high - low, 0.01f);
  EXPECT_LT(high - low, 0.06f);  // gentle: a few centimetres
}

TEST(Ring, MatMeetsTheApronAtTheRopes) {
  const RingSize size;
  const float near_rope = size.mat_half_width - 1e-3f;
  for (const float along : {-2.0f, 0.0f, 1.3f}) {
    EXPECT_NEAR(ring_mat_height(near_rope, along, size), size.platform_height, 1e-3f);
    EXPECT_NEAR(ring_mat_height(along, -near_rope, size), size.platform_height, 1e-3f);
  }
  EXPECT_EQ(ring_mat_height(size.mat_half_width + 0.2f, 0.0f, size), size.platform_height);
}

TEST(Ring, FollowsItsSize) {
  const RingSize size{2.5f, 0.8f};
  const Bounds bounds = bounds_of(build_ring(size));
  EXPECT_EQ(bounds.low.y, 0.0f);                          // the platform stands on the floor
  EXPECT_GT(bounds.high.y, size.platform_height + 1.0f);  // the posts rise above the mat
  EXPECT_NEAR(bounds.high.z, size.mat_half_width + 0.5f, 1e-4f);  // the apron, a bit wider
  EXPECT_NEAR(bounds.low.z, -(size.mat_half_width + 0.5f), 1e-4f);
}

}  // namespace

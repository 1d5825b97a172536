// The texel-footprint sweeps of hard_case_sweeps (hard_case_footprint.h): each shadow texel's
// footprint on screen (texel_footprint.h, depth_map_footprint.h) against the interior error it
// leaves, for the projected techniques and the depth map, the footprint checks off.
#include "hard_case_footprint.h"

#include "hard_case_bench.h"

#include "hard_case_scenes.h"

#include "measure/speed_error.h"
#include "scene/fight_scene.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace hard_cases {

// Texel footprints (texel_footprint.h) against interior error, the footprint check off so every
// configuration is measured: the fight's three bench frames at 640x480, the sample scenes and
// the footprint class's scenes, and `extra` scene files of tests/hard_cases, at every size. Each
// cell: the footprint in screen pixels, then the interior error (false shadow + false light) in %.
static bool footprint_table(const std::vector<gs::BenchConfiguration> &configurations,
                     const std::vector<std::string> &extra) {
  std::vector<gs::BenchFrame> frames;
  gs::FightScene fight(640, 480, 256);
  for (float time : {0.5f, 2.1f, 5.3f}) {
    char name[32];
    std::snprintf(name, sizeof name, "fight t=%.1f", static_cast<double>(time));
    frames.push_back({name, fight.at(time)});
  }
  for (const char *name : {"box_on_plane", "fighters", "obj_mesh", "receiver_between", "spotlight"}) {
    frames.push_back({name, hard_cases::load(std::string("../../scenes/") + name + ".json")});
  }
  std::vector<std::string> files = {"box_over_floor", "dueling_frusta", "crate_close_camera",
                                    "pole_low_sun", "table_high_light", "sign_on_wall",
                                    "bar_low_light", "crate_toward_camera", "rail_toward_camera"};
  files.insert(files.end(), extra.begin(), extra.end());
  for (const std::string &name : files) {
    frames.push_back({name.substr(name.find_last_of('/') + 1), hard_cases::load(name + ".json")});
  }
  std::vector<gs::BenchRow> rows;
  if (!measure_once(frames, configurations, "footprint", rows)) return false;
  std::printf("\n### Texel footprint against interior error (the check off)\n\n"
              "footprint in screen pixels per texel: interior error %% (false shadow + false "
              "light)\n\n| technique |");
  for (const gs::BenchFrame &frame : frames) std::printf(" %s |", frame.name.c_str());
  std::printf("\n|---|");
  for (std::size_t f = 0; f < frames.size(); ++f) std::printf("---|");
  std::printf("\n");
  for (std::size_t k = 0; k < configurations.size(); ++k) {
    std::printf("| %s %s |", configurations[k].technique.c_str(), configurations[k].settings.c_str());
    for (std::size_t f = 0; f < frames.size(); ++f) {
      const gs::BenchRow &row = rows[f * configurations.size() + k];
      if (row.failed) {
        std::printf(" failed |");
        continue;
      }
      std::printf(" %.2f: %.3f |", row.texel_footprint_px,
                  (row.errors.false_shadow_interior + row.errors.false_light_interior) * 100.0);
    }
    std::printf("\n");
  }
  std::fflush(stdout);
  return true;
}

// The projected texture's footprint, both variants.
bool footprint() {
  std::vector<gs::BenchConfiguration> configurations;
  for (const char *name : {"projected", "projected-chroma"}) {
    for (int size : {32, 64, 128, 256, 512}) {
      gs::BenchConfiguration c;
      c.technique = name;
      c.options.projected.size = size;
      c.options.projected.largest_texel_footprint_px = INFINITY;
      c.settings = "size " + std::to_string(size);
      configurations.push_back(c);
    }
  }
  return footprint_table(configurations, {});
}

// The depth map's footprint (depth_map_footprint.h), percentage-closer and nearest lookups, with
// the wide cones of the audit and of the class "depth-map texels too coarse" as well.
bool depth_footprint() {
  std::vector<gs::BenchConfiguration> configurations;
  for (bool linear : {true, false}) {
    for (int size : {32, 64, 128, 256, 512}) {
      gs::BenchConfiguration c;
      c.technique = "depth-map";
      c.options.projected.size = size;
      c.options.depth_map_linear = linear;
      c.options.depth_map_largest_footprint_px = INFINITY;
      c.settings = std::string(linear ? "pcf" : "nearest") + " size " + std::to_string(size);
      configurations.push_back(c);
    }
  }
  return footprint_table(configurations,
                         {"audit/a2_corridor_walls", "audit/a3_lean_to_roof", "wide_cone_hall",
                          "wide_cone_pillars", "wide_cone_crates", "waves_low_sun",
                          "dunes_side_light", "ripples_grazing"});
}

}  // namespace hard_cases

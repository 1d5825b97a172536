// The bench's comparison with the article's step times, on rows whose shares are known; and its
// configurations' labels against the options they run with.
#include "measure/speed_error.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

gs::BenchRow projected_row(const std::string &frame, const std::string &settings, double frame_ms) {
  gs::BenchRow row;
  row.frame = frame;
  row.technique = "projected";
  row.settings = settings;
  row.frame_ms = frame_ms;
  // Steps of 1, 2, 3, 4 and 10 ms: shares 5, 10, 15, 20 and 50 percent.
  const char *names[5] = {"1 caster", "2 texture", "3 st", "4 scene", "5 shadow pass"};
  const double ms[5] = {1, 2, 3, 4, 10};
  for (int i = 0; i < 5; ++i) row.steps.emplace_back(names[i], ms[i]);
  return row;
}

std::string joined(const std::vector<std::string> &lines) {
  std::string text;
  for (const std::string &line : lines) text += line + "\n";
  return text;
}

TEST(ArticleStepComparison, ReportsSharesSlowestStepAndDirectPathGain) {
  std::vector<gs::BenchRow> rows = {
      projected_row("fight t=0.5", "size 256 bilinear lfb", 15.0),
      projected_row("fight t=0.5", "size 256 bilinear direct", 10.0),
      projected_row("box_on_plane", "size 256 bilinear lfb", 99.0),  // not a fight frame: ignored
      // A scene file whose name starts as a fight frame's does (scenes/fighters.json): ignored.
      projected_row("fighters", "size 256 bilinear lfb", 99.0),
      projected_row("fighters", "size 256 bilinear direct", 1.0),
  };
  const std::string text = joined(gs::article_step_comparison(rows));
  EXPECT_NE(text.find("5 shadow pass (50%)"), std::string::npos) << text;
  EXPECT_NE(text.find("2, copying the frame"), std::string::npos) << text;  // the article
  EXPECT_NE(text.find("10%\n"), std::string::npos) << text;   // step 2
  EXPECT_NE(text.find("15%\n"), std::string::npos) << text;   // step 3
  // Ours ends its line; the article's "about 50% faster" stands in the column before it.
  EXPECT_NE(text.find(" 50% faster\n"), std::string::npos) << text;  // 15 ms against 10 ms
}

TEST(ArticleStepComparison, ASlowerDirectPathIsCalledSlower) {
  const std::string text = joined(gs::article_step_comparison(
      {projected_row("fight t=0.5", "size 256 bilinear lfb", 10.0),
       projected_row("fight t=0.5", "size 256 bilinear direct", 12.5)}));
  EXPECT_NE(text.find("20% slower"), std::string::npos) << text;  // 10 ms is 20% less than 12.5
}

TEST(ArticleStepComparison, SaysWhatWasNotMeasured) {
  const std::string text =
      joined(gs::article_step_comparison({projected_row("fight t=2.1", "size 256 bilinear lfb", 12.0)}));
  EXPECT_NE(text.find("not measured (the direct path is not in --quick)"), std::string::npos) << text;
  const std::string empty = joined(gs::article_step_comparison({}));
  EXPECT_NE(empty.find("slowest step"), std::string::npos);
  EXPECT_NE(empty.find("not measured"), std::string::npos) << empty;
}

// Every depth-map row's label says the glPolygonOffset bias it runs with, and no two rows share a
// label (a label left behind by a change of the defaults measured the same settings twice).
TEST(BenchConfigurations, LabelsSayTheDepthBiasTheyRunWithAndDiffer) {
  std::set<std::pair<std::string, std::string>> labels;
  int depth_map_rows = 0;
  for (const gs::BenchConfiguration &c : gs::bench_configurations(false)) {
    const std::string attenuation = c.attenuation ? std::to_string(static_cast<int>(*c.attenuation)) : "-";
    EXPECT_TRUE(labels.insert({c.technique, c.settings + " " + attenuation}).second)
        << c.technique << " " << c.settings;
    if (c.technique != "depth-map") continue;
    ++depth_map_rows;
    char bias[48];
    std::snprintf(bias, sizeof bias, " bias %g/%g", static_cast<double>(c.options.depth_bias_slope),
                  static_cast<double>(c.options.depth_bias_units));
    EXPECT_NE(c.settings.find(bias), std::string::npos) << c.settings << " runs with" << bias;
  }
  EXPECT_GE(depth_map_rows, 5);
}

}  // namespace

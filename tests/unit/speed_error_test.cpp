// The bench's comparison with the article's step times, on rows whose shares are known.
#include "measure/speed_error.h"

#include <gtest/gtest.h>

#include <string>
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
  };
  const std::string text = joined(gs::article_step_comparison(rows));
  EXPECT_NE(text.find("5 shadow pass (50%)"), std::string::npos) << text;
  EXPECT_NE(text.find("2, copying the frame"), std::string::npos) << text;  // the article
  EXPECT_NE(text.find("10%\n"), std::string::npos) << text;   // step 2
  EXPECT_NE(text.find("15%\n"), std::string::npos) << text;   // step 3
  EXPECT_NE(text.find("50% faster"), std::string::npos) << text;  // 15 ms against 10 ms
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

}  // namespace

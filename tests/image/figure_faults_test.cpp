// Every figure check can fail: each case of figure_faults.h renders a figure with a deliberate
// mistake (a panel read after a later render, the texture wrapped instead of clamped, the
// second pass at GR_CMP_LESS, the shadow left out, ...) and asserts that the check it names
// fails, while the figure's other checks are free to pass or fail.
#include "figure_faults.h"

#include <glide.h>
#include <gtest/gtest.h>

#include <cstring>

namespace {

class FigureFaultTest : public ::testing::TestWithParam<FigureFaultCase> {
 protected:
  void SetUp() override { grGlideInit(); }
  void TearDown() override { grGlideShutdown(); }
};

const gs::FigureEntry *find_figure(const char *name) {
  for (const gs::FigureEntry &entry : gs::figure_table()) {
    if (std::strcmp(entry.name, name) == 0) return &entry;
  }
  return nullptr;
}

TEST_P(FigureFaultTest, TheNamedCheckFails) {
  const FigureFaultCase &c = GetParam();
  const gs::FigureEntry *entry = find_figure(c.figure);
  ASSERT_NE(entry, nullptr) << c.figure;
  gs::Figure figure;
  std::string error;
  ASSERT_TRUE(gs::make_figure(*entry, figure, error, c.fault)) << error;
  const gs::FigureCheck *named = nullptr;
  for (const gs::FigureCheck &check : figure.checks) {
    if (check.claim.find(c.claim) != std::string::npos) named = &check;
  }
  ASSERT_NE(named, nullptr) << c.figure << " has no check whose claim holds '" << c.claim << "'";
  EXPECT_FALSE(named->passed) << c.figure << ": the broken rendering passed '" << named->claim
                              << "' (" << named->measured << ")";
}

std::string case_name(const ::testing::TestParamInfo<FigureFaultCase> &info) {
  std::string name = std::string(info.param.figure) + "_" + std::to_string(info.index);
  for (char &c : name) {
    if (c == '-') c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Broken, FigureFaultTest, ::testing::ValuesIn(figure_fault_cases()), case_name);

}  // namespace

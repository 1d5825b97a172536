// The articles' figures (src/figures/): one test per figure runs its checks (what the article
// says the figure shows, measured on our pixels), requires a fault case of figure_faults.h for
// each, and compares its image with reference_images/figures/<name>.png. Tolerance as for the other frames: llvmpipe's output
// depends on the CPU's vector ISA, so a pixel may differ by 4/255 and 1% of pixels may differ
// more. Also the `figures` command as a user runs it.
#include "figure_faults.h"
#include "figures/figures.h"
#include "image_compare.h"

#include <glide.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace fs = std::filesystem;

namespace {

const ImageTolerance kAcrossCpus{4.0f / 255.0f, 0.01};

class FigureTest : public ::testing::TestWithParam<const gs::FigureEntry *> {
 protected:
  void SetUp() override { grGlideInit(); }
  void TearDown() override { grGlideShutdown(); }
};

TEST_P(FigureTest, ChecksPassAndImageMatchesItsReference) {
  const gs::FigureEntry &entry = *GetParam();
  gs::Figure figure;
  std::string error;
  ASSERT_TRUE(gs::make_figure(entry, figure, error)) << error;
  ASSERT_GE(figure.checks.size(), 2u) << "a figure states at least one claim besides the Glide-error check";
  for (const gs::FigureCheck &check : figure.checks) {
    EXPECT_TRUE(check.passed) << entry.source << ": " << check.claim << " (" << check.measured << ")";
    // Glide's error check is the same for every figure; one case (nguyen-16) shows it failing.
    const bool glide_error_check = check.claim.find("Glide reported no error") != std::string::npos;
    EXPECT_TRUE(glide_error_check || has_fault_case(entry.name, check.claim))
        << entry.name << ": no case of figure_faults.h shows this check failing: " << check.claim;
  }
  ASSERT_GT(figure.image.width, 0);
  ASSERT_EQ(figure.image.rgb.size(), static_cast<std::size_t>(figure.image.width * figure.image.height * 3));
  fs::create_directories(output_path("figures"));
  const std::string png = output_path("figures/" + std::string(entry.name) + ".png");
  ASSERT_TRUE(gs::write_figure_png(figure.image, png, error)) << error;
  EXPECT_TRUE(matches_reference("figures/" + std::string(entry.name), png, kAcrossCpus));
}

std::vector<const gs::FigureEntry *> every_figure() {
  std::vector<const gs::FigureEntry *> all;
  for (const gs::FigureEntry &entry : gs::figure_table()) all.push_back(&entry);
  return all;
}

std::string test_name(const ::testing::TestParamInfo<const gs::FigureEntry *> &info) {
  std::string name = info.param->name;
  for (char &c : name) {
    if (c == '-') c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Articles, FigureTest, ::testing::ValuesIn(every_figure()), test_name);

TEST(FigureTable, NamesAreUniqueAndSelectable) {
  std::vector<const gs::FigureEntry *> selected;
  std::string error;
  ASSERT_TRUE(gs::select_figures("", selected, error));
  EXPECT_EQ(selected.size(), gs::figure_table().size());
  for (std::size_t i = 0; i < selected.size(); ++i) {
    for (std::size_t j = i + 1; j < selected.size(); ++j) {
      EXPECT_STRNE(selected[i]->name, selected[j]->name);
    }
  }
  ASSERT_TRUE(gs::select_figures("7,sgi-3,everitt-5", selected, error)) << error;
  ASSERT_EQ(selected.size(), 3u);
  EXPECT_STREQ(selected[0]->name, "nguyen-7");
  EXPECT_STREQ(selected[1]->name, "sgi-3");
  EXPECT_STREQ(selected[2]->name, "everitt-5");
  const std::vector<const gs::FigureEntry *> before = selected;
  EXPECT_FALSE(gs::select_figures("7,nguyen-18", selected, error));
  EXPECT_NE(error.find("nguyen-18"), std::string::npos) << error;
  EXPECT_EQ(selected, before) << "a rejected selection leaves the previous one";
}

std::string file_text(const fs::path &path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(FiguresCommand, WritesTheFiguresAndTheIndex) {
  const fs::path dir = output_path("figures_command");
  fs::remove_all(dir);
  const std::string command = std::string(GLIDESHADOWS_PATH) + " figures --out " + dir.string() +
                              " --only 16,everitt-5 > " + (dir.string() + ".log");
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  EXPECT_TRUE(fs::exists(dir / "nguyen-16.png"));
  EXPECT_TRUE(fs::exists(dir / "everitt-5.png"));
  EXPECT_FALSE(fs::exists(dir / "nguyen-7.png")) << "only the selected figures";
  const std::string index = file_text(dir / "index.html");
  EXPECT_NE(index.find("src=\"nguyen-16.png\""), std::string::npos);
  EXPECT_NE(index.find("src=\"everitt-5.png\""), std::string::npos);
  EXPECT_EQ(index.find("FAIL"), std::string::npos);
  const std::string log = file_text(dir.string() + ".log");
  EXPECT_NE(log.find("[1/2]"), std::string::npos) << log;
  EXPECT_NE(log.find("pass  565: red in bits 15-11"), std::string::npos) << log;
  EXPECT_NE(log.find("0 checks failed"), std::string::npos) << log;
}

TEST(FiguresCommand, RejectsAnUnknownFigure) {
  const std::string command = std::string(GLIDESHADOWS_PATH) + " figures --out " +
                              output_path("figures_rejected") + " --only 99 > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_FALSE(fs::exists(fs::path(output_path("figures_rejected")) / "index.html"));
}

}  // namespace

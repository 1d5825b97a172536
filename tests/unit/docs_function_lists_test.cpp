// The function lists of docs/compatibility.md and docs/porting.md held against the public headers:
// every function glide.h, glideutl.h and glide_shim.h declare has exactly one row (a status) in
// compatibility.md's "Implemented" or "Extras" tables, no row names a function the headers lack,
// the functions "Not implemented" names are indeed not declared, and every Glide or shim function
// porting.md names is declared.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#ifndef GLIDESHADOWS_SOURCE_DIR
#error "GLIDESHADOWS_SOURCE_DIR must name the source tree"
#endif

namespace {

std::string read_text(const std::string &relative_path) {
  std::ifstream in(std::string(GLIDESHADOWS_SOURCE_DIR) + "/" + relative_path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::set<std::string> matches(const std::string &text, const std::regex &pattern) {
  std::set<std::string> names;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern); it != std::sregex_iterator(); ++it)
    names.insert((*it)[1].str());
  return names;
}

// Functions the public headers declare: the SDK's FX_ENTRY ... FX_CALL name( and the shim's
// GLIDESHIM_API ... name( at the start of a line (not the macro's own #define).
std::set<std::string> declared_functions() {
  const std::regex sdk(R"(FX_ENTRY\s+[^;()]*?FX_CALL\s+(\w+)\s*\()");
  const std::regex shim(R"(\nGLIDESHIM_API\s+[^;()]*?\b(\w+)\s*\()");
  std::set<std::string> names = matches(read_text("glide_shim/include/glide.h"), sdk);
  for (const std::string &name : matches(read_text("glide_shim/include/glideutl.h"), sdk)) names.insert(name);
  for (const std::string &name : matches(read_text("glide_shim/include/glide_shim.h"), shim)) names.insert(name);
  return names;
}

// The text of a markdown section: from its "## title" line to the next "## ".
std::string section(const std::string &document, const std::string &title) {
  const std::size_t start = document.find("\n## " + title + "\n");
  if (start == std::string::npos) return "";
  const std::size_t end = document.find("\n## ", start + 1);
  return document.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// Function names in one column of a markdown table's rows (the header and rule rows skipped),
// with how many rows name each.
std::map<std::string, int> table_column_names(const std::string &text, int column) {
  std::map<std::string, int> names;
  std::istringstream lines(text);
  bool after_rule = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] != '|') {
      after_rule = false;
      continue;
    }
    if (line.rfind("|---", 0) == 0) {
      after_rule = true;
      continue;
    }
    if (!after_rule) continue;
    std::vector<std::string> cells;
    std::istringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
    if (static_cast<int>(cells.size()) <= column) continue;
    const std::regex name(R"(\b((?:gr|gu|glideShim)[A-Z0-9]\w*|ConvertAndDownloadRle)\b)");
    for (const std::string &found : matches(cells[static_cast<std::size_t>(column)], name)) ++names[found];
  }
  return names;
}

TEST(DocsFunctionLists, HeadersAreParsed) {
  const std::set<std::string> declared = declared_functions();
  // compatibility.md counts 131 SDK functions; glide_shim.h adds the extras.
  EXPECT_GT(declared.size(), 131u);
  EXPECT_EQ(declared.count("grDrawTriangle"), 1u);
  EXPECT_EQ(declared.count("guTexCombineFunction"), 1u);
  EXPECT_EQ(declared.count("ConvertAndDownloadRle"), 1u);
  EXPECT_EQ(declared.count("glideShimWritePng"), 1u);
}

TEST(DocsFunctionLists, CompatibilityListsEveryDeclaredFunctionOnce) {
  const std::string compatibility = read_text("docs/compatibility.md");
  const std::string implemented = section(compatibility, "Implemented");
  const std::string extras = section(compatibility, "Extras (glide_shim.h; no Voodoo had them)");
  ASSERT_FALSE(implemented.empty());
  ASSERT_FALSE(extras.empty());
  std::map<std::string, int> listed = table_column_names(implemented, 1);
  for (const auto &[name, rows] : table_column_names(extras, 0)) listed[name] += rows;

  const std::set<std::string> declared = declared_functions();
  for (const std::string &name : declared) {
    EXPECT_EQ(listed.count(name), 1u) << name << " is declared but compatibility.md gives it no row";
  }
  for (const auto &[name, rows] : listed) {
    EXPECT_EQ(declared.count(name), 1u) << name << " is listed in compatibility.md but no header declares it";
    EXPECT_EQ(rows, 1) << name << " is listed in " << rows << " rows of compatibility.md";
  }
}

TEST(DocsFunctionLists, NotImplementedNamesNoDeclaredFunction) {
  const std::string not_implemented = section(read_text("docs/compatibility.md"), "Not implemented");
  ASSERT_FALSE(not_implemented.empty());
  // The bullets name what is left out; the paragraph after them names implemented functions.
  std::string bullets;
  std::istringstream lines(not_implemented);
  bool in_bullet = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("- ", 0) == 0) in_bullet = true;
    else if (line.rfind("  ", 0) != 0) in_bullet = false;
    if (in_bullet) bullets += line + "\n";
  }
  const std::set<std::string> named = matches(bullets, std::regex(R"(`((?:gr|gu)[A-Z]\w*)`)"));
  EXPECT_GE(named.size(), 8u);  // grSstVidMode, the seven Glide 2.1 LFB calls, grSstOpen
  const std::set<std::string> declared = declared_functions();
  for (const std::string &name : named) {
    EXPECT_EQ(declared.count(name), 0u) << name << " is called not implemented but is declared";
  }
}

TEST(DocsFunctionLists, PortingNamesOnlyDeclaredFunctions) {
  const std::string porting = read_text("docs/porting.md");
  ASSERT_FALSE(porting.empty());
  // Every gr*/gu*/glideShim* name followed by "(" or in backticks, in prose and code alike.
  const std::set<std::string> named = matches(
      porting, std::regex(R"(\b((?:gr|gu|glideShim)[A-Z][A-Za-z0-9]*)\b(?=\(|`))"));
  EXPECT_GE(named.size(), 30u);
  const std::set<std::string> declared = declared_functions();
  for (const std::string &name : named) {
    EXPECT_EQ(declared.count(name), 1u) << "porting.md names " << name << ", which no header declares";
  }
}

}  // namespace

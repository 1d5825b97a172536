// .3df files: the header, the NCC table or palette, big-endian texels, levels largest first,
// and a clear GLIDESHIM_ERR_FILE for every kind of bad file, with the caller's Gu3dfInfo left
// as it was. Files are written by the test byte by byte, from the format's description.
#include <glide.h>
#include <glide_shim.h>
#include <glideutl.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

std::string temp_path(const std::string &name) {
  // Under the build tree's test directory (TEST_TMPDIR, which ::testing::TempDir reads).
  return ::testing::TempDir() + "gu3df_test_" + name;
}

void write_file(const std::string &path, const std::string &bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

void put16(std::string &bytes, unsigned value) {
  bytes += static_cast<char>((value >> 8) & 0xFF);
  bytes += static_cast<char>(value & 0xFF);
}

void put32(std::string &bytes, FxU32 value) {
  for (int shift = 24; shift >= 0; shift -= 8) bytes += static_cast<char>((value >> shift) & 0xFF);
}

// An RGB565 8x4 (aspect 2:1) chain 8x4, 4x2, 2x1, 1x1: 8 + ... texels, value = index * 7.
std::string rgb565_file(std::vector<FxU16> &texels) {
  std::string bytes = "3df v1.1\nrgb565\nlod range: 1 8\naspect ratio: 2 1\n";
  texels.clear();
  for (int count : {32, 8, 2, 1}) {
    for (int i = 0; i < count; ++i) {
      const auto value = static_cast<FxU16>(texels.size() * 7 + 0x1234);
      texels.push_back(value);
      put16(bytes, value);
    }
  }
  return bytes;
}

class Gu3dfTest : public ::testing::Test {
 protected:
  void SetUp() override { glideShimClearError(); }

  // Expects gu3dfGetInfo or gu3dfLoad to refuse `bytes` with `text` in the message, and to leave
  // a pre-filled info untouched.
  static void expect_refused(const std::string &bytes, const std::string &text, bool load) {
    const std::string path = temp_path("bad.3df");
    write_file(path, bytes);
    Gu3dfInfo info;
    std::memset(&info, 0xA5, sizeof info);
    std::vector<unsigned char> data(4096, 0x5A);
    if (load) {
      // A good header for the file's own size claims, as a program would have from GetInfo.
      std::vector<FxU16> unused;
      const std::string good = temp_path("good.3df");
      write_file(good, rgb565_file(unused));
      ASSERT_TRUE(gu3dfGetInfo(good.c_str(), &info));
      info.data = data.data();
    }
    Gu3dfInfo before;
    std::memcpy(&before, &info, sizeof info);
    const std::vector<unsigned char> data_before = data;
    glideShimClearError();
    const FxBool ok = load ? gu3dfLoad(path.c_str(), &info) : gu3dfGetInfo(path.c_str(), &info);
    EXPECT_FALSE(ok);
    EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find(text), std::string::npos)
        << glideShimGetLastErrorMessage();
    EXPECT_EQ(std::memcmp(&before, &info, sizeof info), 0) << "info changed";
    EXPECT_EQ(data, data_before) << "texel data changed";
  }
};

TEST_F(Gu3dfTest, Rgb565ChainLoadsLargestLevelFirstFromBigEndian) {
  std::vector<FxU16> texels;
  const std::string path = temp_path("rgb565.3df");
  write_file(path, rgb565_file(texels));
  Gu3dfInfo info{};
  ASSERT_TRUE(gu3dfGetInfo(path.c_str(), &info)) << glideShimGetLastErrorMessage();
  EXPECT_EQ(info.header.width, 8u);
  EXPECT_EQ(info.header.height, 4u);
  EXPECT_EQ(info.header.large_lod, GR_LOD_8);
  EXPECT_EQ(info.header.small_lod, GR_LOD_1);
  EXPECT_EQ(info.header.aspect_ratio, GR_ASPECT_2x1);
  EXPECT_EQ(info.header.format, GR_TEXFMT_RGB_565);
  EXPECT_EQ(info.mem_required, 43u * 2u);
  std::vector<FxU16> data(info.mem_required / 2);
  info.data = data.data();
  ASSERT_TRUE(gu3dfLoad(path.c_str(), &info)) << glideShimGetLastErrorMessage();
  EXPECT_EQ(data, texels);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK);
}

TEST_F(Gu3dfTest, PaletteFileFillsTheTableAndIndices) {
  std::string bytes = "3df v1.1\nP8\nlod range: 4 4\naspect ratio: 1 4\n";
  std::vector<FxU32> palette(256);
  for (int i = 0; i < 256; ++i) {
    palette[static_cast<std::size_t>(i)] = 0x00010203u * static_cast<FxU32>(i) ^ 0xFF000000u;
    put32(bytes, palette[static_cast<std::size_t>(i)]);
  }
  for (int i = 0; i < 4; ++i) bytes += static_cast<char>(i * 50);  // 1x4 texels
  const std::string path = temp_path("p8.3df");
  write_file(path, bytes);
  Gu3dfInfo info{};
  ASSERT_TRUE(gu3dfGetInfo(path.c_str(), &info)) << glideShimGetLastErrorMessage();
  EXPECT_EQ(info.header.aspect_ratio, GR_ASPECT_1x4);
  EXPECT_EQ(info.header.width, 1u);
  EXPECT_EQ(info.header.height, 4u);
  std::vector<FxU8> data(info.mem_required);
  ASSERT_EQ(data.size(), 4u);
  info.data = data.data();
  ASSERT_TRUE(gu3dfLoad(path.c_str(), &info)) << glideShimGetLastErrorMessage();
  EXPECT_EQ(data, (std::vector<FxU8>{0, 50, 100, 150}));
  for (int i = 0; i < 256; ++i) EXPECT_EQ(info.table.palette.data[i], palette[static_cast<std::size_t>(i)]);
}

TEST_F(Gu3dfTest, NccFileFillsYiqAndThePackedWords) {
  std::string bytes = "3df v1.1\nyiq\nlod range: 2 2\naspect ratio: 1 1\n";
  for (int i = 0; i < 16; ++i) put16(bytes, static_cast<unsigned>(i * 16 + 3));
  // I then Q, four RGB vectors each, 9-bit two's complement in 16-bit words.
  const int iq[2][4][3] = {{{-256, 0, 255}, {1, -1, 100}, {-7, 8, -9}, {0, 0, 0}},
                           {{12, -12, 120}, {-200, 200, 5}, {3, 2, 1}, {-1, -2, -3}}};
  for (const auto &table : iq) {
    for (const auto &vector : table) {
      for (int c : vector) put16(bytes, static_cast<unsigned>(c) & 0xFFFF);
    }
  }
  for (int i = 0; i < 4; ++i) bytes += static_cast<char>(0x10 * i + i);
  const std::string path = temp_path("yiq.3df");
  write_file(path, bytes);
  Gu3dfInfo info{};
  ASSERT_TRUE(gu3dfGetInfo(path.c_str(), &info)) << glideShimGetLastErrorMessage();
  EXPECT_EQ(info.header.format, GR_TEXFMT_YIQ_422);
  std::vector<FxU8> data(info.mem_required);
  info.data = data.data();
  ASSERT_TRUE(gu3dfLoad(path.c_str(), &info)) << glideShimGetLastErrorMessage();
  const GuNccTable &ncc = info.table.nccTable;
  EXPECT_EQ(ncc.yRGB[5], 5 * 16 + 3);
  EXPECT_EQ(ncc.packed_data[1], FxU32{67} | FxU32{83} << 8 | FxU32{99} << 16 | FxU32{115} << 24);
  // I[0] = (-256, 0, 255): 9-bit fields 0x100, 0x000, 0x0FF.
  EXPECT_EQ(ncc.packed_data[4], (0x100u << 18) | 0x0FFu);
  // Q[1] = (-200, 200, 5).
  EXPECT_EQ(ncc.packed_data[9], ((0x200u - 200u) << 18) | (200u << 9) | 5u);
  EXPECT_EQ(data, (std::vector<FxU8>{0x00, 0x11, 0x22, 0x33}));
}

TEST_F(Gu3dfTest, BadFilesAreRefusedWithTheProblemNamedAndInfoUntouched) {
  std::vector<FxU16> texels;
  const std::string good = rgb565_file(texels);
  expect_refused("", "header does not have four text lines", false);
  expect_refused("3df v1.1\nrgb565\n", "header does not have four text lines", false);
  expect_refused("3dx v1.1\nrgb565\nlod range: 1 8\naspect ratio: 2 1\n", "bad header", false);
  expect_refused("3df v1.1\nrgb999\nlod range: 1 8\naspect ratio: 2 1\n",
                 "unknown texture format \"rgb999\"", false);
  expect_refused("3df v1.1\nrgb565\nlod range: 1 512\naspect ratio: 2 1\n", "bad lod range", false);
  expect_refused("3df v1.1\nrgb565\nlod range: 8 1\naspect ratio: 2 1\n", "bad lod range", false);
  expect_refused("3df v1.1\nrgb565\nlod range: 1 8\naspect ratio: 3 1\n", "bad aspect ratio", false);
  expect_refused("3df v1.1\nrgb565\nlod range: 1 8\nratio 2 1\n", "bad header", false);
  expect_refused(good.substr(0, good.size() - 1), "truncated", true);
  expect_refused(good + "xx", "wrong size", true);
  expect_refused("3df v1.1\nrgb565\nlod range: 1 4\naspect ratio: 2 1\n",
                 "does not describe this file", true);
  // A missing file.
  Gu3dfInfo info{};
  EXPECT_FALSE(gu3dfGetInfo(temp_path("missing.3df").c_str(), &info));
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_FILE);
  EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find("cannot open"), std::string::npos);
  // Load without a buffer for the texels.
  const std::string path = temp_path("good2.3df");
  write_file(path, good);
  ASSERT_TRUE(gu3dfGetInfo(path.c_str(), &info));
  info.data = nullptr;
  EXPECT_FALSE(gu3dfLoad(path.c_str(), &info));
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
}

}  // namespace

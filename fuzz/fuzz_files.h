// Shared by the file fuzzers: a private directory for the file under test, made once per
// process, and writing the input's bytes there.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace fuzz_files {

// A fresh directory under $TMPDIR (or /tmp); aborts if none can be made.
inline const std::string &directory() {
  static const std::string path = [] {
    const char *tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") +
                          "/glideshadows_fuzz_XXXXXX";
    if (mkdtemp(pattern.data()) == nullptr) {
      std::perror("mkdtemp");
      std::abort();
    }
    return pattern;
  }();
  return path;
}

// Writes `size` bytes to `name` inside directory() and returns the file's path.
inline std::string write(const std::string &name, const std::uint8_t *data, std::size_t size) {
  const std::string path = directory() + "/" + name;
  std::FILE *file = std::fopen(path.c_str(), "wb");
  if (file == nullptr || std::fwrite(data, 1, size, file) != size || std::fclose(file) != 0) {
    std::perror(path.c_str());
    std::abort();
  }
  return path;
}

}  // namespace fuzz_files

// Reading an input file (scene, OBJ mesh) whole, with a size limit: only regular files are read,
// so a path naming a device (/dev/zero), a FIFO or a directory is refused instead of read forever.
#pragma once

#include <cstddef>
#include <string>

namespace gs {

// Reads `path` into `contents` when it is a regular file of at most `max_bytes` bytes.
// False, with `error` saying why (without the path), otherwise; `contents` is left unchanged then.
bool read_input_file(const std::string &path, std::size_t max_bytes, std::string &contents,
                     std::string &error);

}  // namespace gs

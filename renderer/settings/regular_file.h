#pragma once
// Reading a file that must be a regular file: a FIFO would block forever, a folder or /dev/zero would read as
// nonsense or without end. The check is on the opened descriptor (fstat), so a swap after the check cannot fool it,
// and the open itself never blocks (O_NONBLOCK).
#include <cstddef>
#include <string>
#include <vector>

namespace shadowlab {

// "a folder", "a FIFO (named pipe)", "a character device", ... for `path` (following symlinks); "" when it is a
// regular file or does not exist.
std::string nonRegularFileKind(const std::string& path);

// Reads the whole regular file at `path` into `out` (replacing it). Returns "" or why not, starting with the path:
// "PATH: no such file", "PATH: is a FIFO (named pipe), not a regular file", "PATH: larger than N bytes", ...
std::string readRegularFile(const std::string& path, std::size_t maxBytes, std::string& out);
std::string readRegularFile(const std::string& path, std::size_t maxBytes, std::vector<unsigned char>& out);

}  // namespace shadowlab

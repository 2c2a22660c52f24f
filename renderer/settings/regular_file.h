#pragma once
// Reading a file that must be a regular file: a FIFO would block forever, a folder or /dev/zero would read as
// nonsense or without end. The check is on the opened descriptor (fstat), so a swap after the check cannot fool it,
// and the open itself never blocks (O_NONBLOCK).
#include <cstddef>
#include <cstdint>
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

// A regular file opened for reading in pieces at any offset (a PNG's chunks, skipping its pixels), with the checks
// of readRegularFile and no size limit.
class RegularFileReader {
public:
    RegularFileReader() = default;
    RegularFileReader(const RegularFileReader&) = delete;
    RegularFileReader& operator=(const RegularFileReader&) = delete;
    ~RegularFileReader();

    // "" or why not, worded as readRegularFile words it ("PATH: no such file", ...).
    std::string open(const std::string& path);
    std::uint64_t size() const { return size_; }
    // All `n` bytes at `offset`, or false (past the end, a read error).
    bool readAt(std::uint64_t offset, std::size_t n, void* out) const;
    int descriptor() const { return fd_; }

private:
    int fd_ = -1;
    std::uint64_t size_ = 0;
};

}  // namespace shadowlab

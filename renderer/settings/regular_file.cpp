#include "settings/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace shadowlab {

namespace {

std::string kindOf(mode_t mode) {
    if (S_ISREG(mode)) return {};
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

template <class Bytes>
std::string readInto(const std::string& path, std::size_t maxBytes, Bytes& out) {
    out.clear();
    RegularFileReader file;
    if (std::string why = file.open(path); !why.empty()) return why;
    const int fd = file.descriptor();
    if (file.size() > maxBytes)
        return path + ": " + std::to_string(file.size()) + " bytes, larger than the limit of " +
               std::to_string(maxBytes) + " bytes";
    out.resize(static_cast<std::size_t>(file.size()));
    std::size_t got = 0;
    // Read until EOF, not st_size: a file may change while it is read; the limit still holds.
    for (;;) {
        if (got == out.size()) {
            if (out.size() >= maxBytes + 1) break;
            out.resize(std::min(maxBytes + 1, out.size() + 65536));
        }
        const ssize_t n = ::read(fd, out.data() + got, out.size() - got);
        if (n < 0) {
            if (errno == EINTR) continue;
            out.clear();
            return path + ": read error: " + std::strerror(errno);
        }
        if (n == 0) break;
        got += static_cast<std::size_t>(n);
    }
    if (got > maxBytes) {
        out.clear();
        return path + ": larger than the limit of " + std::to_string(maxBytes) + " bytes";
    }
    out.resize(got);
    return {};
}

}  // namespace

RegularFileReader::~RegularFileReader() {
    if (fd_ >= 0) ::close(fd_);
}

std::string RegularFileReader::open(const std::string& path) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    size_ = 0;
    if (path.empty()) return "no file name given";
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        if (errno == ENOENT) return path + ": no such file";
        return path + ": cannot open: " + std::strerror(errno);
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const std::string why = std::strerror(errno);
        ::close(fd);
        return path + ": cannot stat: " + why;
    }
    if (const std::string kind = kindOf(st.st_mode); !kind.empty()) {
        ::close(fd);
        return path + ": is " + kind + ", not a regular file";
    }
    fd_ = fd;
    size_ = static_cast<std::uint64_t>(st.st_size);
    return {};
}

bool RegularFileReader::readAt(std::uint64_t offset, std::size_t n, void* out) const {
    auto* bytes = static_cast<unsigned char*>(out);
    while (n > 0) {
        const ssize_t got = ::pread(fd_, bytes, n, static_cast<off_t>(offset));
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        bytes += got;
        n -= static_cast<std::size_t>(got);
        offset += static_cast<std::uint64_t>(got);
    }
    return true;
}

std::string nonRegularFileKind(const std::string& path) {
    struct stat st {};
    if (path.empty() || ::stat(path.c_str(), &st) != 0) return {};
    return kindOf(st.st_mode);
}

std::string readRegularFile(const std::string& path, std::size_t maxBytes, std::string& out) {
    return readInto(path, maxBytes, out);
}

std::string readRegularFile(const std::string& path, std::size_t maxBytes, std::vector<unsigned char>& out) {
    return readInto(path, maxBytes, out);
}

}  // namespace shadowlab

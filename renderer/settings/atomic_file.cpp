#include "settings/atomic_file.h"

#include "settings/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

// 'path' (appended, not "'" + ...: g++ 12 warns falsely about the latter with -Wrestrict).
std::string quoted(const fs::path& path) {
    std::string out = "'";
    out += path.string();
    out += "'";
    return out;
}

std::string errnoText(const std::string& what) { return what + ": " + std::strerror(errno); }

bool writeAll(int fd, const char* p, std::size_t left) {
    while (left > 0) {
        ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace

std::string readOnlyFileReason(const std::string& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::is_regular_file(status)) return "";
    const fs::perms p = status.permissions();
    const fs::perms write = fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
    if ((p & write) != fs::perms::none) return "";
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", unsigned(p) & 07777u);
    return std::string("it is read-only (mode ") + mode + "): ShadowLab does not replace a file its owner protected";
}

std::string writeFileAtomically(const std::string& path, const std::string& text) {
    return writeFileAtomically(path, text.data(), text.size());
}

std::string writeFileAtomically(const std::string& path, const void* bytes, std::size_t size) {
    if (path.empty()) return "no file name given";
    // Replace what a symlink points to, not the link itself, and only when that is a regular file: a dangling
    // link is refused rather than followed to create a file somewhere the user did not name.
    fs::path target(path);
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(target, ec))) {
        fs::path resolved = fs::canonical(target, ec);
        if (ec) return "it is a symbolic link to " + quoted(fs::read_symlink(target, ec)) + ", which does not exist";
        target = resolved;
    }
    fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    fs::file_status folderStatus = fs::status(folder, ec);
    if (folderStatus.type() == fs::file_type::not_found) return "folder " + quoted(folder) + " does not exist";
    if (!fs::is_directory(folderStatus)) return quoted(folder) + " is not a folder";
    // Only a regular file is replaced: renaming over /dev/null, a FIFO or a socket would destroy it.
    if (const std::string kind = nonRegularFileKind(target.string()); !kind.empty())
        return "it is " + kind + ", not a regular file; ShadowLab writes only regular files";
    if (std::string readOnly = readOnlyFileReason(target.string()); !readOnly.empty()) return readOnly;

    // Temporary in the same folder so rename() is atomic (same file system). O_EXCL: never reuse someone's file.
    static std::atomic<unsigned> counter{0};
    std::string tempPath;
    int fd = -1;
    for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
        std::string tempName = ".";
        tempName += target.filename().string();
        tempName += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
        tempPath = (folder / tempName).string();
        fd = ::open(tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && errno != EEXIST) break;
    }
    if (fd < 0) return errnoText("cannot create a temporary file in " + quoted(folder));

    auto abandon = [&](const std::string& what) {
        std::string message = errnoText(what);
        if (fd >= 0) ::close(fd);
        ::unlink(tempPath.c_str());
        return message;
    };
    // Keep the permissions of the file being replaced (the new file would otherwise get 0666 & ~umask).
    struct stat old {};
    if (::stat(target.c_str(), &old) == 0 && ::fchmod(fd, old.st_mode & 07777) != 0) return abandon("fchmod");
    if (!writeAll(fd, static_cast<const char*>(bytes), size))
        return abandon("cannot write " + std::to_string(size) + " bytes into " + quoted(folder));
    if (::fsync(fd) != 0) return abandon("fsync");
    int closeResult = ::close(fd);
    fd = -1;
    if (closeResult != 0) return abandon("close");
    if (::rename(tempPath.c_str(), target.c_str()) != 0) return abandon("rename");

    // Make the rename itself durable; failing here loses nothing, so it is not an error.
    int dirFd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dirFd >= 0) {
        ::fsync(dirFd);
        ::close(dirFd);
    }
    return {};
}

}  // namespace shadowlab

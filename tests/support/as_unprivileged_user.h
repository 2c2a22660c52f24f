#pragma once
// For tests of file permissions that must also run as root (CI does, and root writes into read-only folders): while
// an AsUnprivilegedUser lives, the calling thread's file accesses are checked as user and group `nobody` (65534).
// Linux's filesystem ids (setfsuid / setfsgid) do this for one thread and drop root's permission override with them,
// so the process keeps its GL context and its other threads. Not root: nothing changes (the test already is
// unprivileged).
#include <sys/fsuid.h>
#include <unistd.h>

#include <string>

namespace shadowlab::test {

class AsUnprivilegedUser {
public:
    static constexpr unsigned kNobody = 65534;

    AsUnprivilegedUser() {
        if (::geteuid() != 0) return;
        ::setfsgid(kNobody);
        ::setfsuid(kNobody);
        changed_ = true;
        // Each call returns the id in force before it; -1 is refused and so changes nothing.
        const unsigned fsuid = unsigned(::setfsuid(uid_t(-1))), fsgid = unsigned(::setfsgid(gid_t(-1)));
        if (fsuid != kNobody || fsgid != kNobody)
            error_ = "setfsuid/setfsgid(" + std::to_string(kNobody) + ") left this thread's file ids at " +
                     std::to_string(fsuid) + "/" + std::to_string(fsgid) + " (no CAP_SETUID?)";
    }
    ~AsUnprivilegedUser() {
        if (!changed_) return;
        ::setfsuid(0);
        ::setfsgid(0);
    }
    AsUnprivilegedUser(const AsUnprivilegedUser&) = delete;
    AsUnprivilegedUser& operator=(const AsUnprivilegedUser&) = delete;

    // "" once this thread's file accesses are unprivileged; else why not.
    const std::string& error() const { return error_; }

private:
    bool changed_ = false;
    std::string error_;
};

}  // namespace shadowlab::test

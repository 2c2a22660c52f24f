#pragma once
// Replacing a file atomically: a temporary file in the same folder, fsync, rename over the target. Readers see the
// old file or the new one, never half of one; any failure leaves the old file as it was and removes the temporary.
#include <cstddef>
#include <string>

namespace shadowlab {

// Writes `text` to `path`: a new file, or a regular file replaced (permissions kept); through a symlink, the regular
// file it points to. Refuses anything else: a folder, a device (/dev/null), a FIFO, a socket, a dangling symlink
// (never created). The folder must exist. On any failure (disk full, a file size limit) the old file is untouched. Returns "" or why it failed (folder missing, not writable, disk full, ...).
// A read-only file (no write bit for anyone, e.g. mode 0444) is never replaced, even by root: its owner protected it.
std::string writeFileAtomically(const std::string& path, const std::string& text);
std::string writeFileAtomically(const std::string& path, const void* bytes, std::size_t size);

// Why `path` (an existing file, following symlinks) must not be replaced because it is read-only, naming its mode;
// "" when it is writable or does not exist. writeFileAtomically and the commands' output checks share it.
std::string readOnlyFileReason(const std::string& path);

}  // namespace shadowlab

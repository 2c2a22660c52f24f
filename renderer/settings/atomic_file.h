#pragma once
// Replacing a file atomically: a temporary file in the same folder, fsync, rename over the target. Readers see the
// old file or the new one, never half of one; any failure leaves the old file as it was and removes the temporary.
#include <string>

namespace shadowlab {

// Writes `text` to `path` (through a symlink, the file it points to; permissions of a replaced file are kept).
// The folder must exist. Returns "" or why it failed (folder missing, not writable, disk full, ...).
std::string writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace shadowlab

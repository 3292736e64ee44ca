// Atomic replacement of a file: the new contents are written to `FILE.tmp.<pid>` in the same
// directory, flushed to disk, then renamed over FILE. Readers see either the old file or the
// complete new one, never a partial file. On any failure the temporary file is removed and an
// existing FILE is left exactly as it was.
//
// Used by `tolip simulate --csv` and, later, for table images.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace tolip::ground {

// Writes `contents` to `path` atomically. Returns false and sets *error (when not null) to a
// message naming the file and the failed operation.
bool write_file_atomically(const std::string& path, std::string_view contents, std::string* error);

// Renders the contents with `render` (into memory), then writes them as above. When `render`
// returns false, throws, or leaves the stream failed, nothing is written at all.
bool write_file_atomically(const std::string& path,
                           const std::function<bool(std::ostream&)>& render, std::string* error);

// The temporary name used for `path` by this process: "<path>.tmp.<pid>".
std::string atomic_temp_path(const std::string& path);

// ---- test seam ----------------------------------------------------------------------------------
// The steps of a write. A fault hook returning true makes that step fail as if the system call
// had failed (errno EIO), so tests can check the clean-up on every path. nullptr removes it.
enum class AtomicWriteStep : int { kOpen, kWrite, kSync, kClose, kRename };
using AtomicWriteFaultHook = bool (*)(AtomicWriteStep step);
void set_atomic_write_fault_hook(AtomicWriteFaultHook hook);

}  // namespace tolip::ground

// Atomic replacement of a file: the new contents are written to `FILE.tmp.<pid>` in the same
// directory, flushed to disk, then renamed over FILE. Readers see either the old file or the
// complete new one, never a partial file. On any failure the temporary file is removed and an
// existing FILE is left exactly as it was.
//
// Used by every output of the `tolip` program: CSV files, table images and headers, converted
// decks, plots.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace tolip::ground {

// Only regular files are written: an existing `path` that is anything else (a symbolic link, a
// FIFO, a device, a directory, a socket) is refused, left as it is, with the message
// "refusing to replace 'PATH': it is a symbolic link; ..." (check_replaceable_output).
//
// Writes `contents` to `path` atomically. Returns false and sets *error (when not null) to a
// message naming the file and the failed operation.
bool write_file_atomically(const std::string& path, std::string_view contents, std::string* error);

// Renders the contents with `render` (into memory), then writes them as above. When `render`
// returns false, throws, or leaves the stream failed, nothing is written at all.
bool write_file_atomically(const std::string& path, const std::function<bool(std::ostream&)>& render,
                           std::string* error);

// True when `path` does not exist or is a regular file (not followed through a symbolic link);
// otherwise false with *error "refusing to replace 'PATH': it is <kind>; ...". Every write above
// checks it first.
bool check_replaceable_output(const std::string& path, std::string* error);

// True when the two names denote the same file: equal weakly_canonical absolute paths (so
// "a.toml", "./a.toml" and "dir/../a.toml", or a symbolic link to it, are one file), or, for files
// that exist, the same device and inode (hard links). For refusing an output that is an input or
// another output of the same command.
bool names_same_file(const std::string& a, const std::string& b);

// The temporary name used for `path` by this process: "<path>.tmp.<pid>".
std::string atomic_temp_path(const std::string& path);

// ---- test seam ----------------------------------------------------------------------------------
// The steps of a write. A fault hook returning true makes that step fail as if the system call
// had failed (errno EIO), so tests can check the clean-up on every path. nullptr removes it.
enum class AtomicWriteStep : int { kOpen, kWrite, kSync, kClose, kRename };
using AtomicWriteFaultHook = bool (*)(AtomicWriteStep step);
void set_atomic_write_fault_hook(AtomicWriteFaultHook hook);

}  // namespace tolip::ground

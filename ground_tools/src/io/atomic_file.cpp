// Atomic file replacement (atomic_file.hpp): temp file in the same directory, fsync, rename.
#include "tolip_ground/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <sstream>
#include <system_error>

namespace tolip::ground {
namespace {

std::atomic<AtomicWriteFaultHook> g_fault_hook{nullptr};

// True when the test hook asks this step to fail; errno is then EIO.
bool injected_fault(AtomicWriteStep step) {
  const AtomicWriteFaultHook hook = g_fault_hook.load();
  if (hook != nullptr && hook(step)) {
    errno = EIO;
    return true;
  }
  return false;
}

void set_error(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
}

std::string describe(const char* what, const std::string& path, int error_number) {
  return std::string(what) + " '" + path + "': " + std::strerror(error_number);
}

// The directory holding `path` ("." when it has no slash), for the final fsync.
std::string directory_of(const std::string& path) {
  const std::string::size_type slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// What a non-regular file is, for the refusal message.
const char* file_kind(mode_t mode) {
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

bool names_same_file(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  if (a.empty() || b.empty()) return false;
  std::error_code code_a;
  std::error_code code_b;
  const fs::path canonical_a = fs::weakly_canonical(fs::absolute(a, code_a), code_a);
  const fs::path canonical_b = fs::weakly_canonical(fs::absolute(b, code_b), code_b);
  if (!code_a && !code_b && canonical_a == canonical_b) return true;
  // Two names of one existing file (a hard link, a bind mount): the same device and inode.
  struct stat info_a {};
  struct stat info_b {};
  return ::stat(a.c_str(), &info_a) == 0 && ::stat(b.c_str(), &info_b) == 0 &&
         info_a.st_dev == info_b.st_dev && info_a.st_ino == info_b.st_ino;
}

bool check_replaceable_output(const std::string& path, std::string* error) {
  struct stat existing {};
  if (::lstat(path.c_str(), &existing) != 0 || S_ISREG(existing.st_mode)) return true;
  set_error(error, "refusing to replace '" + path + "': it is " + file_kind(existing.st_mode) +
                       "; tolip writes its outputs only as regular files (remove it or name another file)");
  return false;
}

std::string atomic_temp_path(const std::string& path) {
  return path + ".tmp." + std::to_string(static_cast<long long>(::getpid()));
}

void set_atomic_write_fault_hook(AtomicWriteFaultHook hook) { g_fault_hook.store(hook); }

bool write_file_atomically(const std::string& path, std::string_view contents, std::string* error) {
  if (path.empty()) {
    set_error(error, "cannot write a file with an empty name");
    return false;
  }
  // Only a regular file is ever replaced: rename() would otherwise swap a symbolic link, a FIFO,
  // a device or an empty directory for our file.
  if (!check_replaceable_output(path, error)) return false;
  const std::string temp = atomic_temp_path(path);

  // Keep the permissions of a file being replaced; new files get 0666 less the umask.
  mode_t mode = 0666;
  struct stat existing {};
  const bool replacing = ::lstat(path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode);
  if (replacing) mode = existing.st_mode & 07777;

  int fd = -1;
  if (!injected_fault(AtomicWriteStep::kOpen)) {
    // O_EXCL: never write through a stale temp left by a crashed process with our pid; remove it
    // once and retry.
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (fd < 0 && errno == EEXIST) {
      ::unlink(temp.c_str());
      fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    }
  }
  if (fd < 0) {
    set_error(error, describe("cannot create temporary file", temp, errno));
    return false;
  }

  // From here on every failure removes the temporary file.
  auto fail = [&](const char* what, const std::string& name) {
    const int saved = errno;
    if (fd >= 0) ::close(fd);
    ::unlink(temp.c_str());
    set_error(error, describe(what, name, saved));
    return false;
  };

  if (replacing && ::fchmod(fd, mode) != 0) return fail("cannot set permissions of", temp);

  const char* data = contents.data();
  std::size_t remaining = contents.size();
  while (remaining > 0) {
    if (injected_fault(AtomicWriteStep::kWrite)) return fail("cannot write", temp);
    const ssize_t written = ::write(fd, data, remaining);
    if (written < 0) {
      if (errno == EINTR) continue;
      return fail("cannot write", temp);
    }
    data += written;
    remaining -= static_cast<std::size_t>(written);
  }
  if (contents.empty() && injected_fault(AtomicWriteStep::kWrite)) return fail("cannot write", temp);
  if (injected_fault(AtomicWriteStep::kSync) || ::fsync(fd) != 0) return fail("cannot flush", temp);
  const int fd_to_close = fd;
  fd = -1;
  if (injected_fault(AtomicWriteStep::kClose)) {
    ::close(fd_to_close);
    return fail("cannot close", temp);
  }
  if (::close(fd_to_close) != 0) return fail("cannot close", temp);
  // Once more just before the rename: the path may have been replaced meanwhile.
  if (!check_replaceable_output(path, error)) {
    ::unlink(temp.c_str());
    return false;
  }
  if (injected_fault(AtomicWriteStep::kRename) || ::rename(temp.c_str(), path.c_str()) != 0) {
    return fail("cannot replace", path);
  }

  // Make the rename itself durable; a failure here cannot undo it and is not reported.
  const int dir_fd = ::open(directory_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    (void)::fsync(dir_fd);
    ::close(dir_fd);
  }
  return true;
}

bool write_file_atomically(const std::string& path, const std::function<bool(std::ostream&)>& render,
                           std::string* error) {
  std::ostringstream buffer;
  bool rendered = false;
  try {
    rendered = render && render(buffer) && static_cast<bool>(buffer);
  } catch (const std::exception& e) {
    set_error(error, "cannot produce the contents of '" + path + "': " + e.what());
    return false;
  } catch (...) {
    set_error(error, "cannot produce the contents of '" + path + "': unknown exception");
    return false;
  }
  if (!rendered) {
    set_error(error, "cannot produce the contents of '" + path + "'");
    return false;
  }
  return write_file_atomically(path, buffer.view(), error);
}

}  // namespace tolip::ground

// The capped reader of every input file (capped_read.hpp).
#include "tolip_ground/capped_read.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

namespace tolip::ground {

bool read_file_capped(const std::string& path, std::size_t max_bytes, const std::string& kind,
                      std::string* contents, std::string* error) {
  auto fail = [&](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  const std::string too_large = "more than " + std::to_string(max_bytes) + " bytes: a " + kind +
                                " is at most " + std::to_string(max_bytes) +
                                " bytes (docs/cli.md, \"Input limits\")";
  if (path.empty()) return fail("cannot open the " + kind + ": the file name is empty");
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return fail("cannot open the " + kind + ": " + std::strerror(errno));
  struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
  } closer{fd};

  struct stat info {};
  if (::fstat(fd, &info) != 0) return fail("cannot read the " + kind + ": " + std::strerror(errno));
  if (S_ISDIR(info.st_mode)) return fail("is a directory, not a " + kind);
  if (S_ISREG(info.st_mode) && info.st_size > 0 && static_cast<std::size_t>(info.st_size) > max_bytes) {
    return fail(too_large);
  }

  // Read up to the cap, then probe for one byte more: that byte alone says the file is too large
  // (probed on the side, so the string never grows past the cap).
  std::string text;
  char buffer[65536];
  for (;;) {
    const bool probing = text.size() == max_bytes;
    const std::size_t want = probing ? 1 : std::min(sizeof buffer, max_bytes - text.size());
    const ssize_t got = ::read(fd, buffer, want);
    if (got < 0) {
      if (errno == EINTR) continue;
      return fail("cannot read the " + kind + ": " + std::strerror(errno));
    }
    if (got == 0) break;
    if (probing) return fail(too_large);
    text.append(buffer, static_cast<std::size_t>(got));
  }
  *contents = std::move(text);
  return true;
}

}  // namespace tolip::ground

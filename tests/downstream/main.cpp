// Links the installed core and calls into it; prints "kOk" and exits 0 when it works.
#include <cstdio>
#include <cstring>

#include "tolip/core/status.hpp"

int main() {
  const char* name = tolip::status_name(tolip::Status::kOk);
  std::printf("%s\n", name);
  return std::strcmp(name, "kOk") == 0 ? 0 : 1;
}

// The one source compiled with the repository's absolute paths (see repository_paths.hpp).
#include "support/repository_paths.hpp"

namespace tolip::repository_paths {

const char* source_dir() { return TOLIP_SOURCE_DIR; }
const char* binary_dir() { return TOLIP_BINARY_DIR; }
const char* reference_dir() { return TOLIP_REFERENCE_DIR; }
const char* examples_dir() { return TOLIP_EXAMPLES_DIR; }
const char* tolip_executable() { return TOLIP_EXECUTABLE; }
const char* pil_image() { return TOLIP_PIL_IMAGE; }

}  // namespace tolip::repository_paths

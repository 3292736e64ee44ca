// Where the tests and the benchmarks find the repository's files and the built programs.
//
// The folders are compiled into one source, repository_paths.cpp, and into no other: no other
// test or benchmark source has an absolute path in its compile command, so a copy of the
// repository in another folder with the same build folder inside it (the clean-clone check,
// tests/scripts/check_clean_clone.sh) compiles them from the compiler cache (scripts/lib/deps.sh).
// Each function returns a NUL-terminated path without a trailing slash; none allocates.
#pragma once

namespace tolip::repository_paths {

const char* source_dir();        // the repository root
const char* binary_dir();        // the build folder (CMake's PROJECT_BINARY_DIR)
const char* reference_dir();     // tests/reference: the independent reference data
const char* examples_dir();      // examples: the bundled decks
const char* tolip_executable();  // the built `tolip` program
const char* pil_image();         // the Cortex-M7 PIL image (build-cortex-m7/, when built)

}  // namespace tolip::repository_paths

# shellcheck shell=bash
# Shared helpers for scripts/setup.sh and scripts/test.sh: Debian packages the build needs,
# installed only when missing. Source this file; it defines functions and changes nothing.

# Everything needed to configure, build, test and benchmark the project.
TOLIP_DEBIAN_PACKAGES=(
  cmake g++ make
  libeigen3-dev
  libgtest-dev googletest
  libbenchmark-dev
  libcli11-dev
  libtomlplusplus-dev
  nlohmann-json3-dev
  python3
  hyperfine
  # The radar tests measure the look angles against GeographicLib (tests/core/radar_test.cpp).
  libgeographiclib-dev
  # Repository_SourcesFollowClangFormat: scripts/format.sh --check against .clang-format.
  clang-format
  # tolip plot: PNG and SVG figures are drawn by gnuplot (docs/cli.md "tolip plot"); the -nox
  # build has the pngcairo and svg terminals without pulling in X11.
  gnuplot-nox
  # The Monte Carlo dispersions under MPI (optional at build time: tolip_montecarlo_mpi is built
  # when CMake finds MPI; docs/theory/dispersions.md).
  libopenmpi-dev openmpi-bin
  # The bare-metal Cortex-M7 target (CMakePresets.json preset cortex-m7, docs/target.md): the
  # cross compiler, newlib and libstdc++ for arm-none-eabi, and QEMU to run the image.
  gcc-arm-none-eabi
  libnewlib-arm-none-eabi
  libstdc++-arm-none-eabi-newlib
  qemu-system-arm
  # Certification-style evidence (issue 14; docs/verification/): clang-tidy and cppcheck for
  # StaticAnalysis_* (scripts/static_analysis.sh), gcovr for the coverage preset
  # (scripts/coverage.sh), clang 14 with its libFuzzer and sanitizer runtimes for the fuzz preset
  # (scripts/fuzz.sh).
  clang-tidy cppcheck
  gcovr
  clang-14 libclang-rt-14-dev
)

# Wanted, not needed: the compiler cache of tolip_configure_and_build (below), which serves the
# clean-clone check's second build of the project. When it cannot be installed (no network, say)
# the scripts warn and build without it.
TOLIP_OPTIONAL_DEBIAN_PACKAGES=(ccache)

# True when the package is fully installed ("install ok installed"; a removed package whose
# configuration files remain is reported by dpkg -s but is not usable).
tolip_package_installed() {
  local status
  status=$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null) || return 1
  [[ "$status" == "install ok installed" ]]
}

# Runs a command as root: directly when already root, through sudo otherwise.
tolip_as_root() {
  if [[ "$(id -u)" -eq 0 ]]; then
    "$@"
  elif command -v sudo >/dev/null 2>&1; then
    sudo "$@"
  else
    echo "error: need root (or sudo) to run: $*" >&2
    return 1
  fi
}

# Installs the packages of TOLIP_DEBIAN_PACKAGES that are missing; does nothing when none is.
tolip_ensure_packages() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "error: dpkg-query not found; these scripts support Debian 12 (bookworm)" >&2
    return 1
  fi
  local missing=() pkg
  for pkg in "${TOLIP_DEBIAN_PACKAGES[@]}"; do
    tolip_package_installed "$pkg" || missing+=("$pkg")
  done
  local optional=()
  for pkg in "${TOLIP_OPTIONAL_DEBIAN_PACKAGES[@]}"; do
    tolip_package_installed "$pkg" || optional+=("$pkg")
  done
  if [[ ${#missing[@]} -eq 0 && ${#optional[@]} -eq 0 ]]; then
    echo "-- all required Debian packages are installed"
    return 0
  fi
  if [[ ${#missing[@]} -gt 0 ]]; then
    echo "-- installing missing Debian packages: ${missing[*]}"
    tolip_as_root env DEBIAN_FRONTEND=noninteractive apt-get update
    tolip_as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
  fi
  if [[ ${#optional[@]} -gt 0 ]]; then
    echo "-- installing optional Debian packages: ${optional[*]}"
    # The package lists are fresh when the required packages were just installed.
    [[ ${#missing[@]} -gt 0 ]] || tolip_as_root env DEBIAN_FRONTEND=noninteractive apt-get update || true
    tolip_as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${optional[@]}" ||
      echo "warning: could not install ${optional[*]}; building without them (slower, same results)" >&2
  fi
}

# Configures (Release) and builds the project into the given build directory with two jobs:
# every target, or only the targets named after the two folders (setup.sh builds just `tolip`).
#
# The compiler cache: a new build directory compiles through ccache when the optional package above
# is installed, unless CMAKE_CXX_COMPILER_LAUNCHER in the environment names another launcher; an
# existing build directory keeps what it was configured with. CCACHE_BASEDIR is the source folder, so ccache hashes
# the project's paths relative to it and a copy of the repository elsewhere with the same build
# folder (the clean-clone check's copy, tests/scripts/check_clean_clone.sh) is served from the
# cache: CI then compiles the project once, not twice. A hit still needs every header the compile
# reads to exist with the same contents, so a copy that lacked one would fail as before.
tolip_configure_and_build() {
  local source_dir=$1 build_dir=$2
  shift 2
  local launcher=()
  if [[ ! -f "$build_dir/CMakeCache.txt" && -z "${CMAKE_CXX_COMPILER_LAUNCHER:-}" ]] &&
     command -v ccache >/dev/null 2>&1; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
  cmake -S "$source_dir" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}"
  if [[ $# -gt 0 ]]; then
    CCACHE_BASEDIR="$source_dir" cmake --build "$build_dir" -j2 --target "$@"
  else
    CCACHE_BASEDIR="$source_dir" cmake --build "$build_dir" -j2
  fi
}

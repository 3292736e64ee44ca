// tolip: command-line entry point. The command line (CLI11) and the subcommands live in
// ground_tools/src/commands/ (run_tolip); docs/cli.md is the reference.
#include <exception>
#include <iostream>

#include "tolip_ground/commands.hpp"

int main(int argc, char** argv) {
  try {
    return tolip::ground::run_tolip(argc, argv, std::cout, std::cerr);
  } catch (const std::exception& e) {
    std::cerr << "tolip: internal error: " << e.what() << '\n';
  } catch (...) {
    std::cerr << "tolip: internal error\n";
  }
  return tolip::ground::kExitFailure;
}

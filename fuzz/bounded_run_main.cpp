// A bounded run of a fuzz target without libFuzzer (issue 14; docs/verification/fuzzing.md
// "Bounded runs in the test command"): the target's own LLVMFuzzerTestOneInput, linked into the
// Release (GCC) and asan builds, so that the README's test command exercises every target and not
// only the clang fuzz preset. It is not a coverage-guided campaign: it replays the seed corpus and
// the regressions, then feeds a fixed number of inputs mutated by a seeded generator (byte flips,
// random bytes, erased, duplicated and spliced ranges), so a failure reproduces from the same
// arguments. Any crash, abort, escaping exception or sanitizer report ends the process non-zero.
//
//   tolip_fuzz_TARGET_bounded RUNS SEED DIR...
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using Bytes = std::vector<std::uint8_t>;

constexpr std::size_t kMaxInputBytes = 65536;  // scripts/fuzz.sh's -max_len

std::vector<Bytes> read_corpus(const std::vector<std::string>& directories) {
  std::vector<std::filesystem::path> files;
  for (const std::string& directory : directories) {
    if (!std::filesystem::is_directory(directory)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
      if (entry.is_regular_file()) files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());  // the order, and so the run, does not depend on the file system
  std::vector<Bytes> corpus;
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    corpus.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return corpus;
}

// One to eight edits of `input`, each chosen by the generator.
Bytes mutate(const Bytes& input, const Bytes& other, std::mt19937_64* random) {
  Bytes out = input;
  std::uniform_int_distribution<int> edits(1, 8);
  const int n = edits(*random);
  for (int e = 0; e < n; ++e) {
    const auto at = [&](std::size_t size) {
      return size == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, size - 1)(*random);
    };
    switch (std::uniform_int_distribution<int>(0, 4)(*random)) {
      case 0:  // flip one bit
        if (!out.empty()) out[at(out.size())] ^= static_cast<std::uint8_t>(1u << at(8));
        break;
      case 1:  // one random byte
        if (!out.empty()) out[at(out.size())] = static_cast<std::uint8_t>(at(256));
        break;
      case 2: {  // erase a range of up to 64 bytes
        if (out.empty()) break;
        const std::size_t begin = at(out.size());
        const std::size_t length = std::min<std::size_t>(out.size() - begin, 1 + at(64));
        out.erase(out.begin() + static_cast<std::ptrdiff_t>(begin),
                  out.begin() + static_cast<std::ptrdiff_t>(begin + length));
        break;
      }
      case 3: {  // duplicate a range of up to 64 bytes in place
        if (out.empty()) break;
        const std::size_t begin = at(out.size());
        const std::size_t length = std::min<std::size_t>(out.size() - begin, 1 + at(64));
        const Bytes range(out.begin() + static_cast<std::ptrdiff_t>(begin),
                          out.begin() + static_cast<std::ptrdiff_t>(begin + length));
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(at(out.size() + 1)), range.begin(), range.end());
        break;
      }
      default: {  // splice in up to 256 bytes of another corpus input
        if (other.empty()) break;
        const std::size_t begin = at(other.size());
        const std::size_t length = std::min<std::size_t>(other.size() - begin, 1 + at(256));
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(at(out.size() + 1)),
                   other.begin() + static_cast<std::ptrdiff_t>(begin),
                   other.begin() + static_cast<std::ptrdiff_t>(begin + length));
        break;
      }
    }
  }
  if (out.size() > kMaxInputBytes) out.resize(kMaxInputBytes);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s RUNS SEED DIR...\n", argv[0]);
    return 2;
  }
  const long runs = std::strtol(argv[1], nullptr, 10);
  const unsigned long long seed = std::strtoull(argv[2], nullptr, 10);
  const std::vector<Bytes> corpus = read_corpus(std::vector<std::string>(argv + 3, argv + argc));
  if (corpus.empty() || runs < 0) {
    std::fprintf(stderr, "%s: no corpus input in the directories given (or RUNS < 0)\n", argv[0]);
    return 2;
  }
  for (const Bytes& input : corpus) LLVMFuzzerTestOneInput(input.data(), input.size());
  std::mt19937_64 random(seed);
  std::uniform_int_distribution<std::size_t> pick(0, corpus.size() - 1);
  for (long i = 0; i < runs; ++i) {
    const Bytes input = mutate(corpus[pick(random)], corpus[pick(random)], &random);
    LLVMFuzzerTestOneInput(input.data(), input.size());
  }
  std::printf("%s: %zu corpus inputs and %ld mutated inputs (seed %llu): no crash\n", argv[0], corpus.size(),
              runs, seed);
  return 0;
}

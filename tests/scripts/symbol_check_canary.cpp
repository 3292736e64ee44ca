// Deliberately violates the core's rules (heap and exceptions) so that the symbol check can be
// shown to fail on it (CTest: Core_SymbolCheckRejectsAllocatorAndExceptionUse).
#include <stdexcept>
#include <vector>

namespace tolip::test {

int symbol_check_canary(int n) {
  std::vector<int> values(static_cast<unsigned>(n), 1);
  if (n > 100) throw std::runtime_error("too many");
  int* extra = new int(n);
  const int result = values.empty() ? *extra : values.front() + *extra;
  delete extra;
  return result;
}

}  // namespace tolip::test

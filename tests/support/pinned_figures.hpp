// The pinned figures of the reference optimization (examples/scout/mission.toml from its crude
// program), written once for every test that checks an analysis leaves them untouched. The test
// that pins them is Sec22Optimizer.ReferenceOptimizationIsPinnedToAllItsDigits (tests/core/
// optimizer_test.cpp); change them only with a change that is meant to move them, and say so in
// its commit message (the last move: the exact Sec. 14 integral, 307.6771784567345 ->
// 307.6782575333464 lb).
#pragma once

namespace tolip::test {

inline constexpr double kPinnedReferencePayloadLb = 307.6782575333464;
inline constexpr int kPinnedReferenceForwardRuns = 19;
inline constexpr int kPinnedReferenceBackwardRuns = 15;

}  // namespace tolip::test

// Rules of the core: the flight-side table loader (stage, validate, commit, rejections), the
// guidance executor over a whole flight timeline and the control law allocate nothing.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "support/allocation_counter.hpp"
#include "support/guidance_table_fixture.hpp"
#include "tolip/table/control_law.hpp"
#include "tolip/table/crc32.hpp"
#include "tolip/table/guidance_executor.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip/table/table_service.hpp"

namespace tolip {
namespace {

TEST(CoreNoHeap, TableLoaderExecutorAndControlLawAllocateNothing) {
  static GuidanceTableService service;
  static std::uint8_t good[kTableImageSize];
  static std::uint8_t other[kTableImageSize];
  static std::uint8_t bad[kTableImageSize];
  const GuidanceTable table_a = test::make_test_table(0);
  const GuidanceTable table_b = test::make_test_table(1);

  test::AllocationScope scope;
  Status encode_a = encode_table_image(table_a, good, sizeof good);
  Status encode_b = encode_table_image(table_b, other, sizeof other);
  std::memcpy(bad, other, sizeof bad);
  bad[kOffsetSegments + 20] ^= 0x40;
  const Status load_a = service.load(good, sizeof good);
  const Status load_bad = service.load(bad, sizeof bad);
  const Status load_short = service.load(good, sizeof good - 1);
  const Status stage_b = service.stage(other, sizeof other);
  const Status validate_b = service.validate_staged();
  const Status commit_b = service.commit();
  const std::uint32_t crc = crc32(good, kOffsetCrc);

  GuidanceExecutor executor(service);
  double theta_sum = 0.0;
  const int failures = test::fly_test_timeline(executor, [&theta_sum](const GuidanceCommand& command) {
    ControlDeflection deflection;
    const Status law = attitude_control_deflection(command, command.theta_rad + 0.01, 0.001, &deflection);
    theta_sum += command.theta_rad + deflection.deflection_rad;
    return ok(law);
  });
  const auto allocations = scope.count();

  EXPECT_EQ(encode_a, Status::kOk);
  EXPECT_EQ(encode_b, Status::kOk);
  EXPECT_EQ(load_a, Status::kOk);
  EXPECT_EQ(load_bad, Status::kTableImageCrcMismatch);
  EXPECT_EQ(load_short, Status::kTableImageTruncated);
  EXPECT_EQ(stage_b, Status::kOk);
  EXPECT_EQ(validate_b, Status::kOk);
  EXPECT_EQ(commit_b, Status::kOk);
  EXPECT_EQ(crc, stored_table_crc(good));
  EXPECT_EQ(failures, 0);
  EXPECT_NE(theta_sum, 0.0);  // the work really happened
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip

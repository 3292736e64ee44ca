// Flight-side table loader (tolip/table/table_service.hpp): stage, validate, commit; every
// rejection cause is named, and after each rejection the previously active table still executes
// unchanged (same table, same CRC, same commands bit for bit).
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "support/guidance_table_fixture.hpp"
#include "tolip/table/guidance_executor.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip/table/table_service.hpp"

namespace tolip {
namespace {

using test::encode;
using test::Image;

// Commands of the active table over a whole flight timeline, as bit patterns.
std::vector<std::uint64_t> command_trace(const GuidanceTableService& service) {
  GuidanceExecutor executor(service);
  std::vector<std::uint64_t> trace;
  int next_event = 1;  // kTestTimeline[0] is stage 1 at lift-off
  for (int k = 0; k <= 6500; k += 7) {
    const double t = k / 10.0;
    while (next_event < 10 && test::kTestTimeline[next_event].start_s <= t) {
      EXPECT_EQ(
          executor.stage_event(test::kTestTimeline[next_event].code, test::kTestTimeline[next_event].start_s),
          Status::kOk);
      ++next_event;
    }
    GuidanceCommand command;
    EXPECT_EQ(executor.step(t, &command), Status::kOk);
    for (double value : {command.theta_rad, command.theta_dot_rad_s, command.chi_rad, command.k_theta,
                         command.k_q_s, command.max_deflection_rad}) {
      trace.push_back(std::bit_cast<std::uint64_t>(value));
    }
    trace.push_back(static_cast<std::uint64_t>(command.segment_index + 1));
  }
  return trace;
}

class TableLoader : public ::testing::Test {
 protected:
  void SetUp() override {
    active_image_ = encode(test::make_test_table(0));
    ASSERT_EQ(service_.load(active_image_.data(), active_image_.size()), Status::kOk);
    active_trace_ = command_trace(service_);
    candidate_ = encode(test::make_test_table(1));  // valid, different everywhere
  }

  // Loads `image`, expects `expected`, and checks that table A is still the one executing.
  void expect_rejected_keeping_active(const Image& image, Status expected, const std::string& what) {
    const std::uint32_t commits = service_.commit_count();
    EXPECT_EQ(service_.load(image.data(), image.size()), expected) << what;
    ASSERT_NE(service_.active(), nullptr) << what;
    EXPECT_STREQ(service_.active()->mission_id, "TEST MISSION A") << what;
    EXPECT_EQ(service_.active_crc(), stored_table_crc(active_image_.data())) << what;
    EXPECT_EQ(std::memcmp(service_.active_image(), active_image_.data(), kTableImageSize), 0) << what;
    EXPECT_EQ(service_.commit_count(), commits) << what;
    EXPECT_EQ(command_trace(service_), active_trace_) << what;
  }

  // A copy of the valid candidate with one patch, resealed (correct CRC) unless told otherwise.
  Image patched(const std::function<void(std::uint8_t*)>& patch, bool reseal = true) const {
    Image image = candidate_;
    patch(image.data());
    if (reseal) reseal_table_image(image.data());
    return image;
  }

  GuidanceTableService service_;
  Image active_image_;
  Image candidate_;
  std::vector<std::uint64_t> active_trace_;
};

TEST_F(TableLoader, CommitsAValidImageAtomicallyAndExecutesIt) {
  EXPECT_EQ(service_.commit_count(), 1u);
  EXPECT_EQ(service_.load(candidate_.data(), candidate_.size()), Status::kOk);
  EXPECT_EQ(service_.commit_count(), 2u);
  EXPECT_STREQ(service_.active()->mission_id, "TEST MISSION B");
  EXPECT_EQ(service_.active_crc(), stored_table_crc(candidate_.data()));
  EXPECT_NE(command_trace(service_), active_trace_);
  // And back: the buffers alternate.
  EXPECT_EQ(service_.load(active_image_.data(), active_image_.size()), Status::kOk);
  EXPECT_EQ(command_trace(service_), active_trace_);
}

TEST(TableLoaderEmpty, HasNoActiveTableUntilTheFirstCommit) {
  GuidanceTableService service;
  EXPECT_FALSE(service.has_active_table());
  EXPECT_EQ(service.active(), nullptr);
  EXPECT_EQ(service.active_crc(), 0u);
  GuidanceExecutor executor(service);
  GuidanceCommand command;
  command.theta_rad = 123.0;
  EXPECT_EQ(executor.step(1.0, &command), Status::kNoActiveTable);
  EXPECT_EQ(command.theta_rad, 123.0);  // not modified
  const Image bad(10, 0);
  EXPECT_EQ(service.load(bad.data(), bad.size()), Status::kTableImageTruncated);
  EXPECT_FALSE(service.has_active_table());
}

TEST_F(TableLoader, StagingValidatingAndCommittingAreSeparateSteps) {
  EXPECT_EQ(service_.commit(), Status::kTableNotStaged);
  EXPECT_EQ(service_.validate_staged(), Status::kTableNotStaged);
  ASSERT_EQ(service_.stage(candidate_.data(), candidate_.size()), Status::kOk);
  EXPECT_EQ(service_.commit(), Status::kTableNotValidated);  // staged is not enough
  EXPECT_STREQ(service_.active()->mission_id, "TEST MISSION A");
  ASSERT_EQ(service_.validate_staged(), Status::kOk);
  EXPECT_STREQ(service_.active()->mission_id, "TEST MISSION A");  // validated, not yet active
  ASSERT_EQ(service_.commit(), Status::kOk);
  EXPECT_STREQ(service_.active()->mission_id, "TEST MISSION B");
  EXPECT_EQ(service_.commit(), Status::kTableNotStaged);  // nothing new staged
}

TEST_F(TableLoader, RejectsTruncatedImageAndKeepsActiveTable) {
  Image image = candidate_;
  image.pop_back();
  expect_rejected_keeping_active(image, Status::kTableImageTruncated, "one byte short");
  expect_rejected_keeping_active(Image(kTableHeaderSize, 0), Status::kTableImageTruncated, "header only");
  expect_rejected_keeping_active(Image(), Status::kTableImageTruncated, "empty");
}

TEST_F(TableLoader, RejectsOversizedImageAndKeepsActiveTable) {
  Image image = candidate_;
  image.push_back(0);
  expect_rejected_keeping_active(image, Status::kTableImageSizeMismatch, "one byte long");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { put_u32_le(b + kOffsetImageSize, 1581); }),
                                 Status::kTableImageSizeMismatch, "size field 1581");
}

TEST_F(TableLoader, RejectsBadMagicAndKeepsActiveTable) {
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { b[0] = 'X'; }), Status::kTableImageBadMagic,
                                 "magic XLGT");
  expect_rejected_keeping_active(Image(kTableImageSize, 0), Status::kTableImageBadMagic, "all zero");
}

TEST_F(TableLoader, RejectsWrongVersionAndKeepsActiveTable) {
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { put_u16_le(b + kOffsetFormatVersion, 1); }),
                                 Status::kTableImageUnsupportedVersion, "version 1");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { put_u16_le(b + kOffsetFormatVersion, 2); }),
                                 Status::kTableImageUnsupportedVersion,
                                 "version 2 field in a version-3 image");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { put_u16_le(b + kOffsetFormatVersion, 4); }),
                                 Status::kTableImageUnsupportedVersion, "version 4");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { put_u16_le(b + kOffsetFormatVersion, 0); }),
                                 Status::kTableImageUnsupportedVersion, "version 0");
}

TEST_F(TableLoader, RejectsLayoutMismatchAndKeepsActiveTable) {
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { put_u16_le(b + kOffsetHeaderSize, 64); }),
                                 Status::kTableImageLayoutMismatch, "header size 64");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { put_u16_le(b + kOffsetSegmentCapacity, 16); }),
                                 Status::kTableImageLayoutMismatch, "capacity 16");
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { put_u16_le(b + kOffsetSegmentRecordSize, 24); }),
      Status::kTableImageLayoutMismatch, "record size 24");
}

TEST_F(TableLoader, RejectsCrcMismatchAndKeepsActiveTable) {
  // One flipped bit anywhere before the CRC, and a damaged CRC itself.
  for (std::size_t at : {std::size_t{20}, kOffsetLiftoffDuration + 3, kOffsetSegments + 17, kOffsetCrc - 1}) {
    expect_rejected_keeping_active(patched([at](std::uint8_t* b) { b[at] ^= 0x10; }, false),
                                   Status::kTableImageCrcMismatch, "bit flip at " + std::to_string(at));
  }
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { b[kOffsetCrc] ^= 0x01; }, false),
                                 Status::kTableImageCrcMismatch, "damaged CRC");
}

TEST_F(TableLoader, RejectsTooManySegmentsAndKeepsActiveTable) {
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { put_u16_le(b + kOffsetSegmentCount, 16); }),
                                 Status::kTooManyLinearSegments, "count 16");
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { put_u16_le(b + kOffsetSegmentCount, 0xFFFF); }),
      Status::kTooManyLinearSegments, "count 65535");
}

TEST_F(TableLoader, RejectsNonMonotonicTimesAndKeepsActiveTable) {
  // Two segments of stage 1 in decreasing start order.
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { put_f64_le(b + kOffsetSegments + kTableSegmentRecordSize + 8, 2.0); }),
      Status::kSegmentTimesNotMonotonic, "stage 1 starts 3 then 2");
  // Equal start times.
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { put_f64_le(b + kOffsetSegments + kTableSegmentRecordSize + 8, 3.0); }),
      Status::kSegmentTimesNotMonotonic, "stage 1 starts 3 then 3");
  // A stage out of flight order: segment 3 (stage 2) moved back to coast 7 before segment 4 (stage 2).
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { put_u16_le(b + kOffsetSegments + 3 * kTableSegmentRecordSize, 7); }),
      Status::kSegmentTimesNotMonotonic, "stages 6 7 2");
}

TEST_F(TableLoader, RejectsNaNAndInfinityAndKeepsActiveTable) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::size_t theta1 = kOffsetSegments + kTableSegmentRecordSize + kSegmentOffsetTheta;
  const std::size_t rate2 = kOffsetSegments + 2 * kTableSegmentRecordSize + kSegmentOffsetRate;
  const std::size_t start0 = kOffsetSegments + kSegmentOffsetStartTime;
  struct Case {
    std::size_t at;
    double value;
    const char* what;
  };
  const Case cases[] = {
      {theta1, nan, "NaN theta"},
      {rate2, inf, "+inf rate"},
      {rate2, -inf, "-inf rate"},
      {start0, nan, "NaN start"},
      {kOffsetLiftoffDuration, inf, "inf lift-off"},
      {kOffsetMaxPitchRate, nan, "NaN rate limit"},
      {kOffsetMaxDeflection, nan, "NaN deflection"},
      {kOffsetStage5Chi, -inf, "-inf chi 5"},
      {kOffsetStageGains + 3 * kTableStageGainRecordSize + kGainOffsetKq, nan, "NaN gain"},
  };
  for (const Case& c : cases) {
    expect_rejected_keeping_active(patched([&c](std::uint8_t* b) { put_f64_le(b + c.at, c.value); }),
                                   Status::kValueNotFinite, c.what);
  }
}

TEST_F(TableLoader, RejectsRateOutsideLimitsAndKeepsActiveTable) {
  const GuidanceTable table = test::make_test_table(1);
  const std::size_t rate1 = kOffsetSegments + kTableSegmentRecordSize + kSegmentOffsetRate;
  expect_rejected_keeping_active(
      patched([&](std::uint8_t* b) { put_f64_le(b + rate1, -1.01 * table.max_pitch_rate_rad_s); }),
      Status::kSegmentRateExceedsLimit, "rate 1.01 x max");
  expect_rejected_keeping_active(
      patched([&](std::uint8_t* b) { put_f64_le(b + rate1, 2.0 * table.max_pitch_rate_rad_s); }),
      Status::kSegmentRateExceedsLimit, "rate 2 x max, positive");
  // Lowering the image's own limit below a segment's rate is the same fault.
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { put_f64_le(b + kOffsetMaxPitchRate, 1.0 * kDegToRad); }),
      Status::kSegmentRateExceedsLimit, "limit 1 deg/s under a 2 deg/s segment");
}

TEST_F(TableLoader, RejectsReservedBytesAndBadTextAndKeepsActiveTable) {
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { b[kOffsetHeaderReserved1] = 1; }),
                                 Status::kTableImageReservedBytesSet, "header reserved word");
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { b[kOffsetHeaderReserved2 + kHeaderReserved2Bytes - 1] = 1; }),
      Status::kTableImageReservedBytesSet, "header reserved tail");
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { b[kOffsetSegments + kSegmentOffsetReserved] = 1; }),
      Status::kTableImageReservedBytesSet, "segment reserved bytes");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { b[kOffsetSchedule - 1] = 1; }),
                                 Status::kTableImageReservedBytesSet, "unused segment record");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { b[kOffsetCrc - 1] = 1; }),
                                 Status::kTableImageReservedBytesSet, "unused gain schedule record");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { b[kOffsetMissionId + 2] = 0x07; }),
                                 Status::kTableImageTextInvalid, "control character in mission id");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { b[kOffsetMissionId + 31] = 'Z'; }),
                                 Status::kTableImageTextInvalid, "text after the NUL padding");
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { std::memset(b + kOffsetGeneratorVersion, 0, 16); }),
      Status::kTableImageTextInvalid, "empty generator version");
}

TEST_F(TableLoader, RejectsOutOfRangeValuesAndBadStageCodesAndKeepsActiveTable) {
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { put_f64_le(b + kOffsetLiftoffDuration, -3.0); }),
      Status::kTableLiftoffDurationOutOfRange, "negative lift-off");
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { put_f64_le(b + kOffsetSegments + kSegmentOffsetTheta, 7.0); }),
      Status::kSegmentAttitudeOutOfRange, "theta 7 rad");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { put_u64_le(b + kOffsetCreatedUnixS, ~0ull); }),
                                 Status::kTableCreationTimeOutOfRange, "stamp beyond year 9999");
  expect_rejected_keeping_active(
      patched([](std::uint8_t* b) { put_u16_le(b + kOffsetSegments + 7 * kTableSegmentRecordSize, 9); }),
      Status::kSegmentStageInvalid, "segment in coast 9 (spun under IP(9) = 1)");
  expect_rejected_keeping_active(patched([](std::uint8_t* b) { put_u16_le(b + kOffsetSpinOption, 4); }),
                                 Status::kTableSpinOptionOutOfRange, "IP(9) = 4");
}

TEST_F(TableLoader, AValidImageAfterRejectionsIsStillAccepted) {
  Image bad = candidate_;
  bad[100] ^= 1;
  EXPECT_EQ(service_.load(bad.data(), bad.size()), Status::kTableImageCrcMismatch);
  EXPECT_EQ(service_.validate_staged(), Status::kTableNotStaged);  // the rejected image is gone
  EXPECT_EQ(service_.commit(), Status::kTableNotStaged);
  EXPECT_EQ(service_.load(candidate_.data(), candidate_.size()), Status::kOk);
  EXPECT_STREQ(service_.active()->mission_id, "TEST MISSION B");
}

}  // namespace
}  // namespace tolip

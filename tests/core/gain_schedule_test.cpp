// Issue 16, table image format version 3: autopilot gain schedule records (stage code, stage time,
// K_theta, K_q). The codec writes them at their documented offsets byte by byte, the loader
// validates them before activation (keeping the active table on every fault), the executor
// interpolates linearly in stage time within a stage and holds at the ends (checked against an
// interpolation written here), and a version-2 image is rejected by name.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <string>

#include "support/guidance_table_fixture.hpp"
#include "tolip/table/guidance_executor.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip/table/table_service.hpp"

namespace tolip {
namespace {

using test::encode;
using test::Image;

// Stage 1: four points, stage 2: two, stage 3: one (held everywhere); coasts fly their records.
GuidanceTable scheduled_table() {
  GuidanceTable t = test::make_test_table(0);
  const GainSchedulePoint points[] = {
      {1, 0.0, 1.5, 0.40}, {1, 10.0, 1.1, 0.30}, {1, 25.0, 0.7, 0.22}, {1, 40.0, 2.0, 0.50},
      {2, 5.0, 0.9, 0.6},  {2, 30.0, 1.3, 0.8},  {3, 12.0, 0.8, 0.45},
  };
  t.schedule_count = static_cast<int>(sizeof points / sizeof points[0]);
  for (int i = 0; i < t.schedule_count; ++i) t.schedule[i] = points[i];
  return t;
}

// Independent: the schedule points of `code`, linear between neighbours, held outside.
StageGains expected_gains(const GuidanceTable& t, int code, double tau) {
  double times[kMaxGainSchedulePoints], kt[kMaxGainSchedulePoints], kq[kMaxGainSchedulePoints];
  int n = 0;
  for (int i = 0; i < t.schedule_count; ++i) {
    if (t.schedule[i].stage_code != code) continue;
    times[n] = t.schedule[i].stage_time_s;
    kt[n] = t.schedule[i].k_theta;
    kq[n] = t.schedule[i].k_q_s;
    ++n;
  }
  if (n == 0) return t.gains[code - 1];
  if (tau <= times[0]) return StageGains{kt[0], kq[0]};
  if (tau >= times[n - 1]) return StageGains{kt[n - 1], kq[n - 1]};
  int j = 0;
  while (times[j + 1] <= tau) ++j;
  const double w = (tau - times[j]) / (times[j + 1] - times[j]);
  return StageGains{(1.0 - w) * kt[j] + w * kt[j + 1], (1.0 - w) * kq[j] + w * kq[j + 1]};
}

TEST(GainSchedule, Issue16_RecordsSitAtTheirDocumentedOffsetsAndRoundTripBitForBit) {
  const GuidanceTable table = scheduled_table();
  const Image image = encode(table);
  ASSERT_EQ(image.size(), 1580u);
  EXPECT_EQ(get_u16_le(image.data() + 84), 7u);
  // Record 2 (stage 1, 25 s) at 808 + 2 * 32.
  const std::uint8_t* r = image.data() + 808 + 2 * 32;
  EXPECT_EQ(get_u16_le(r), 1u);
  for (int i = 2; i < 8; ++i) EXPECT_EQ(r[i], 0);
  EXPECT_EQ(get_f64_le(r + 8), 25.0);
  EXPECT_EQ(get_f64_le(r + 16), 0.7);
  EXPECT_EQ(get_f64_le(r + 24), 0.22);
  for (std::size_t i = 808 + 7 * 32; i < 1576; ++i) ASSERT_EQ(image[i], 0) << i;
  GuidanceTable decoded;
  ASSERT_EQ(decode_table_image(image.data(), image.size(), &decoded), Status::kOk);
  ASSERT_EQ(decoded.schedule_count, table.schedule_count);
  for (int i = 0; i < table.schedule_count; ++i) {
    EXPECT_EQ(decoded.schedule[i].stage_code, table.schedule[i].stage_code);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(decoded.schedule[i].stage_time_s),
              std::bit_cast<std::uint64_t>(table.schedule[i].stage_time_s));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(decoded.schedule[i].k_theta),
              std::bit_cast<std::uint64_t>(table.schedule[i].k_theta));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(decoded.schedule[i].k_q_s),
              std::bit_cast<std::uint64_t>(table.schedule[i].k_q_s));
  }
}

TEST(GainSchedule, Issue16_ExecutorInterpolatesWithinAStageAndHoldsAtTheEnds) {
  const GuidanceTable table = scheduled_table();
  const Image image = encode(table);
  static GuidanceTableService service;
  ASSERT_EQ(service.load(image.data(), image.size()), Status::kOk);
  GuidanceExecutor executor(service);
  int next_event = 1;
  double worst = 0.0;
  int checked = 0;
  for (int k = 0; k <= 6500; k += 3) {
    const double t = k / 10.0;
    while (next_event < 10 && test::kTestTimeline[next_event].start_s <= t) {
      ASSERT_EQ(
          executor.stage_event(test::kTestTimeline[next_event].code, test::kTestTimeline[next_event].start_s),
          Status::kOk);
      ++next_event;
    }
    GuidanceCommand command;
    ASSERT_EQ(executor.step(t, &command), Status::kOk);
    const int code = executor.stage_in_force();
    const StageGains want = expected_gains(table, code, t - executor.stage_start_s(code));
    worst = std::fmax(worst, std::fabs(command.k_theta - want.k_theta));
    worst = std::fmax(worst, std::fabs(command.k_q_s - want.k_q_s));
    ++checked;
  }
  EXPECT_LT(worst, 1e-14);
  EXPECT_GT(checked, 2000);
  // Exactly the points at the points, the end values held.
  EXPECT_EQ(scheduled_gains(table, 1, 10.0).k_theta, 1.1);
  EXPECT_EQ(scheduled_gains(table, 1, 17.5).k_theta, 0.9);
  EXPECT_EQ(scheduled_gains(table, 1, 90.0).k_q_s, 0.50);
  EXPECT_EQ(scheduled_gains(table, 2, 0.0).k_theta, 0.9);
  EXPECT_EQ(scheduled_gains(table, 3, 0.0).k_q_s, 0.45);
  EXPECT_EQ(scheduled_gains(table, 6, 3.0).k_theta, table.gains[5].k_theta);
}

// Every schedule fault is named before activation, and the active table stays in force.
TEST(GainSchedule, Issue16_LoaderRejectsBadSchedulesBeforeActivation) {
  static GuidanceTableService service;
  const Image good = encode(scheduled_table());
  ASSERT_EQ(service.load(good.data(), good.size()), Status::kOk);
  const std::uint32_t commits = service.commit_count();
  auto patched = [&](auto edit) {
    Image image = good;
    edit(image.data());
    reseal_table_image(image.data());
    return image;
  };
  auto record = [](std::uint8_t* b, int i) { return b + kOffsetSchedule + i * kTableScheduleRecordSize; };
  const struct {
    Image image;
    Status expected;
    const char* what;
  } cases[] = {
      {patched([&](std::uint8_t* b) { put_f64_le(record(b, 2) + 8, 10.0); }),
       Status::kGainScheduleTimesNotMonotonic, "time equal to the previous point's"},
      {patched([&](std::uint8_t* b) { put_f64_le(record(b, 1) + 8, 30.0); }),
       Status::kGainScheduleTimesNotMonotonic, "time going back"},
      {patched([&](std::uint8_t* b) {
         put_u16_le(record(b, 4), 1);
         put_u16_le(record(b, 5), 1);
         put_u16_le(record(b, 6), 1);
       }),
       Status::kGainScheduleTimesNotMonotonic, "stage 2 times under stage 1"},
      {patched([&](std::uint8_t* b) { put_u16_le(record(b, 0), 2); }), Status::kGainScheduleStageInvalid,
       "stage 2 before stage 1"},
      {patched([&](std::uint8_t* b) { put_u16_le(record(b, 6), 4); }), Status::kGainScheduleStageInvalid,
       "a spun stage"},
      {patched([&](std::uint8_t* b) { put_u16_le(record(b, 6), 11); }), Status::kGainScheduleStageInvalid,
       "stage code 11"},
      {patched([&](std::uint8_t* b) { put_f64_le(record(b, 0) + 8, -1.0); }),
       Status::kGainScheduleTimeOutOfRange, "negative stage time"},
      {patched([&](std::uint8_t* b) { put_f64_le(record(b, 3) + 16, 100.5); }), Status::kTableGainOutOfRange,
       "K_theta above 100"},
      {patched([&](std::uint8_t* b) { put_f64_le(record(b, 3) + 24, -0.1); }), Status::kTableGainOutOfRange,
       "negative K_q"},
      {patched([&](std::uint8_t* b) { put_f64_le(record(b, 3) + 16, std::nan("")); }),
       Status::kValueNotFinite, "NaN K_theta"},
      {patched([&](std::uint8_t* b) { put_u16_le(b + kOffsetScheduleCount, 25); }),
       Status::kTooManyGainSchedulePoints, "count over the capacity"},
      {patched([&](std::uint8_t* b) { put_u16_le(b + kOffsetScheduleCapacity, 23); }),
       Status::kTableImageLayoutMismatch, "capacity field"},
      {patched([&](std::uint8_t* b) { record(b, 1)[3] = 1; }), Status::kTableImageReservedBytesSet,
       "record reserved bytes"},
      {patched([&](std::uint8_t* b) { put_u16_le(b + kOffsetScheduleCount, 6); }),
       Status::kTableImageReservedBytesSet, "a used record past the count"},
  };
  for (const auto& c : cases) {
    EXPECT_EQ(service.load(c.image.data(), c.image.size()), c.expected) << c.what;
    EXPECT_EQ(service.commit_count(), commits) << c.what;
    EXPECT_EQ(std::memcmp(service.active_image(), good.data(), kTableImageSize), 0) << c.what;
  }
  // The encoder refuses the same faults in a table.
  GuidanceTable over = scheduled_table();
  over.schedule_count = kMaxGainSchedulePoints + 1;
  Image out(kTableImageSize);
  EXPECT_EQ(encode_table_image(over, out.data(), out.size()), Status::kTooManyGainSchedulePoints);
}

// A version-2 image (812 bytes, version field 2) is rejected by its version, with a message that
// says why; any other short upload is still truncated.
TEST(GainSchedule, Issue16_Version2ImagesAreRejectedWithTheReason) {
  Image v2(kTableVersion2ImageSize, 0);
  std::memcpy(v2.data(), "TLGT", 4);
  put_u16_le(v2.data() + kOffsetFormatVersion, 2);
  GuidanceTable decoded;
  EXPECT_EQ(decode_table_image(v2.data(), v2.size(), &decoded), Status::kTableImageVersion2);
  static GuidanceTableService service;
  EXPECT_EQ(service.load(v2.data(), v2.size()), Status::kTableImageVersion2);
  EXPECT_EQ(service.active(), nullptr);
  const std::string message = status_message(Status::kTableImageVersion2);
  EXPECT_NE(message.find("version 2"), std::string::npos);
  EXPECT_NE(message.find("export"), std::string::npos);
  put_u16_le(v2.data() + kOffsetFormatVersion, 3);
  EXPECT_EQ(decode_table_image(v2.data(), v2.size(), &decoded), Status::kTableImageTruncated);
}

}  // namespace
}  // namespace tolip

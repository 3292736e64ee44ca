// Guidance table image (tolip/table/table_image.hpp, docs/table-format.md): CRC-32, the byte layout
// and the encode/decode round trip.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>

#include "support/guidance_table_fixture.hpp"
#include "support/repository_paths.hpp"
#include "tolip/table/crc32.hpp"
#include "tolip/table/table_image.hpp"

namespace tolip {
namespace {

using test::encode;
using test::Image;

std::uint64_t bits(double value) { return std::bit_cast<std::uint64_t>(value); }

TEST(Crc32, MatchesTheStandardCheckValue) {
  const char* text = "123456789";
  EXPECT_EQ(crc32(reinterpret_cast<const std::uint8_t*>(text), 9), 0xCBF43926u);
  EXPECT_EQ(kCrc32CheckValue, 0xCBF43926u);
}

TEST(Crc32, EmptyInputIsZeroAndIncrementalEqualsOneShot) {
  EXPECT_EQ(crc32(nullptr, 0), 0u);
  const std::uint8_t data[] = {'T', 'O', 'L', 'I', 'P', 0x00, 0xFF, 0x80, 0x7F, 0x01};
  std::uint32_t crc = 0;
  for (std::uint8_t byte : data) crc = crc32_update(crc, &byte, 1);
  EXPECT_EQ(crc, crc32(data, sizeof data));
  // Known value of the IEEE CRC-32 of one zero byte.
  const std::uint8_t zero = 0;
  EXPECT_EQ(crc32(&zero, 1), 0xD202EF8Du);
}

TEST(TableImage, HasTheDocumentedFixedSizeAndOffsets) {
  EXPECT_EQ(kTableHeaderSize, 96u);
  EXPECT_EQ(kOffsetStageGains, 168u);
  EXPECT_EQ(kOffsetSegments, 328u);
  EXPECT_EQ(kOffsetSchedule, 808u);
  EXPECT_EQ(kOffsetCrc, 1576u);
  EXPECT_EQ(kTableImageSize, 1580u);
  EXPECT_EQ(kOffsetScheduleCapacity, 80u);
  EXPECT_EQ(kOffsetScheduleRecordSize, 82u);
  EXPECT_EQ(kOffsetScheduleCount, 84u);
  EXPECT_EQ(kOffsetHeaderReserved2, 86u);
}

TEST(TableImage, WritesEveryHeaderFieldLittleEndianAtItsOffset) {
  const GuidanceTable table = test::make_test_table();
  const Image image = encode(table);
  EXPECT_EQ(std::memcmp(image.data(), "TLGT", 4), 0);
  EXPECT_EQ(image[4], 0x03);  // format version 3, little-endian u16
  EXPECT_EQ(image[5], 0x00);
  EXPECT_EQ(image[6], 96);    // header size
  EXPECT_EQ(image[8], 0x2C);  // image size 1580 = 0x062C
  EXPECT_EQ(image[9], 0x06);
  EXPECT_EQ(image[10], 0x00);
  EXPECT_EQ(image[12], 15);  // segment capacity
  EXPECT_EQ(image[14], 32);  // segment record size
  EXPECT_EQ(image[16], table.segment_count);
  EXPECT_EQ(image[18], 10);                                                                 // gain records
  EXPECT_EQ(get_u16_le(image.data() + 20), static_cast<std::uint16_t>(table.spin_option));  // IP(9)
  EXPECT_EQ(image[22], 0);                                                                  // reserved
  EXPECT_EQ(image[23], 0);
  EXPECT_EQ(get_u64_le(image.data() + 24), static_cast<std::uint64_t>(table.created_unix_s));
  EXPECT_EQ(std::memcmp(image.data() + 32, "TEST MISSION A", 14), 0);
  EXPECT_EQ(image[32 + 14], 0);
  // Lift-off duration 3.0 = 0x4008000000000000, least significant byte first.
  const std::uint8_t three[8] = {0, 0, 0, 0, 0, 0, 0x08, 0x40};
  EXPECT_EQ(std::memcmp(image.data() + kOffsetLiftoffDuration, three, 8), 0);
  EXPECT_EQ(image[80], kMaxGainSchedulePoints);  // schedule capacity 24
  EXPECT_EQ(image[82], 32);                      // schedule record size
  EXPECT_EQ(get_u16_le(image.data() + 84), static_cast<std::uint16_t>(table.schedule_count));
  // The CRC covers bytes [0, 1576) and is stored little-endian at 1576.
  const std::uint32_t crc = crc32(image.data(), kOffsetCrc);
  EXPECT_EQ(image[1576], crc & 0xFFu);
  EXPECT_EQ(image[1579], (crc >> 24) & 0xFFu);
  EXPECT_EQ(stored_table_crc(image.data()), crc);
}

TEST(TableImage, UnusedSegmentRecordsAreZero) {
  const GuidanceTable table = test::make_test_table();
  const Image image = encode(table);
  for (std::size_t i =
           kOffsetSegments + static_cast<std::size_t>(table.segment_count) * kTableSegmentRecordSize;
       i < kOffsetSchedule; ++i) {
    ASSERT_EQ(image[i], 0) << "byte " << i;
  }
}

TEST(TableImage, RoundTripReproducesEveryFieldBitForBit) {
  const GuidanceTable table = test::make_test_table();
  const Image image = encode(table);
  GuidanceTable decoded;
  ASSERT_EQ(decode_table_image(image.data(), image.size(), &decoded), Status::kOk);
  EXPECT_STREQ(decoded.mission_id, table.mission_id);
  EXPECT_STREQ(decoded.generator_version, table.generator_version);
  EXPECT_EQ(decoded.created_unix_s, table.created_unix_s);
  EXPECT_EQ(bits(decoded.liftoff_duration_s), bits(table.liftoff_duration_s));
  EXPECT_EQ(bits(decoded.max_pitch_rate_rad_s), bits(table.max_pitch_rate_rad_s));
  EXPECT_EQ(bits(decoded.min_pitch_rate_rad_s), bits(table.min_pitch_rate_rad_s));
  EXPECT_EQ(bits(decoded.min_pitch_rate_change_rad_s), bits(table.min_pitch_rate_change_rad_s));
  EXPECT_EQ(bits(decoded.max_deflection_rad), bits(table.max_deflection_rad));
  EXPECT_EQ(bits(decoded.stage4_theta_rad), bits(table.stage4_theta_rad));
  EXPECT_EQ(bits(decoded.stage4_chi_rad), bits(table.stage4_chi_rad));
  EXPECT_EQ(bits(decoded.stage5_theta_rad), bits(table.stage5_theta_rad));
  EXPECT_EQ(bits(decoded.stage5_chi_rad), bits(table.stage5_chi_rad));
  for (int i = 0; i < kMaxStages; ++i) {
    EXPECT_EQ(bits(decoded.gains[i].k_theta), bits(table.gains[i].k_theta)) << i;
    EXPECT_EQ(bits(decoded.gains[i].k_q_s), bits(table.gains[i].k_q_s)) << i;
  }
  ASSERT_EQ(decoded.segment_count, table.segment_count);
  for (int i = 0; i < table.segment_count; ++i) {
    EXPECT_EQ(decoded.segments[i].stage_code, table.segments[i].stage_code) << i;
    EXPECT_EQ(bits(decoded.segments[i].start_stage_time_s), bits(table.segments[i].start_stage_time_s)) << i;
    EXPECT_EQ(bits(decoded.segments[i].theta_start_rad), bits(table.segments[i].theta_start_rad)) << i;
    EXPECT_EQ(bits(decoded.segments[i].rate_rad_s), bits(table.segments[i].rate_rad_s)) << i;
  }
  // Encoding the decoded table gives the same bytes.
  EXPECT_EQ(encode(decoded), image);
}

TEST(TableImage, RoundTripKeepsNegativeZeroAndExtremeRangeValues) {
  GuidanceTable table = test::make_test_table();
  table.stage4_chi_rad = -0.0;
  table.stage5_theta_rad = -kTableMaxAttitudeRad;
  table.segments[0].rate_rad_s = -table.max_pitch_rate_rad_s;
  table.segments[0].start_stage_time_s = std::numeric_limits<double>::denorm_min();
  const Image image = encode(table);
  GuidanceTable decoded;
  ASSERT_EQ(decode_table_image(image.data(), image.size(), &decoded), Status::kOk);
  EXPECT_EQ(bits(decoded.stage4_chi_rad), bits(-0.0));
  EXPECT_EQ(decoded.stage5_theta_rad, -kTableMaxAttitudeRad);
  EXPECT_EQ(decoded.segments[0].start_stage_time_s, std::numeric_limits<double>::denorm_min());
}

TEST(TableImage, EncodeRefusesAnInvalidTableAndAWrongBufferSize) {
  GuidanceTable table = test::make_test_table();
  Image image(kTableImageSize, 0xAA);
  table.segments[2].theta_start_rad = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(encode_table_image(table, image.data(), image.size()), Status::kValueNotFinite);
  EXPECT_EQ(image, Image(kTableImageSize, 0xAA));  // nothing written
  const GuidanceTable good = test::make_test_table();
  EXPECT_EQ(encode_table_image(good, image.data(), kTableImageSize - 1), Status::kTableImageTruncated);
  Image larger(kTableImageSize + 1);
  EXPECT_EQ(encode_table_image(good, larger.data(), larger.size()), Status::kTableImageSizeMismatch);
}

TEST(TableImage, ValidationChecksEveryDocumentedRange) {
  struct Case {
    const char* what;
    void (*mutate)(GuidanceTable*);
    Status expected;
  };
  const Case cases[] = {
      {"lift-off 0", [](GuidanceTable* t) { t->liftoff_duration_s = 0.0; },
       Status::kTableLiftoffDurationOutOfRange},
      {"lift-off 61 s", [](GuidanceTable* t) { t->liftoff_duration_s = 61.0; },
       Status::kTableLiftoffDurationOutOfRange},
      {"max rate 0", [](GuidanceTable* t) { t->max_pitch_rate_rad_s = 0.0; },
       Status::kTablePitchRateLimitOutOfRange},
      {"max rate 31 deg/s", [](GuidanceTable* t) { t->max_pitch_rate_rad_s = 31.0 * kDegToRad; },
       Status::kTablePitchRateLimitOutOfRange},
      {"min rate above max", [](GuidanceTable* t) { t->min_pitch_rate_rad_s = 6.0 * kDegToRad; },
       Status::kTableMinPitchRateOutOfRange},
      {"negative min rate change", [](GuidanceTable* t) { t->min_pitch_rate_change_rad_s = -1e-3; },
       Status::kTablePitchRateChangeOutOfRange},
      {"deflection 0", [](GuidanceTable* t) { t->max_deflection_rad = 0.0; },
       Status::kTableDeflectionLimitOutOfRange},
      {"deflection 31 deg", [](GuidanceTable* t) { t->max_deflection_rad = 31.0 * kDegToRad; },
       Status::kTableDeflectionLimitOutOfRange},
      {"stage 4 theta 4 rad", [](GuidanceTable* t) { t->stage4_theta_rad = 4.0; },
       Status::kTableUpperStageAttitudeOutOfRange},
      {"negative gain", [](GuidanceTable* t) { t->gains[2].k_q_s = -0.1; }, Status::kTableGainOutOfRange},
      {"gain 101", [](GuidanceTable* t) { t->gains[0].k_theta = 101.0; }, Status::kTableGainOutOfRange},
      {"negative start", [](GuidanceTable* t) { t->segments[0].start_stage_time_s = -1.0; },
       Status::kSegmentStartTimeOutOfRange},
      {"theta 3.2 rad", [](GuidanceTable* t) { t->segments[1].theta_start_rad = 3.2; },
       Status::kSegmentAttitudeOutOfRange},
      {"stamp negative", [](GuidanceTable* t) { t->created_unix_s = -1; },
       Status::kTableCreationTimeOutOfRange},
      {"stage 4 segment", [](GuidanceTable* t) { t->segments[7].stage_code = 4; },
       Status::kSegmentStageInvalid},
      {"stage 0 segment", [](GuidanceTable* t) { t->segments[0].stage_code = 0; },
       Status::kSegmentStageInvalid},
      {"stage 11 segment", [](GuidanceTable* t) { t->segments[0].stage_code = 11; },
       Status::kSegmentStageInvalid},
      {"empty mission id", [](GuidanceTable* t) { t->mission_id[0] = '\0'; }, Status::kTableImageTextInvalid},
      {"control character", [](GuidanceTable* t) { t->generator_version[1] = '\n'; },
       Status::kTableImageTextInvalid},
      {"16 segments", [](GuidanceTable* t) { t->segment_count = 16; }, Status::kTooManyLinearSegments},
  };
  for (const Case& c : cases) {
    GuidanceTable table = test::make_test_table();
    c.mutate(&table);
    EXPECT_EQ(validate_guidance_table(table), c.expected) << c.what;
  }
  EXPECT_EQ(validate_guidance_table(test::make_test_table()), Status::kOk);
}

// docs/table-format.md: every word is checked on its own (a NaN named as such, wherever it is),
// and a decoded header names the layout field that differs from this build's.
TEST(TableImage, EveryWordAndLayoutFieldIsCheckedOnItsOwn) {
  GuidanceTable good = test::make_test_table();
  good.schedule_count = 1;
  good.schedule[0].stage_code = 1;
  good.schedule[0].stage_time_s = 5.0;
  good.schedule[0].k_theta = 1.0;
  good.schedule[0].k_q_s = 0.1;
  ASSERT_EQ(validate_guidance_table(good), Status::kOk);
  struct Case {
    const char* what;
    void (*mutate)(GuidanceTable*);
    Status expected;
  };
  static const Case cases[] = {
      {"format version", [](GuidanceTable* t) { t->format_version = 2; },
       Status::kTableImageUnsupportedVersion},
      {"negative segment count", [](GuidanceTable* t) { t->segment_count = -1; },
       Status::kTooManyLinearSegments},
      {"mission id without its NUL",
       [](GuidanceTable* t) {
         for (char& c : t->mission_id) c = 'A';
       },
       Status::kTableImageTextInvalid},
      {"K_q not finite",
       [](GuidanceTable* t) { t->gains[3].k_q_s = std::numeric_limits<double>::infinity(); },
       Status::kValueNotFinite},
      {"segment rate not finite",
       [](GuidanceTable* t) { t->segments[1].rate_rad_s = std::numeric_limits<double>::quiet_NaN(); },
       Status::kValueNotFinite},
      {"segment start not finite",
       [](GuidanceTable* t) { t->segments[1].start_stage_time_s = std::numeric_limits<double>::infinity(); },
       Status::kValueNotFinite},
      {"negative schedule count", [](GuidanceTable* t) { t->schedule_count = -1; },
       Status::kTooManyGainSchedulePoints},
      {"schedule beyond capacity", [](GuidanceTable* t) { t->schedule_count = kMaxGainSchedulePoints + 1; },
       Status::kTooManyGainSchedulePoints},
      {"schedule time not finite",
       [](GuidanceTable* t) { t->schedule[0].stage_time_s = std::numeric_limits<double>::quiet_NaN(); },
       Status::kValueNotFinite},
      {"schedule K_theta not finite",
       [](GuidanceTable* t) { t->schedule[0].k_theta = std::numeric_limits<double>::infinity(); },
       Status::kValueNotFinite},
      {"schedule K_q not finite",
       [](GuidanceTable* t) { t->schedule[0].k_q_s = std::numeric_limits<double>::quiet_NaN(); },
       Status::kValueNotFinite},
      {"schedule K_theta beyond 100", [](GuidanceTable* t) { t->schedule[0].k_theta = 101.0; },
       Status::kTableGainOutOfRange},
  };
  for (const Case& c : cases) {
    GuidanceTable table = good;
    c.mutate(&table);
    EXPECT_EQ(validate_guidance_table(table), c.expected) << c.what;
  }

  // Decoding: each layout word of the header altered alone is a layout mismatch (the CRC is not
  // reached); a version-2 image is named by its version only when its magic is the table's.
  const Image image = encode(good);
  const std::size_t layout[] = {kOffsetHeaderSize,     kOffsetSegmentCapacity,  kOffsetSegmentRecordSize,
                                kOffsetStageGainCount, kOffsetScheduleCapacity, kOffsetScheduleRecordSize};
  GuidanceTable decoded;
  for (std::size_t offset : layout) {
    Image altered = image;
    altered[offset] ^= 0x01u;
    EXPECT_EQ(decode_table_image(altered.data(), altered.size(), &decoded), Status::kTableImageLayoutMismatch)
        << "offset " << offset;
  }
  Image version2(image.begin(), image.begin() + kTableVersion2ImageSize);
  version2[kOffsetFormatVersion] = 2u;
  version2[kOffsetFormatVersion + 1] = 0u;
  EXPECT_EQ(table_image_size_status(version2.data(), version2.size()), Status::kTableImageVersion2);
  for (std::size_t i = 1; i < 4; ++i) {
    Image other = version2;
    other[kOffsetMagic + i] ^= 0x20u;
    EXPECT_EQ(table_image_size_status(other.data(), other.size()), Status::kTableImageTruncated) << i;
  }
  version2[kOffsetFormatVersion] = 3u;
  EXPECT_EQ(table_image_size_status(version2.data(), version2.size()), Status::kTableImageTruncated);
  EXPECT_EQ(table_image_size_status(nullptr, kTableImageSize), Status::kTableImageTruncated);
}

TEST(TableImage, ZeroSegmentsAndAFullTableOfFifteenAreValid) {
  GuidanceTable empty = test::make_test_table();
  empty.segment_count = 0;
  EXPECT_EQ(validate_guidance_table(empty), Status::kOk);
  GuidanceTable full = test::make_test_table();
  full.segment_count = kMaxLinearSegments;
  for (int i = 0; i < kMaxLinearSegments; ++i) {
    full.segments[i] = GuidanceSegment{1, 3.0 + 2.0 * i, (80.0 - i) * kDegToRad, -0.5 * kDegToRad};
  }
  const Image image = encode(full);
  GuidanceTable decoded;
  EXPECT_EQ(decode_table_image(image.data(), image.size(), &decoded), Status::kOk);
  EXPECT_EQ(decoded.segment_count, kMaxLinearSegments);
}

TEST(TableImage, RateAtTheLimitPassesAndJustBeyondTheToleranceFails) {
  GuidanceTable table = test::make_test_table();
  table.segments[0].rate_rad_s = -table.max_pitch_rate_rad_s * (1.0 + 0.5 * kTableRateLimitRelativeTolerance);
  EXPECT_EQ(validate_guidance_table(table), Status::kOk);
  table.segments[0].rate_rad_s = -table.max_pitch_rate_rad_s * (1.0 + 2.0 * kTableRateLimitRelativeTolerance);
  EXPECT_EQ(validate_guidance_table(table), Status::kSegmentRateExceedsLimit);
}

TEST(TableImage, FlightOrderIndexFollowsTheStageSequence) {
  const int sequence[] = {1, 6, 2, 7, 3, 8, 4, 9, 5, 10};
  for (int i = 0; i < 10; ++i) EXPECT_EQ(flight_order_index(sequence[i]), i);
  EXPECT_EQ(flight_order_index(0), -1);
  EXPECT_EQ(flight_order_index(11), -1);
  // IP(9) = 1 (stages 4 and 5 spun): the segment stages of format version 1.
  for (int code : {1, 2, 3, 6, 7, 8}) EXPECT_TRUE(is_segment_stage(1, code)) << code;
  for (int code : {0, 4, 5, 9, 10, 11}) EXPECT_FALSE(is_segment_stage(1, code)) << code;
}

// Sec. 22 IP(9): "2 Stage 4 continuous and Stage 5 spun; 3 Stages 4 and 5 continuous". The image
// carries IP(9), its segments may lie in the continuous stages, and the loader rejects one in a
// spun stage.
TEST(TableImage, Sec22_SegmentStagesFollowTheSpinOptionIP9) {
  for (int code : {1, 2, 3, 6, 7, 8, 4, 9}) EXPECT_TRUE(is_segment_stage(2, code)) << code;
  for (int code : {0, 5, 10, 11}) EXPECT_FALSE(is_segment_stage(2, code)) << code;
  for (int code = 1; code <= 10; ++code) EXPECT_TRUE(is_segment_stage(3, code)) << code;
  for (int code : {0, 11}) EXPECT_FALSE(is_segment_stage(3, code)) << code;

  GuidanceTable table = test::make_test_table();
  ASSERT_LT(table.segment_count, kMaxLinearSegments);
  GuidanceSegment& last = table.segments[table.segment_count++];
  last = GuidanceSegment{4, 2.0, -0.3, -0.001};
  table.spin_option = 1;
  EXPECT_EQ(validate_guidance_table(table), Status::kSegmentStageInvalid);
  table.spin_option = 2;
  ASSERT_EQ(validate_guidance_table(table), Status::kOk);
  const Image image = encode(table);
  EXPECT_EQ(get_u16_le(image.data() + kOffsetSpinOption), 2u);
  GuidanceTable decoded;
  ASSERT_EQ(decode_table_image(image.data(), image.size(), &decoded), Status::kOk);
  EXPECT_EQ(decoded.spin_option, 2);
  EXPECT_EQ(decoded.segments[decoded.segment_count - 1].stage_code, 4);
  table.spin_option = 4;
  EXPECT_EQ(validate_guidance_table(table), Status::kTableSpinOptionOutOfRange);
}

TEST(Status, EveryTableStatusHasANameAndAMessage) {
  for (int i = static_cast<int>(Status::kTableImageTruncated);
       i <= static_cast<int>(Status::kStageEventOutOfOrder); ++i) {
    const auto s = static_cast<Status>(i);
    EXPECT_STRNE(status_name(s), "kUnknownStatus") << i;
    EXPECT_GT(std::strlen(status_message(s)), 5u) << i;
  }
}

// The table-image fuzzer's seeds (fuzz/corpus/table_image) are a mode byte (even: reseal, odd: load
// as it is; fuzz/table_image_fuzzer.cpp) and an image of the current format. A seed left behind by a
// format change (the 812-byte version-2 image did so: every execution stopped at the size check)
// would let the campaign's executions count without reaching the field checks; this fails first.
TEST(TableImage, FuzzSeedsAreImagesOfTheCurrentFormatBehindTheirModeByte) {
  const std::filesystem::path seeds =
      std::filesystem::path(tolip::repository_paths::source_dir()) / "fuzz/corpus/table_image";
  int decoded = 0;
  for (const auto& entry : std::filesystem::directory_iterator(seeds)) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    ASSERT_EQ(bytes.size(), kTableImageSize + 1) << entry.path();
    GuidanceTable table;
    EXPECT_EQ(decode_table_image(bytes.data() + 1, bytes.size() - 1, &table), Status::kOk) << entry.path();
    ++decoded;
  }
  EXPECT_GE(decoded, 2);  // one seed per mode
}

}  // namespace
}  // namespace tolip

// The guidance-computer table image: a fixed-size, versioned, little-endian binary image holding
// the pitch program (linear segments), the spun-stage attitudes, the autopilot gains per stage and
// the limits, protected by a CRC-32. docs/table-format.md is the specification: every field's
// offset, type, unit and range; the constants below are that table in code.
//
// The image is written and read byte by byte (explicit little-endian serialization, IEEE-754
// binary64 doubles through their bit patterns), never by copying a struct, so host and target
// produce and accept the same bytes whatever their own byte order, padding or alignment.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tolip/core/capacity.hpp"
#include "tolip/core/stage_codes.hpp"
#include "tolip/core/status.hpp"

namespace tolip {

// ---- format constants (docs/table-format.md, "Layout") ------------------------------------------
inline constexpr std::uint8_t kTableMagic[4] = {0x54, 0x4C, 0x47, 0x54};  // "TLGT"
// Version 2 added the stage 4-5 control word (IP(9)) and pitch segments in stages 4, 5 and coasts
// 9, 10 when IP(9) does not spin them; version 3 the autopilot gain schedule records (issue 16)
// after the segments (docs/table-format.md, "Versioning").
inline constexpr std::uint16_t kTableFormatVersion = 3;
inline constexpr std::size_t kTableVersion2ImageSize = 812;  // rejected by its version (and size)
inline constexpr std::size_t kTableHeaderSize = 96;
inline constexpr std::size_t kTableMissionIdBytes = 32;
inline constexpr std::size_t kTableGeneratorVersionBytes = 16;
inline constexpr std::size_t kTableSegmentRecordSize = 32;
inline constexpr std::size_t kTableStageGainCount = static_cast<std::size_t>(kMaxStages);  // codes 1-10
inline constexpr std::size_t kTableStageGainRecordSize = 16;
inline constexpr std::size_t kTableScheduleRecordSize = 32;

// Header field offsets.
inline constexpr std::size_t kOffsetMagic = 0;
inline constexpr std::size_t kOffsetFormatVersion = 4;
inline constexpr std::size_t kOffsetHeaderSize = 6;
inline constexpr std::size_t kOffsetImageSize = 8;
inline constexpr std::size_t kOffsetSegmentCapacity = 12;
inline constexpr std::size_t kOffsetSegmentRecordSize = 14;
inline constexpr std::size_t kOffsetSegmentCount = 16;
inline constexpr std::size_t kOffsetStageGainCount = 18;
inline constexpr std::size_t kOffsetSpinOption = 20;       // u16: IP(9), which of stages 4, 5 are spun
inline constexpr std::size_t kOffsetHeaderReserved1 = 22;  // 2 bytes, zero
inline constexpr std::size_t kOffsetCreatedUnixS = 24;
inline constexpr std::size_t kOffsetMissionId = 32;
inline constexpr std::size_t kOffsetGeneratorVersion = 64;
inline constexpr std::size_t kOffsetScheduleCapacity = 80;    // u16: kMaxGainSchedulePoints
inline constexpr std::size_t kOffsetScheduleRecordSize = 82;  // u16: 32
inline constexpr std::size_t kOffsetScheduleCount = 84;       // u16: records used
inline constexpr std::size_t kOffsetHeaderReserved2 = 86;     // 10 bytes, zero
inline constexpr std::size_t kHeaderReserved2Bytes = 10;
// Body field offsets.
inline constexpr std::size_t kOffsetLiftoffDuration = 96;
inline constexpr std::size_t kOffsetMaxPitchRate = 104;
inline constexpr std::size_t kOffsetMinPitchRate = 112;
inline constexpr std::size_t kOffsetMinPitchRateChange = 120;
inline constexpr std::size_t kOffsetMaxDeflection = 128;
inline constexpr std::size_t kOffsetStage4Theta = 136;
inline constexpr std::size_t kOffsetStage4Chi = 144;
inline constexpr std::size_t kOffsetStage5Theta = 152;
inline constexpr std::size_t kOffsetStage5Chi = 160;
inline constexpr std::size_t kOffsetStageGains = 168;
inline constexpr std::size_t kOffsetSegments =
    kOffsetStageGains + kTableStageGainCount * kTableStageGainRecordSize;  // 328
inline constexpr std::size_t kOffsetSchedule =
    kOffsetSegments + static_cast<std::size_t>(kMaxLinearSegments) * kTableSegmentRecordSize;  // 808
inline constexpr std::size_t kOffsetCrc =
    kOffsetSchedule + static_cast<std::size_t>(kMaxGainSchedulePoints) * kTableScheduleRecordSize;  // 1576
inline constexpr std::size_t kTableImageSize = kOffsetCrc + 4;                                      // 1580

// Offsets inside one segment record and one gain record.
inline constexpr std::size_t kSegmentOffsetStageCode = 0;   // u16
inline constexpr std::size_t kSegmentOffsetReserved = 2;    // 6 bytes, zero
inline constexpr std::size_t kSegmentOffsetStartTime = 8;   // f64
inline constexpr std::size_t kSegmentOffsetTheta = 16;      // f64
inline constexpr std::size_t kSegmentOffsetRate = 24;       // f64
inline constexpr std::size_t kGainOffsetKTheta = 0;         // f64
inline constexpr std::size_t kGainOffsetKq = 8;             // f64
inline constexpr std::size_t kScheduleOffsetStageCode = 0;  // u16
inline constexpr std::size_t kScheduleOffsetReserved = 2;   // 6 bytes, zero
inline constexpr std::size_t kScheduleOffsetTime = 8;       // f64, stage time s
inline constexpr std::size_t kScheduleOffsetKTheta = 16;    // f64
inline constexpr std::size_t kScheduleOffsetKq = 24;        // f64

// ---- documented ranges (docs/table-format.md, "Ranges") -----------------------------------------
inline constexpr double kTableMaxLiftoffDurationS = 60.0;                  // (0, 60] s
inline constexpr double kTableMaxPitchRateLimitRadS = 0.5235987755982988;  // pi/6 rad/s = 30 deg/s
inline constexpr double kTableMaxDeflectionLimitRad = 0.5235987755982988;  // pi/6 rad = 30 deg
inline constexpr double kTableMaxAttitudeRad = 3.141592653589793;          // |theta|, |chi| <= pi
inline constexpr double kTableMaxSegmentStartS = 10000.0;                  // [0, 10000] s stage time
inline constexpr double kTableMaxGain = 100.0;                             // K_theta [0,100], K_q [0,100] s
inline constexpr std::int64_t kTableMaxCreatedUnixS = 253402300799;        // 9999-12-31T23:59:59Z
// A segment rate may exceed the image's maximum pitch rate by this fraction at most: it absorbs
// the round-off of degree/radian conversions (a 5 deg/s segment against a 5 deg/s limit).
inline constexpr double kTableRateLimitRelativeTolerance = 1e-9;

// ---- decoded contents ---------------------------------------------------------------------------

// One linear pitch segment: theta(t) = theta_start + rate (t - start), t in the stage's own time,
// from `start_stage_time_s` until the next segment takes over (across stage boundaries too).
struct GuidanceSegment {
  int stage_code = 0;               // a stage that flies the pitch program: is_segment_stage()
  double start_stage_time_s = 0.0;  // s from the ignition (start) of that stage
  double theta_start_rad = 0.0;     // pitch attitude at the start, platform frame
  double rate_rad_s = 0.0;          // d theta / dt over the segment
};

struct StageGains {
  double k_theta = 0.0;  // autopilot position gain K_theta, rad/rad
  double k_q_s = 0.0;    // autopilot rate gain K_q, s (rad per rad/s)
};

// One point of an autopilot gain schedule (format version 3): the gains in force at `stage_time_s`
// of stage `stage_code`; the executor interpolates linearly in stage time between the points of
// the stage in force and holds the first (last) point's gains before (after) them.
struct GainSchedulePoint {
  int stage_code = 0;         // a stage the image's IP(9) does not spin
  double stage_time_s = 0.0;  // s from the ignition (start) of that stage
  double k_theta = 0.0;       // rad/rad
  double k_q_s = 0.0;         // s
};

struct GuidanceTable {
  // Header.
  std::uint16_t format_version = kTableFormatVersion;
  std::int64_t created_unix_s = 0;  // creation stamp, s since 1970-01-01T00:00:00Z
  // IP(9) of the case (0-3): which of stages 4 and 5 (and coasts 9, 10) are spun, by the one rule
  // tolip::stage_is_spun(); the others fly the segments. 1: both spun (format version 1's only case).
  int spin_option = 1;
  char mission_id[kTableMissionIdBytes + 1] = {};                // printable ASCII, NUL-terminated
  char generator_version[kTableGeneratorVersionBytes + 1] = {};  // printable ASCII, NUL-terminated
  // Body.
  double liftoff_duration_s = 0.0;           // theta held at 90 deg from lift-off until this time
  double max_pitch_rate_rad_s = 0.0;         // |segment rate| limit, enforced by validation
  double min_pitch_rate_rad_s = 0.0;         // carried for the linearization (data block 22)
  double min_pitch_rate_change_rad_s = 0.0;  // carried for the linearization (data block 22)
  double max_deflection_rad = 0.0;           // control law deflection limit (+/-)
  double stage4_theta_rad = 0.0;             // spun stage 4 (and coast 9) attitude (IP(9) = 1)
  double stage4_chi_rad = 0.0;
  double stage5_theta_rad = 0.0;  // spun stage 5 (and coast 10) attitude (IP(9) = 1, 2)
  double stage5_chi_rad = 0.0;
  StageGains gains[kMaxStages];  // by stage_index(code), codes 1-10
  int segment_count = 0;
  GuidanceSegment segments[kMaxLinearSegments];
  // Autopilot gain schedule (version 3): in flight order of the stages, strictly increasing times
  // within a stage. A stage without points flies its constant `gains` record.
  int schedule_count = 0;
  GainSchedulePoint schedule[kMaxGainSchedulePoints];
};

// The gains in force in stage `stage_code` at `stage_time_s`: linear in time between the stage's
// schedule points, held at the first and last; the stage's constant record when it has none.
// One bounded pass over kMaxGainSchedulePoints records (+, -, *, / only).
StageGains scheduled_gains(const GuidanceTable& table, int stage_code, double stage_time_s);

// True for the stage codes a pitch segment may belong to: the stage codes 1-10 that IP(9)
// (`spin_option`) does not spin: 1, 2, 3, 6, 7, 8 always; 4, 9 unless IP(9) = 1; 5, 10 when IP(9) = 3
// (or 0).
bool is_segment_stage(int spin_option, int stage_code);

// Position of a stage code (1-10) in the flight order 1 6 2 7 3 8 4 9 5 10 (0-9); -1 otherwise.
int flight_order_index(int stage_code);

// Checks every documented range and rule of the decoded contents (docs/table-format.md,
// "Validation"): finiteness, ranges, text, segment count, stage codes, monotonic start times,
// rates within the image's own limit. Returns the first fault.
Status validate_guidance_table(const GuidanceTable& table);

// Serializes `table` into exactly kTableImageSize bytes (CRC included). Validates first and writes
// nothing when the table is invalid. Unused segment records are zero.
Status encode_table_image(const GuidanceTable& table, std::uint8_t* image, std::size_t image_size);

// The size checks of an upload: kTableImageVersion2 for a version-2 image (812 bytes, magic and
// version 2: no gain schedule, another layout), kTableImageTruncated / kTableImageSizeMismatch
// for any other size than kTableImageSize; kOk otherwise.
Status table_image_size_status(const std::uint8_t* image, std::size_t size);

// Checks the raw image (size, magic, version, layout, CRC, reserved bytes) and decodes it into
// *table, then validates the contents. *table is written only when the whole image is valid.
Status decode_table_image(const std::uint8_t* image, std::size_t size, GuidanceTable* table);

// The CRC stored in an image of kTableImageSize bytes (no checking).
std::uint32_t stored_table_crc(const std::uint8_t* image);

// Little-endian field access, for tools and tests that build or patch images byte by byte.
void put_u16_le(std::uint8_t* at, std::uint16_t value);
void put_u32_le(std::uint8_t* at, std::uint32_t value);
void put_u64_le(std::uint8_t* at, std::uint64_t value);
void put_f64_le(std::uint8_t* at, double value);
std::uint16_t get_u16_le(const std::uint8_t* at);
std::uint32_t get_u32_le(const std::uint8_t* at);
std::uint64_t get_u64_le(const std::uint8_t* at);
double get_f64_le(const std::uint8_t* at);

// Recomputes and stores the CRC of an image of kTableImageSize bytes (tests and tools that patch
// fields use it to isolate one fault from the CRC check).
void reseal_table_image(std::uint8_t* image);

}  // namespace tolip

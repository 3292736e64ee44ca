// Guidance table image: byte-by-byte little-endian serialization, checks and validation
// (docs/table-format.md).
#include "tolip/table/table_image.hpp"

#include <bit>
#include <cmath>

#include "tolip/table/crc32.hpp"

namespace tolip {
namespace {

bool is_printable_ascii(char c) { return c >= 0x20 && c <= 0x7E; }

// A text field: printable ASCII, then NUL padding to the end; the first byte must be printable.
bool text_field_valid(const std::uint8_t* at, std::size_t bytes) {
  std::size_t length = 0;
  while (length < bytes && at[length] != 0u) {
    if (!is_printable_ascii(static_cast<char>(at[length]))) return false;
    ++length;
  }
  if (length == 0) return false;
  for (std::size_t i = length; i < bytes; ++i) {
    if (at[i] != 0u) return false;
  }
  return true;
}

bool text_valid(const char* text, std::size_t bytes) {
  // `text` has room for bytes + 1 characters: at most `bytes` printable ones, then a NUL.
  std::size_t length = 0;
  while (length < bytes && text[length] != '\0') {
    if (!is_printable_ascii(text[length])) return false;
    ++length;
  }
  return length > 0 && text[length] == '\0';
}

bool all_zero(const std::uint8_t* at, std::size_t bytes) {
  for (std::size_t i = 0; i < bytes; ++i) {
    if (at[i] != 0u) return false;
  }
  return true;
}

void put_text(std::uint8_t* at, const char* text, std::size_t bytes) {
  std::size_t i = 0;
  for (; i < bytes && text[i] != '\0'; ++i) at[i] = static_cast<std::uint8_t>(text[i]);
  for (; i < bytes; ++i) at[i] = 0u;
}

void get_text(const std::uint8_t* at, std::size_t bytes, char* text) {
  std::size_t i = 0;
  for (; i < bytes && at[i] != 0u; ++i) text[i] = static_cast<char>(at[i]);
  for (; i <= bytes; ++i) text[i] = '\0';
}

bool in_range(double value, double lo, double hi) { return value >= lo && value <= hi; }

}  // namespace

// ---- byte access ---------------------------------------------------------------------------------

void put_u16_le(std::uint8_t* at, std::uint16_t value) {
  at[0] = static_cast<std::uint8_t>(value & 0xFFu);
  at[1] = static_cast<std::uint8_t>((value >> 8) & 0xFFu);
}

void put_u32_le(std::uint8_t* at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) at[i] = static_cast<std::uint8_t>((value >> (8 * i)) & 0xFFu);
}

void put_u64_le(std::uint8_t* at, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) at[i] = static_cast<std::uint8_t>((value >> (8 * i)) & 0xFFu);
}

void put_f64_le(std::uint8_t* at, double value) { put_u64_le(at, std::bit_cast<std::uint64_t>(value)); }

std::uint16_t get_u16_le(const std::uint8_t* at) {
  return static_cast<std::uint16_t>(static_cast<std::uint16_t>(at[0]) |
                                    static_cast<std::uint16_t>(static_cast<std::uint16_t>(at[1]) << 8));
}

std::uint32_t get_u32_le(const std::uint8_t* at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<std::uint32_t>(at[i]);
  return value;
}

std::uint64_t get_u64_le(const std::uint8_t* at) {
  std::uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = (value << 8) | static_cast<std::uint64_t>(at[i]);
  return value;
}

double get_f64_le(const std::uint8_t* at) { return std::bit_cast<double>(get_u64_le(at)); }

std::uint32_t stored_table_crc(const std::uint8_t* image) { return get_u32_le(image + kOffsetCrc); }

void reseal_table_image(std::uint8_t* image) { put_u32_le(image + kOffsetCrc, crc32(image, kOffsetCrc)); }

// ---- stage codes ---------------------------------------------------------------------------------

bool is_segment_stage(int spin_option, int stage_code) {
  return stage_code >= 1 && stage_code <= kMaxStages && !stage_is_spun(spin_option, stage_code);
}

int flight_order_index(int stage_code) {
  if (stage_code >= 1 && stage_code <= 5) return 2 * (stage_code - 1);
  if (stage_code >= 6 && stage_code <= 10) return 2 * (stage_code - 6) + 1;
  return -1;
}

// ---- validation ----------------------------------------------------------------------------------

Status validate_guidance_table(const GuidanceTable& t) {
  if (t.format_version != kTableFormatVersion) return Status::kTableImageUnsupportedVersion;
  if (t.segment_count < 0 || t.segment_count > kMaxLinearSegments) return Status::kTooManyLinearSegments;
  if (!text_valid(t.mission_id, kTableMissionIdBytes) ||
      !text_valid(t.generator_version, kTableGeneratorVersionBytes)) {
    return Status::kTableImageTextInvalid;
  }

  // Every double finite first, so that a NaN is reported as such and not as a range fault.
  const double scalars[] = {
      t.liftoff_duration_s, t.max_pitch_rate_rad_s, t.min_pitch_rate_rad_s, t.min_pitch_rate_change_rad_s,
      t.max_deflection_rad, t.stage4_theta_rad,     t.stage4_chi_rad,       t.stage5_theta_rad,
      t.stage5_chi_rad};
  for (double value : scalars) {
    if (!std::isfinite(value)) return Status::kValueNotFinite;
  }
  for (int i = 0; i < kMaxStages; ++i) {
    if (!std::isfinite(t.gains[i].k_theta) || !std::isfinite(t.gains[i].k_q_s)) {
      return Status::kValueNotFinite;
    }
  }
  for (int i = 0; i < t.segment_count; ++i) {
    const GuidanceSegment& s = t.segments[i];
    if (!std::isfinite(s.start_stage_time_s) || !std::isfinite(s.theta_start_rad) ||
        !std::isfinite(s.rate_rad_s)) {
      return Status::kValueNotFinite;
    }
  }
  if (t.schedule_count < 0 || t.schedule_count > kMaxGainSchedulePoints) {
    return Status::kTooManyGainSchedulePoints;
  }
  for (int i = 0; i < t.schedule_count; ++i) {
    const GainSchedulePoint& p = t.schedule[i];
    if (!std::isfinite(p.stage_time_s) || !std::isfinite(p.k_theta) || !std::isfinite(p.k_q_s)) {
      return Status::kValueNotFinite;
    }
  }

  // Documented ranges.
  if (t.spin_option < 0 || t.spin_option > 3) return Status::kTableSpinOptionOutOfRange;
  if (t.created_unix_s < 0 || t.created_unix_s > kTableMaxCreatedUnixS) {
    return Status::kTableCreationTimeOutOfRange;
  }
  if (!(t.liftoff_duration_s > 0.0 && t.liftoff_duration_s <= kTableMaxLiftoffDurationS)) {
    return Status::kTableLiftoffDurationOutOfRange;
  }
  if (!(t.max_pitch_rate_rad_s > 0.0 && t.max_pitch_rate_rad_s <= kTableMaxPitchRateLimitRadS)) {
    return Status::kTablePitchRateLimitOutOfRange;
  }
  if (!in_range(t.min_pitch_rate_rad_s, 0.0, t.max_pitch_rate_rad_s)) {
    return Status::kTableMinPitchRateOutOfRange;
  }
  if (!in_range(t.min_pitch_rate_change_rad_s, 0.0, 2.0 * t.max_pitch_rate_rad_s)) {
    return Status::kTablePitchRateChangeOutOfRange;
  }
  if (!(t.max_deflection_rad > 0.0 && t.max_deflection_rad <= kTableMaxDeflectionLimitRad)) {
    return Status::kTableDeflectionLimitOutOfRange;
  }
  const double attitudes[] = {t.stage4_theta_rad, t.stage4_chi_rad, t.stage5_theta_rad, t.stage5_chi_rad};
  for (double value : attitudes) {
    if (!in_range(value, -kTableMaxAttitudeRad, kTableMaxAttitudeRad)) {
      return Status::kTableUpperStageAttitudeOutOfRange;
    }
  }
  for (int i = 0; i < kMaxStages; ++i) {
    if (!in_range(t.gains[i].k_theta, 0.0, kTableMaxGain) ||
        !in_range(t.gains[i].k_q_s, 0.0, kTableMaxGain)) {
      return Status::kTableGainOutOfRange;
    }
  }
  for (int i = 0; i < t.segment_count; ++i) {
    const GuidanceSegment& s = t.segments[i];
    if (!is_segment_stage(t.spin_option, s.stage_code)) return Status::kSegmentStageInvalid;
    if (!in_range(s.start_stage_time_s, 0.0, kTableMaxSegmentStartS)) {
      return Status::kSegmentStartTimeOutOfRange;
    }
    if (!in_range(s.theta_start_rad, -kTableMaxAttitudeRad, kTableMaxAttitudeRad)) {
      return Status::kSegmentAttitudeOutOfRange;
    }
  }

  // Flight order of stages, strictly increasing start times within a stage.
  for (int i = 1; i < t.segment_count; ++i) {
    const GuidanceSegment& a = t.segments[i - 1];
    const GuidanceSegment& b = t.segments[i];
    const int order_a = flight_order_index(a.stage_code);
    const int order_b = flight_order_index(b.stage_code);
    if (order_b < order_a || (order_b == order_a && !(b.start_stage_time_s > a.start_stage_time_s))) {
      return Status::kSegmentTimesNotMonotonic;
    }
  }

  // Gain schedule (version 3): stages that fly an autopilot, flight order, strictly increasing
  // stage times within a stage, gains in the constant records' range.
  for (int i = 0; i < t.schedule_count; ++i) {
    const GainSchedulePoint& p = t.schedule[i];
    if (!is_segment_stage(t.spin_option, p.stage_code)) return Status::kGainScheduleStageInvalid;
    if (!in_range(p.stage_time_s, 0.0, kTableMaxSegmentStartS)) return Status::kGainScheduleTimeOutOfRange;
    if (!in_range(p.k_theta, 0.0, kTableMaxGain) || !in_range(p.k_q_s, 0.0, kTableMaxGain)) {
      return Status::kTableGainOutOfRange;
    }
    if (i > 0) {
      const GainSchedulePoint& a = t.schedule[i - 1];
      const int order_a = flight_order_index(a.stage_code);
      const int order_b = flight_order_index(p.stage_code);
      if (order_b < order_a) return Status::kGainScheduleStageInvalid;
      if (order_b == order_a && !(p.stage_time_s > a.stage_time_s)) {
        return Status::kGainScheduleTimesNotMonotonic;
      }
    }
  }

  // Rates inside the limit the image itself carries.
  const double rate_limit = t.max_pitch_rate_rad_s * (1.0 + kTableRateLimitRelativeTolerance);
  for (int i = 0; i < t.segment_count; ++i) {
    if (std::fabs(t.segments[i].rate_rad_s) > rate_limit) return Status::kSegmentRateExceedsLimit;
  }
  return Status::kOk;
}

// ---- encoding ------------------------------------------------------------------------------------

Status encode_table_image(const GuidanceTable& t, std::uint8_t* image, std::size_t image_size) {
  if (image_size < kTableImageSize) return Status::kTableImageTruncated;
  if (image_size > kTableImageSize) return Status::kTableImageSizeMismatch;
  const Status valid = validate_guidance_table(t);
  if (!ok(valid)) return valid;

  for (std::size_t i = 0; i < kTableImageSize; ++i) image[i] = 0u;
  for (std::size_t i = 0; i < 4; ++i) image[kOffsetMagic + i] = kTableMagic[i];
  put_u16_le(image + kOffsetFormatVersion, kTableFormatVersion);
  put_u16_le(image + kOffsetHeaderSize, static_cast<std::uint16_t>(kTableHeaderSize));
  put_u32_le(image + kOffsetImageSize, static_cast<std::uint32_t>(kTableImageSize));
  put_u16_le(image + kOffsetSegmentCapacity, static_cast<std::uint16_t>(kMaxLinearSegments));
  put_u16_le(image + kOffsetSegmentRecordSize, static_cast<std::uint16_t>(kTableSegmentRecordSize));
  put_u16_le(image + kOffsetSegmentCount, static_cast<std::uint16_t>(t.segment_count));
  put_u16_le(image + kOffsetStageGainCount, static_cast<std::uint16_t>(kTableStageGainCount));
  put_u16_le(image + kOffsetSpinOption, static_cast<std::uint16_t>(t.spin_option));
  put_u16_le(image + kOffsetScheduleCapacity, static_cast<std::uint16_t>(kMaxGainSchedulePoints));
  put_u16_le(image + kOffsetScheduleRecordSize, static_cast<std::uint16_t>(kTableScheduleRecordSize));
  put_u16_le(image + kOffsetScheduleCount, static_cast<std::uint16_t>(t.schedule_count));
  put_u64_le(image + kOffsetCreatedUnixS, static_cast<std::uint64_t>(t.created_unix_s));
  put_text(image + kOffsetMissionId, t.mission_id, kTableMissionIdBytes);
  put_text(image + kOffsetGeneratorVersion, t.generator_version, kTableGeneratorVersionBytes);

  put_f64_le(image + kOffsetLiftoffDuration, t.liftoff_duration_s);
  put_f64_le(image + kOffsetMaxPitchRate, t.max_pitch_rate_rad_s);
  put_f64_le(image + kOffsetMinPitchRate, t.min_pitch_rate_rad_s);
  put_f64_le(image + kOffsetMinPitchRateChange, t.min_pitch_rate_change_rad_s);
  put_f64_le(image + kOffsetMaxDeflection, t.max_deflection_rad);
  put_f64_le(image + kOffsetStage4Theta, t.stage4_theta_rad);
  put_f64_le(image + kOffsetStage4Chi, t.stage4_chi_rad);
  put_f64_le(image + kOffsetStage5Theta, t.stage5_theta_rad);
  put_f64_le(image + kOffsetStage5Chi, t.stage5_chi_rad);
  for (std::size_t i = 0; i < kTableStageGainCount; ++i) {
    std::uint8_t* record = image + kOffsetStageGains + i * kTableStageGainRecordSize;
    put_f64_le(record + kGainOffsetKTheta, t.gains[i].k_theta);
    put_f64_le(record + kGainOffsetKq, t.gains[i].k_q_s);
  }
  for (int i = 0; i < t.segment_count; ++i) {
    std::uint8_t* record = image + kOffsetSegments + static_cast<std::size_t>(i) * kTableSegmentRecordSize;
    const GuidanceSegment& s = t.segments[i];
    put_u16_le(record + kSegmentOffsetStageCode, static_cast<std::uint16_t>(s.stage_code));
    put_f64_le(record + kSegmentOffsetStartTime, s.start_stage_time_s);
    put_f64_le(record + kSegmentOffsetTheta, s.theta_start_rad);
    put_f64_le(record + kSegmentOffsetRate, s.rate_rad_s);
  }
  for (int i = 0; i < t.schedule_count; ++i) {
    std::uint8_t* record = image + kOffsetSchedule + static_cast<std::size_t>(i) * kTableScheduleRecordSize;
    const GainSchedulePoint& p = t.schedule[i];
    put_u16_le(record + kScheduleOffsetStageCode, static_cast<std::uint16_t>(p.stage_code));
    put_f64_le(record + kScheduleOffsetTime, p.stage_time_s);
    put_f64_le(record + kScheduleOffsetKTheta, p.k_theta);
    put_f64_le(record + kScheduleOffsetKq, p.k_q_s);
  }
  reseal_table_image(image);
  return Status::kOk;
}

// ---- decoding ------------------------------------------------------------------------------------

Status table_image_size_status(const std::uint8_t* image, std::size_t size) {
  // A version-2 image (812 bytes, no gain schedule) is named by its version, not by its size.
  if (image != nullptr && size == kTableVersion2ImageSize && image[0] == kTableMagic[0] &&
      image[1] == kTableMagic[1] && image[2] == kTableMagic[2] && image[3] == kTableMagic[3] &&
      get_u16_le(image + kOffsetFormatVersion) == 2u) {
    return Status::kTableImageVersion2;
  }
  if (image == nullptr || size < kTableImageSize) return Status::kTableImageTruncated;
  if (size > kTableImageSize) return Status::kTableImageSizeMismatch;
  return Status::kOk;
}

Status decode_table_image(const std::uint8_t* image, std::size_t size, GuidanceTable* table) {
  const Status sized = table_image_size_status(image, size);
  if (!ok(sized)) return sized;
  if (size > kTableImageSize) return Status::kTableImageSizeMismatch;
  for (std::size_t i = 0; i < 4; ++i) {
    if (image[kOffsetMagic + i] != kTableMagic[i]) return Status::kTableImageBadMagic;
  }
  if (get_u16_le(image + kOffsetFormatVersion) != kTableFormatVersion) {
    return Status::kTableImageUnsupportedVersion;
  }
  if (get_u32_le(image + kOffsetImageSize) != kTableImageSize) return Status::kTableImageSizeMismatch;
  if (get_u16_le(image + kOffsetHeaderSize) != kTableHeaderSize ||
      get_u16_le(image + kOffsetSegmentCapacity) != static_cast<std::uint16_t>(kMaxLinearSegments) ||
      get_u16_le(image + kOffsetSegmentRecordSize) != kTableSegmentRecordSize ||
      get_u16_le(image + kOffsetStageGainCount) != kTableStageGainCount ||
      get_u16_le(image + kOffsetScheduleCapacity) != static_cast<std::uint16_t>(kMaxGainSchedulePoints) ||
      get_u16_le(image + kOffsetScheduleRecordSize) != kTableScheduleRecordSize) {
    return Status::kTableImageLayoutMismatch;
  }
  if (crc32(image, kOffsetCrc) != stored_table_crc(image)) return Status::kTableImageCrcMismatch;

  const std::uint16_t count = get_u16_le(image + kOffsetSegmentCount);
  if (count > static_cast<std::uint16_t>(kMaxLinearSegments)) return Status::kTooManyLinearSegments;
  const std::uint16_t schedule_count = get_u16_le(image + kOffsetScheduleCount);
  if (schedule_count > static_cast<std::uint16_t>(kMaxGainSchedulePoints)) {
    return Status::kTooManyGainSchedulePoints;
  }
  if (!all_zero(image + kOffsetHeaderReserved1, 2) ||
      !all_zero(image + kOffsetHeaderReserved2, kHeaderReserved2Bytes)) {
    return Status::kTableImageReservedBytesSet;
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(kMaxGainSchedulePoints); ++i) {
    const std::uint8_t* record = image + kOffsetSchedule + i * kTableScheduleRecordSize;
    const bool used = i < schedule_count;
    if (used ? !all_zero(record + kScheduleOffsetReserved, 6) : !all_zero(record, kTableScheduleRecordSize)) {
      return Status::kTableImageReservedBytesSet;
    }
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(kMaxLinearSegments); ++i) {
    const std::uint8_t* record = image + kOffsetSegments + i * kTableSegmentRecordSize;
    const bool used = i < count;
    if (used ? !all_zero(record + kSegmentOffsetReserved, 6) : !all_zero(record, kTableSegmentRecordSize)) {
      return Status::kTableImageReservedBytesSet;
    }
  }
  if (!text_field_valid(image + kOffsetMissionId, kTableMissionIdBytes) ||
      !text_field_valid(image + kOffsetGeneratorVersion, kTableGeneratorVersionBytes)) {
    return Status::kTableImageTextInvalid;
  }
  const std::uint64_t created = get_u64_le(image + kOffsetCreatedUnixS);
  if (created > static_cast<std::uint64_t>(kTableMaxCreatedUnixS)) {
    return Status::kTableCreationTimeOutOfRange;
  }

  // Decode into a local table first: *table changes only when everything is valid. The decoded
  // table is small (about 0.8 KiB) and lives on the caller's stack frame for this call only.
  GuidanceTable decoded;
  decoded.format_version = kTableFormatVersion;
  decoded.created_unix_s = static_cast<std::int64_t>(created);
  decoded.spin_option = static_cast<int>(get_u16_le(image + kOffsetSpinOption));
  get_text(image + kOffsetMissionId, kTableMissionIdBytes, decoded.mission_id);
  get_text(image + kOffsetGeneratorVersion, kTableGeneratorVersionBytes, decoded.generator_version);
  decoded.liftoff_duration_s = get_f64_le(image + kOffsetLiftoffDuration);
  decoded.max_pitch_rate_rad_s = get_f64_le(image + kOffsetMaxPitchRate);
  decoded.min_pitch_rate_rad_s = get_f64_le(image + kOffsetMinPitchRate);
  decoded.min_pitch_rate_change_rad_s = get_f64_le(image + kOffsetMinPitchRateChange);
  decoded.max_deflection_rad = get_f64_le(image + kOffsetMaxDeflection);
  decoded.stage4_theta_rad = get_f64_le(image + kOffsetStage4Theta);
  decoded.stage4_chi_rad = get_f64_le(image + kOffsetStage4Chi);
  decoded.stage5_theta_rad = get_f64_le(image + kOffsetStage5Theta);
  decoded.stage5_chi_rad = get_f64_le(image + kOffsetStage5Chi);
  for (std::size_t i = 0; i < kTableStageGainCount; ++i) {
    const std::uint8_t* record = image + kOffsetStageGains + i * kTableStageGainRecordSize;
    decoded.gains[i].k_theta = get_f64_le(record + kGainOffsetKTheta);
    decoded.gains[i].k_q_s = get_f64_le(record + kGainOffsetKq);
  }
  decoded.segment_count = static_cast<int>(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* record = image + kOffsetSegments + i * kTableSegmentRecordSize;
    GuidanceSegment& s = decoded.segments[i];
    s.stage_code = static_cast<int>(get_u16_le(record + kSegmentOffsetStageCode));
    s.start_stage_time_s = get_f64_le(record + kSegmentOffsetStartTime);
    s.theta_start_rad = get_f64_le(record + kSegmentOffsetTheta);
    s.rate_rad_s = get_f64_le(record + kSegmentOffsetRate);
  }
  decoded.schedule_count = static_cast<int>(schedule_count);
  for (std::size_t i = 0; i < schedule_count; ++i) {
    const std::uint8_t* record = image + kOffsetSchedule + i * kTableScheduleRecordSize;
    GainSchedulePoint& p = decoded.schedule[i];
    p.stage_code = static_cast<int>(get_u16_le(record + kScheduleOffsetStageCode));
    p.stage_time_s = get_f64_le(record + kScheduleOffsetTime);
    p.k_theta = get_f64_le(record + kScheduleOffsetKTheta);
    p.k_q_s = get_f64_le(record + kScheduleOffsetKq);
  }
  const Status valid = validate_guidance_table(decoded);
  if (!ok(valid)) return valid;
  *table = decoded;
  return Status::kOk;
}

// ---- gain schedule -------------------------------------------------------------------------------

StageGains scheduled_gains(const GuidanceTable& t, int stage_code, double stage_time_s) {
  StageGains out = (stage_code >= 1 && stage_code <= kMaxStages) ? t.gains[stage_code - 1] : StageGains{};
  int previous = -1;  // last point of the stage at or before stage_time_s
  int next = -1;      // first point of the stage after it
  for (int i = 0; i < kMaxGainSchedulePoints; ++i) {
    if (i >= t.schedule_count) break;
    const GainSchedulePoint& p = t.schedule[i];
    if (p.stage_code != stage_code) continue;
    if (p.stage_time_s <= stage_time_s) {
      previous = i;
    } else {
      next = i;
      break;
    }
  }
  if (previous < 0 && next < 0) return out;
  if (previous < 0 || next < 0) {
    const GainSchedulePoint& p = t.schedule[previous < 0 ? next : previous];
    out.k_theta = p.k_theta;
    out.k_q_s = p.k_q_s;
    return out;
  }
  const GainSchedulePoint& a = t.schedule[previous];
  const GainSchedulePoint& b = t.schedule[next];
  const double f = (stage_time_s - a.stage_time_s) / (b.stage_time_s - a.stage_time_s);
  out.k_theta = a.k_theta + f * (b.k_theta - a.k_theta);
  out.k_q_s = a.k_q_s + f * (b.k_q_s - a.k_q_s);
  return out;
}

}  // namespace tolip

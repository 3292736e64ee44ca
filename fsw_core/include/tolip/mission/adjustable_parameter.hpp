// The adjustable-parameter codes of data block 6 (manual Sec. 22, "Adjustable Parameter Codes";
// Sec. 9's S matrix): one named type and one mapping, used by validation, the optimizer and the
// reports. Decks store the manual's integer codes; code here switches on the names.
#pragma once

namespace tolip {

enum class AdjustableParameter : int {
  kStage4Theta = 1,       // spun stage-4 pitch attitude
  kStage4Chi = 2,         // spun stage-4 yaw attitude
  kCoastAfterStage3 = 3,  // length of coast 8
  kCoastAfterStage2 = 4,  // length of coast 7
  kCoastAfterStage1 = 5,  // length of coast 6
  kLaunchAzimuth = 6,
  kLaunchTime = 7,  // time of day (Space Age Date)
  kStage5Theta = 8,
  kStage5Chi = 9,
  kCoastAfterStage4 = 10,  // length of coast 9
  kCoastAfterStage5 = 11,  // length of coast 10
};

// Decodes a data block 6 code; false (and *out unchanged) for a code outside 1-11.
constexpr bool decode_adjustable_parameter(int code, AdjustableParameter* out) {
  if (code < 1 || code > 11) return false;
  *out = static_cast<AdjustableParameter>(code);
  return true;
}

constexpr int adjustable_parameter_code(AdjustableParameter p) { return static_cast<int>(p); }

// The coast (stage code 6-10) whose length the parameter is; 0 for the other parameters.
constexpr int adjusted_coast_stage_code(AdjustableParameter p) {
  switch (p) {
    case AdjustableParameter::kCoastAfterStage1: return 6;
    case AdjustableParameter::kCoastAfterStage2: return 7;
    case AdjustableParameter::kCoastAfterStage3: return 8;
    case AdjustableParameter::kCoastAfterStage4: return 9;
    case AdjustableParameter::kCoastAfterStage5: return 10;
    default: return 0;
  }
}

// The same from a code; 0 for a code that is not a coast length (or not a code at all).
constexpr int adjusted_coast_stage_code(int code) {
  AdjustableParameter p = AdjustableParameter::kStage4Theta;
  return decode_adjustable_parameter(code, &p) ? adjusted_coast_stage_code(p) : 0;
}

}  // namespace tolip

// Hand-made guidance tables for the table-image, loader and executor tests (no deck involved).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "tolip/core/constants.hpp"
#include "tolip/table/guidance_executor.hpp"
#include "tolip/table/table_image.hpp"

namespace tolip::test {

// An encoded table image (the table-image and loader tests; not for the allocation-free paths).
using Image = std::vector<std::uint8_t>;

inline Image encode(const GuidanceTable& table) {
  Image image(kTableImageSize);
  EXPECT_EQ(encode_table_image(table, image.data(), image.size()), Status::kOk);
  return image;
}

inline void set_text(char* field, std::size_t capacity, const char* text) {
  std::memset(field, 0, capacity + 1);
  std::strncpy(field, text, capacity);
}

// A valid three-stage program: lift-off 3 s, segments in stages 1, 6, 2, 7, 3, 8, spun 4 and 5,
// distinct gains per stage. `variant` shifts the attitudes so that two tables differ everywhere.
inline GuidanceTable make_test_table(int variant = 0) {
  GuidanceTable t;
  set_text(t.mission_id, kTableMissionIdBytes, variant == 0 ? "TEST MISSION A" : "TEST MISSION B");
  set_text(t.generator_version, kTableGeneratorVersionBytes, "test");
  t.created_unix_s = 1700000000 + variant;
  t.liftoff_duration_s = 3.0;
  t.max_pitch_rate_rad_s = 5.0 * kDegToRad;
  t.min_pitch_rate_rad_s = 0.05 * kDegToRad;
  t.min_pitch_rate_change_rad_s = 0.05 * kDegToRad;
  t.max_deflection_rad = 10.0 * kDegToRad;
  const double shift = variant * 1.5 * kDegToRad;
  t.stage4_theta_rad = -20.0 * kDegToRad + shift;
  t.stage4_chi_rad = 1.0 * kDegToRad;
  t.stage5_theta_rad = -25.0 * kDegToRad + shift;
  t.stage5_chi_rad = 2.0 * kDegToRad;
  for (int code = 1; code <= kMaxStages; ++code) {
    t.gains[code - 1].k_theta = 0.5 + 0.1 * code + 0.01 * variant;
    t.gains[code - 1].k_q_s = 0.2 + 0.05 * code;
  }
  const GuidanceSegment segments[] = {
      {1, 3.0, 90.0 * kDegToRad + shift, -2.0 * kDegToRad},
      {1, 10.0, 76.0 * kDegToRad + shift, -0.5 * kDegToRad},
      {6, 0.0, 60.0 * kDegToRad + shift, 0.0},
      {2, 0.0, 60.0 * kDegToRad + shift, -1.0 * kDegToRad},
      {2, 20.0, 40.0 * kDegToRad + shift, 0.25 * kDegToRad},
      {7, 0.0, 45.0 * kDegToRad + shift, 0.0},
      {3, 5.0, 38.0 * kDegToRad + shift, -0.1 * kDegToRad},
      {8, 0.0, 35.0 * kDegToRad + shift, 0.0},
  };
  t.segment_count = static_cast<int>(sizeof segments / sizeof segments[0]);
  for (int i = 0; i < t.segment_count; ++i) t.segments[i] = segments[i];
  return t;
}

// The stage timeline the test tables are flown with (time from lift-off of each stage start).
struct TestStageStart {
  int code;
  double start_s;
};
inline constexpr TestStageStart kTestTimeline[] = {{1, 0.0},   {6, 45.0},  {2, 50.0},  {7, 88.0},
                                                   {3, 94.0},  {8, 130.0}, {4, 550.0}, {9, 578.0},
                                                   {5, 600.0}, {10, 630.0}};

// Flies `executor` over kTestTimeline at 10 Hz from lift-off to 650 s (past the last stage
// start), each stage event delivered once its start has passed, and hands every step's command to
// `use(command)`, which returns whether its own work succeeded. Returns the number of failed
// calls (stage events, steps and uses). Allocates nothing itself: the no-heap tests call it
// inside their counting window.
template <typename UseCommand>
int fly_test_timeline(GuidanceExecutor& executor, const UseCommand& use) {
  const int stage_count = static_cast<int>(sizeof kTestTimeline / sizeof kTestTimeline[0]);
  int failures = 0;
  int events = 1;  // the first stage starts with the executor
  for (int k = 0; k <= 6500; ++k) {
    const double t = k / 10.0;
    while (events < stage_count && kTestTimeline[events].start_s <= t) {
      if (!ok(executor.stage_event(kTestTimeline[events].code, kTestTimeline[events].start_s))) ++failures;
      ++events;
    }
    GuidanceCommand command;
    if (!ok(executor.step(t, &command))) ++failures;
    if (!use(command)) ++failures;
  }
  return failures;
}

}  // namespace tolip::test

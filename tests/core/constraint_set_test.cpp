// The one constraint set of a run (tolip/optimizer/constraint_set.hpp; issue 18 item 1, manual
// Sec. 13, 22 IP(13)): the inequality rule, corrections (an excess counts, a deficit does not),
// the deadband judgement, and values and terminal partials on a flown trajectory against the
// per-code functions of constraint_parameters.hpp they must equal.
#include <gtest/gtest.h>

#include <cmath>

#include "support/reference_mission.hpp"
#include "tolip/optimizer/constraint_set.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {
namespace {

ConstraintCode decoded(int code) {
  ConstraintCode c;
  EXPECT_EQ(decode_constraint_code(code, &c), Status::kOk) << code;
  return c;
}

TEST(Sec22ConstraintSet, Sec13_HeatingAndIP13QbarAreInequalitiesNothingElseIs) {
  Options options;
  EXPECT_TRUE(is_inequality_constraint(decoded(14), options));
  EXPECT_FALSE(is_inequality_constraint(decoded(29), options));  // stage-2 q-bar, IP(13) = 0
  options.ip[13] = 1;
  EXPECT_TRUE(is_inequality_constraint(decoded(29), options));
  for (int code : {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 27, 100}) {
    EXPECT_FALSE(is_inequality_constraint(decoded(code), options)) << code;
  }
}

TEST(Sec22ConstraintSet, AnExcessCountsADeficitDoesNotAndMetIsTheSameRule) {
  Options options;
  options.ip[13] = 1;
  ConstraintSet set;
  ASSERT_EQ(append_constraint(decoded(7), 1000.0, 10.0, options, &set), Status::kOk);  // altitude
  ASSERT_EQ(append_constraint(decoded(29), 500.0, 5.0, options, &set), Status::kOk);   // q-bar <= 500
  EXPECT_EQ(append_constraint(decoded(7), 1000.0, 0.0, options, &set), Status::kDeadbandNotPositive);
  ASSERT_EQ(set.count, 2);
  EXPECT_FALSE(set.inequality[0]);
  EXPECT_TRUE(set.inequality[1]);
  // Equality: desired - achieved either way.
  EXPECT_EQ(constraint_correction(set, 0, 1012.0), -12.0);
  EXPECT_EQ(constraint_correction(set, 0, 988.0), 12.0);
  // Inequality: 30 above the limit asks for -30, any amount below it for nothing.
  EXPECT_EQ(constraint_correction(set, 1, 530.0), -30.0);
  EXPECT_EQ(constraint_correction(set, 1, 100.0), 0.0);
  for (double achieved : {100.0, 496.0, 504.0, 506.0}) {
    const double values[kMaxConstraints] = {1005.0, achieved};
    const bool met = std::fabs(constraint_correction(set, 1, achieved)) <= 5.0;
    EXPECT_EQ(constraint_met(set.codes[1], true, achieved, 500.0, 5.0), met) << achieved;
    EXPECT_EQ(within_deadbands(set, 0, values), met) << achieved;
  }
  const double off[kMaxConstraints] = {1011.0, 100.0};
  EXPECT_FALSE(within_deadbands(set, 0, off));
  EXPECT_TRUE(within_deadbands(set, 1, off));  // entry 0 (a payoff) is not judged from 1 on
}

TEST(Sec22ConstraintSet, ValuesAndTerminalsOnTheReferenceFlightAreThePerCodeFunctions) {
  static Mission mission;
  static PreparedCase prepared;
  static Trajectory trajectory;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(mission, prepared, &trajectory), Status::kOk);
  ConstraintSet set;
  set.payload_payoff = true;
  ASSERT_EQ(append_constraint(decoded(0), 0.0, 1.0, mission.options, &set), Status::kOk);
  for (int code : {7, 2, 3, 10, 27}) {
    ASSERT_EQ(append_constraint(decoded(code), 0.0, 1.0, mission.options, &set), Status::kOk);
  }
  double values[kMaxConstraints] = {};
  ConstraintTerminal terminals[kMaxConstraints];
  ASSERT_EQ(evaluate_constraints(set, mission, trajectory, values), Status::kOk);
  ASSERT_EQ(constraint_terminals(set, mission, trajectory, terminals), Status::kOk);
  EXPECT_EQ(values[0], mission.vehicle.payload_lb);
  for (int i = 1; i < set.count; ++i) {
    const int index = constraint_point_index(set.codes[i], trajectory);
    ASSERT_GE(index, 0);
    const ConstraintPoint point = constraint_point_at(mission, trajectory, index);
    double value = 0.0;
    AdjointVector partials;
    ASSERT_EQ(constraint_value(mission.constants, mission.launch, set.codes[i], point, &value), Status::kOk);
    ASSERT_EQ(constraint_partials(mission.constants, mission.launch, set.codes[i], point, &partials),
              Status::kOk);
    EXPECT_EQ(values[i], value) << set.codes[i].code;
    EXPECT_EQ(terminals[i].point, index);
    EXPECT_EQ(terminals[i].partials, partials);
  }
  // The stage-2 altitude (27) applies at stage 2's burnout, not at the final point.
  EXPECT_LT(terminals[5].point, trajectory.point_count - 1);
  // A stage that is not flown is no point of the trajectory: a named status, nothing evaluated.
  ConstraintSet missing;
  ASSERT_EQ(append_constraint(decoded(57), 0.0, 1.0, mission.options, &missing), Status::kOk);
  EXPECT_EQ(evaluate_constraints(missing, mission, trajectory, values),
            Status::kConstraintPointNotInTrajectory);
}

}  // namespace
}  // namespace tolip

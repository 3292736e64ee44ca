// The flight application's defined reaction to a failed port (docs/hil.md, "The ports"; issue 14
// structural coverage): every port call that fails is counted under its own name and the cycle
// goes on; a table store that fails is a rejection; an incomplete set of ports does not boot.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "support/guidance_table_fixture.hpp"
#include "tolip/hal/flight_application.hpp"

namespace tolip::hal {
namespace {

// Ports whose every call succeeds unless told to fail.
struct Fake {
  test::Image image = test::encode(test::make_test_table());
  std::uint32_t cycle = 0;
  StageDiscretes discretes;
  bool fail_clock = false, fail_platform = false, fail_actuators = false, fail_store = false,
       fail_discretes = false, fail_telemetry = false;
  PlatformSample sample = PlatformSample{1.5, 0.0, 0.0, 0.0};  // what the platform reads
  std::size_t store_overstates_by = 0;                         // bytes the store claims beyond those it wrote
  ActuatorCommand last_command;
  int commands = 0, frames = 0;

  static Fake& of(void* context) { return *static_cast<Fake*>(context); }
  static Status wait(void* c, std::uint32_t* cycle) {
    *cycle = of(c).cycle++;
    return of(c).fail_clock ? Status::kHalClockOverrun : Status::kOk;
  }
  static Status platform(void* c, PlatformSample* s) {
    *s = of(c).sample;
    return of(c).fail_platform ? Status::kHalSensorInvalid : Status::kOk;
  }
  static Status actuators(void* c, const ActuatorCommand& command) {
    of(c).last_command = command;
    ++of(c).commands;
    return of(c).fail_actuators ? Status::kHalActuatorRejected : Status::kOk;
  }
  static Status store(void* c, std::uint8_t* buffer, std::size_t capacity, std::size_t* size) {
    if (of(c).fail_store) return Status::kHalTableStoreFailed;
    *size = of(c).image.size() < capacity ? of(c).image.size() : capacity;
    std::memcpy(buffer, of(c).image.data(), *size);
    *size += of(c).store_overstates_by;
    return Status::kOk;
  }
  static Status read_discretes(void* c, StageDiscretes* d) {
    *d = of(c).discretes;
    return of(c).fail_discretes ? Status::kHalDiscretesInvalid : Status::kOk;
  }
  static Status emit(void* c, const TelemetryFrame&) {
    ++of(c).frames;
    return of(c).fail_telemetry ? Status::kHalTelemetryFailed : Status::kOk;
  }
  Ports ports() {
    Ports p;
    p.clock = ClockPort{this, wait, 0.02};
    p.platform = InertialPlatformPort{this, platform};
    p.actuators = ActuatorPort{this, actuators};
    p.table_store = TableStorePort{this, store};
    p.discretes = DiscretesPort{this, read_discretes};
    p.telemetry = TelemetryPort{this, emit};
    return p;
  }
};

TEST(HalFlightApplication, EachFailedPortIsCountedUnderItsNameAndTheCycleGoesOn) {
  static Fake fake;
  static FlightApplication app(fake.ports());
  ASSERT_EQ(app.boot(), Status::kOk);
  EXPECT_EQ(app.counters().table_loads, 1u);
  EXPECT_EQ(app.run_minor_cycle(), Status::kOk);
  EXPECT_EQ(app.counters().total_faults(), 0u);

  // One failed port at a time, each counted under its own name only; the cycle reports the fault.
  struct PortCase {
    const char* port;
    bool Fake::*fail;
    std::uint32_t FlightCounters::*counter;
  };
  const PortCase cases[] = {
      {"actuators", &Fake::fail_actuators, &FlightCounters::actuator_rejections},
      {"telemetry", &Fake::fail_telemetry, &FlightCounters::telemetry_drops},
      {"clock", &Fake::fail_clock, &FlightCounters::clock_overruns},
      {"discretes", &Fake::fail_discretes, &FlightCounters::discrete_faults},
      {"platform", &Fake::fail_platform, &FlightCounters::platform_dropouts},
  };
  std::uint32_t faults_before = 0;
  for (const PortCase& c : cases) {
    SCOPED_TRACE(c.port);
    fake.*c.fail = true;
    EXPECT_NE(app.run_minor_cycle(), Status::kOk);
    EXPECT_EQ(app.counters().*c.counter, 1u);
    EXPECT_EQ(app.counters().total_faults(), ++faults_before);
    fake.*c.fail = false;
  }
  // Stage events follow the flight order: stage 3 after stage 1 is taken (a later stage); back to
  // stage 2 after it is refused, counted, and stage 3 stays in force.
  fake.discretes.stage_code = 3;
  fake.discretes.sequence = 1;
  EXPECT_EQ(app.run_minor_cycle(), Status::kOk);
  EXPECT_EQ(app.executor().stage_in_force(), 3);
  fake.discretes.stage_code = 2;
  fake.discretes.sequence = 2;
  EXPECT_NE(app.run_minor_cycle(), Status::kOk);
  EXPECT_EQ(app.counters().stage_events_refused, 1u);
  EXPECT_EQ(app.executor().stage_in_force(), 3);
  // Every cycle commanded the actuators and emitted its telemetry, failed or not.
  EXPECT_EQ(app.counters().cycles, 8u);
  EXPECT_EQ(fake.commands, 8);
  EXPECT_EQ(fake.frames, 8);
  EXPECT_EQ(app.counters().total_faults(), 6u);
  // A table store that fails is a rejection; the table in force stays.
  const std::uint32_t crc = app.tables().active_crc();
  fake.fail_store = true;
  EXPECT_EQ(app.load_table(), Status::kHalTableStoreFailed);
  EXPECT_EQ(app.counters().table_rejections, 1u);
  EXPECT_EQ(app.tables().active_crc(), crc);
}

// docs/hil.md, "The ports": a platform read that succeeds but carries a non-finite angle or rate is a
// dropout like a failed read, named kHalSensorInvalid; the cycle flies the last good sample
// propagated with its rates, and the telemetry says the platform was not valid.
TEST(HalFlightApplication, APlatformSampleWithANonFiniteFieldIsADropoutNamedSensorInvalid) {
  static Fake fake;
  static FlightApplication app(fake.ports());
  ASSERT_EQ(app.boot(), Status::kOk);
  fake.sample = PlatformSample{1.5, 0.01, 0.1, -0.2};
  ASSERT_EQ(app.run_minor_cycle(), Status::kOk);
  EXPECT_TRUE(app.last_frame().platform_valid);
  double PlatformSample::*const fields[] = {&PlatformSample::theta_rad, &PlatformSample::chi_rad,
                                            &PlatformSample::pitch_rate_rad_s,
                                            &PlatformSample::yaw_rate_rad_s};
  const double dt = 0.02;
  double theta = 1.5;
  double chi = 0.01;
  std::uint32_t dropouts = 0;
  for (double PlatformSample::*field : fields) {
    PlatformSample bad = PlatformSample{1.5, 0.01, 0.1, -0.2};
    bad.*field = std::nan("");
    fake.sample = bad;
    EXPECT_EQ(app.run_minor_cycle(), Status::kHalSensorInvalid);
    EXPECT_EQ(app.counters().platform_dropouts, ++dropouts);
    EXPECT_FALSE(app.last_frame().platform_valid);
    theta += 0.1 * dt;  // the last good sample, propagated by its rates one cycle more
    chi += -0.2 * dt;
    EXPECT_DOUBLE_EQ(app.last_frame().theta_measured_rad, theta);
    EXPECT_DOUBLE_EQ(app.last_frame().chi_measured_rad, chi);
    EXPECT_TRUE(std::isfinite(app.last_frame().pitch_command));
  }
  fake.sample = PlatformSample{1.5, 0.01, 0.1, -0.2};
  EXPECT_EQ(app.run_minor_cycle(), Status::kOk);
  EXPECT_TRUE(app.last_frame().platform_valid);
  EXPECT_EQ(app.last_frame().theta_measured_rad, 1.5);
}

// docs/hil.md, "The ports": the application rides through kMaxPlatformDropoutCycles failed platform
// reads on the propagated attitude, commands neutral actuators from the next one on (stage 1: fins
// and vanes at zero), and controls again as soon as a good sample returns.
TEST(HalFlightApplication, AfterTheDropoutAllowanceTheActuatorsGoNeutralUntilAGoodSampleReturns) {
  static Fake fake;
  static FlightApplication app(fake.ports());
  ASSERT_EQ(app.boot(), Status::kOk);
  ASSERT_EQ(app.run_minor_cycle(), Status::kOk);
  ASSERT_EQ(fake.last_command.kind, ActuatorKind::kFinsAndVanes);
  ASSERT_NE(fake.last_command.pitch, 0.0);  // 90 deg commanded, 1.5 rad measured
  fake.fail_platform = true;
  for (int i = 1; i <= kMaxPlatformDropoutCycles; ++i) {
    EXPECT_EQ(app.run_minor_cycle(), Status::kHalSensorInvalid);
    EXPECT_NE(fake.last_command.pitch, 0.0) << "dropout " << i << " still flies the propagated attitude";
  }
  EXPECT_EQ(app.counters().neutral_cycles, 0u);
  EXPECT_EQ(app.run_minor_cycle(), Status::kHalSensorInvalid);
  EXPECT_EQ(app.counters().neutral_cycles, 1u);
  EXPECT_EQ(fake.last_command.kind, ActuatorKind::kFinsAndVanes);
  EXPECT_EQ(fake.last_command.pitch, 0.0);
  EXPECT_EQ(fake.last_command.yaw, 0.0);
  EXPECT_EQ(app.counters().platform_dropouts, static_cast<std::uint32_t>(kMaxPlatformDropoutCycles) + 1u);
  fake.fail_platform = false;
  EXPECT_EQ(app.run_minor_cycle(), Status::kOk);
  EXPECT_EQ(app.counters().neutral_cycles, 1u);
  EXPECT_NE(fake.last_command.pitch, 0.0);
}

// A boot whose table store fails leaves no table: every cycle is then a guidance fault named
// kNoActiveTable, with no actuator kind commanded, and still emits its telemetry.
TEST(HalFlightApplication, WithoutATableEachCycleIsAGuidanceFaultWithNoActuatorCommanded) {
  static Fake fake;
  fake.fail_store = true;
  static FlightApplication app(fake.ports());
  EXPECT_EQ(app.boot(), Status::kHalTableStoreFailed);
  EXPECT_EQ(app.run_minor_cycle(), Status::kNoActiveTable);
  EXPECT_EQ(app.counters().guidance_faults, 1u);
  EXPECT_EQ(fake.last_command.kind, ActuatorKind::kNone);
  EXPECT_EQ(fake.frames, 1);
  EXPECT_EQ(app.last_frame().table_crc, 0u);
  // The store mends: the next upload loads and the cycle flies.
  fake.fail_store = false;
  EXPECT_EQ(app.load_table(), Status::kOk);
  EXPECT_EQ(app.run_minor_cycle(), Status::kOk);
  EXPECT_EQ(fake.last_command.kind, ActuatorKind::kFinsAndVanes);
}

// run_minor_cycle() reports the first failed call of the cycle in its order (clock first,
// telemetry last), and counts every one.
TEST(HalFlightApplication, TheFirstFailedCallOfACycleIsTheOneReported) {
  static Fake fake;
  static FlightApplication app(fake.ports());
  ASSERT_EQ(app.boot(), Status::kOk);
  fake.fail_clock = true;
  fake.fail_telemetry = true;
  EXPECT_EQ(app.run_minor_cycle(), Status::kHalClockOverrun);
  EXPECT_EQ(app.counters().clock_overruns, 1u);
  EXPECT_EQ(app.counters().telemetry_drops, 1u);
  fake.fail_clock = false;
  fake.fail_actuators = true;
  EXPECT_EQ(app.run_minor_cycle(), Status::kHalActuatorRejected);
  EXPECT_EQ(app.counters().telemetry_drops, 2u);
}

// docs/hil.md, "The minor cycle", step 2: a new sequence number with the stage in force raises no stage
// event; a new stage code raises one even when the sequence number did not change.
TEST(HalFlightApplication, AStageEventFollowsTheStageCodeNotTheSequenceNumber) {
  static Fake fake;
  static FlightApplication app(fake.ports());
  ASSERT_EQ(app.boot(), Status::kOk);
  fake.discretes.stage_code = 1;
  fake.discretes.sequence = 5;
  EXPECT_EQ(app.run_minor_cycle(), Status::kOk);
  EXPECT_EQ(app.executor().stage_in_force(), 1);
  fake.discretes.stage_code = 2;  // sequence still 5
  EXPECT_EQ(app.run_minor_cycle(), Status::kOk);
  EXPECT_EQ(app.executor().stage_in_force(), 2);
  EXPECT_EQ(app.counters().stage_events_refused, 0u);
}

// A table store that claims more bytes than the upload buffer holds is read as an oversized image:
// the loader refuses it by size, and the table in force stays.
TEST(HalFlightApplication, AStoreThatOverstatesItsImageIsRefusedBySizeAndTheTableStays) {
  static Fake fake;
  static FlightApplication app(fake.ports());
  ASSERT_EQ(app.boot(), Status::kOk);
  const std::uint32_t crc = app.tables().active_crc();
  fake.store_overstates_by = 4096;
  EXPECT_EQ(app.load_table(), Status::kTableImageSizeMismatch);
  EXPECT_EQ(app.counters().table_rejections, 1u);
  EXPECT_EQ(app.tables().active_crc(), crc);
}

// docs/hil.md, "The minor cycle", "Spun stages": the coast before a spun stage commands that stage's spin-up
// attitude from the table (coast 8 -> stage 4's, coast 9 -> stage 5's); the spun stage itself
// flies its attitude through the executor.
TEST(HalFlightApplication, TheCoastBeforeEachSpunStageAlignsToThatStagesAttitude) {
  static Fake fake;
  static FlightApplication app(fake.ports());
  ASSERT_EQ(app.boot(), Status::kOk);
  const GuidanceTable table = test::make_test_table();
  ASSERT_EQ(table.spin_option, 1);  // stages 4 and 5 spun
  const struct {
    int coast;
    int spun;
    double theta_rad;
    double chi_rad;
  } coasts[] = {{8, 4, table.stage4_theta_rad, table.stage4_chi_rad},
                {9, 5, table.stage5_theta_rad, table.stage5_chi_rad}};
  std::uint32_t sequence = 0;
  for (const auto& c : coasts) {
    SCOPED_TRACE(c.coast);
    fake.discretes.stage_code = c.coast;
    fake.discretes.sequence = ++sequence;
    EXPECT_EQ(app.run_minor_cycle(), Status::kOk);
    EXPECT_EQ(app.executor().stage_in_force(), c.coast);
    EXPECT_EQ(app.last_frame().theta_command_rad, c.theta_rad);
    EXPECT_EQ(app.last_frame().chi_command_rad, c.chi_rad);
    fake.discretes.stage_code = c.spun;
    fake.discretes.sequence = ++sequence;
    EXPECT_EQ(app.run_minor_cycle(), Status::kOk);
    EXPECT_EQ(app.executor().stage_in_force(), c.spun);
    EXPECT_EQ(fake.last_command.kind, ActuatorKind::kControlJets);
  }
}

TEST(HalFlightApplication, AnIncompleteSetOfPortsDoesNotBoot) {
  static Fake fake;
  const Ports good = fake.ports();
  ASSERT_TRUE(ports_complete(good));
  // Each port without its function in turn, then a clock period that is not a positive number:
  // one change from the complete set at a time, so that each check proves its own rule.
  struct Broken {
    const char* what;
    void (*apply)(Ports*);
  };
  const Broken broken[] = {
      {"clock.wait_next_cycle", [](Ports* p) { p->clock.wait_next_cycle = nullptr; }},
      {"platform.read", [](Ports* p) { p->platform.read = nullptr; }},
      {"actuators.command", [](Ports* p) { p->actuators.command = nullptr; }},
      {"table_store.read", [](Ports* p) { p->table_store.read = nullptr; }},
      {"discretes.read", [](Ports* p) { p->discretes.read = nullptr; }},
      {"telemetry.emit", [](Ports* p) { p->telemetry.emit = nullptr; }},
      {"clock.period_s NaN", [](Ports* p) { p->clock.period_s = std::nan(""); }},
      {"clock.period_s 0", [](Ports* p) { p->clock.period_s = 0.0; }},
  };
  Ports p = good;
  for (const Broken& b : broken) {
    p = good;
    b.apply(&p);
    EXPECT_FALSE(ports_complete(p)) << b.what;
  }
  // The last of them (a zero clock period) must not boot either.
  static FlightApplication app(p);
  EXPECT_EQ(app.boot(), Status::kHalPortMissing);
  EXPECT_EQ(app.counters().table_loads, 0u);
}

}  // namespace
}  // namespace tolip::hal

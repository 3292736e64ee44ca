// The flight application's defined reaction to a failed port (docs/hil.md, "Faults"; issue 14
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
  int commands = 0, frames = 0;

  static Fake& of(void* context) { return *static_cast<Fake*>(context); }
  static Status wait(void* c, std::uint32_t* cycle) {
    *cycle = of(c).cycle++;
    return of(c).fail_clock ? Status::kHalClockOverrun : Status::kOk;
  }
  static Status platform(void* c, PlatformSample* s) {
    *s = PlatformSample{};
    s->theta_rad = 1.5;
    return of(c).fail_platform ? Status::kHalSensorInvalid : Status::kOk;
  }
  static Status actuators(void* c, const ActuatorCommand&) {
    ++of(c).commands;
    return of(c).fail_actuators ? Status::kHalActuatorRejected : Status::kOk;
  }
  static Status store(void* c, std::uint8_t* buffer, std::size_t capacity, std::size_t* size) {
    if (of(c).fail_store) return Status::kHalTableStoreFailed;
    *size = of(c).image.size() < capacity ? of(c).image.size() : capacity;
    std::memcpy(buffer, of(c).image.data(), *size);
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

// `tolip hil`: the hardware-in-the-loop bench (docs/hil.md, docs/cli.md). Uploads a table image
// through the flight-side loader of the flight application (fsw_core hal), flies it against the
// simulated vehicle of hal_sim from lift-off to the final burnout, and reports the achieved
// burnout and orbit beside the ground prediction for the same table.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tolip/core/constants.hpp"
#include "tolip/core/stage_codes.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/guidance_table.hpp"
#include "tolip_ground/hardover_run.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_ground/units.hpp"
#include "tolip_hal_sim/bench.hpp"
#include "tolip_hal_sim/qemu_target.hpp"

namespace tolip::ground {
namespace {

// Where the cortex-m7 preset builds the processor-in-the-loop image, from the repository root.
constexpr const char* kDefaultPilImage = "build-cortex-m7/flight_image/tolip_flight_pil.elf";

std::string scenario_list() {
  std::string names;
  for (const sim::ScenarioInfo& info : sim::scenarios()) {
    if (!names.empty()) names += ", ";
    names += info.name;
  }
  return names;
}

// The ground prediction's burnout: the end of the last powered stage of the trajectory.
const TrajectoryPoint* predicted_burnout(const Trajectory& trajectory) {
  const TrajectoryPoint* found = nullptr;
  for (int e = 0; e < trajectory.stage_count; ++e) {
    const StageEvent& event = trajectory.stages[e];
    if (is_powered_stage(event.code) && event.completed) found = &trajectory.points[event.last_point];
  }
  return found;
}

std::string hex32(std::uint32_t v) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08X", static_cast<unsigned>(v));
  return text;
}

nlohmann::ordered_json counters_json(const hal::FlightCounters& c) {
  nlohmann::ordered_json j;
  j["cycles"] = c.cycles;
  j["clock_overruns"] = c.clock_overruns;
  j["platform_dropouts"] = c.platform_dropouts;
  j["neutral_cycles"] = c.neutral_cycles;
  j["actuator_rejections"] = c.actuator_rejections;
  j["telemetry_drops"] = c.telemetry_drops;
  j["discrete_faults"] = c.discrete_faults;
  j["stage_events_refused"] = c.stage_events_refused;
  j["guidance_faults"] = c.guidance_faults;
  j["table_loads"] = c.table_loads;
  j["table_rejections"] = c.table_rejections;
  j["saturated_cycles"] = c.saturated_cycles;
  return j;
}

nlohmann::ordered_json link_json(const sim::LinkCounters& c) {
  return nlohmann::ordered_json{
      {"frames_sent", c.frames_sent}, {"frames_lost", c.frames_lost}, {"frames_corrupt", c.frames_corrupt}};
}

struct Burnout {
  double time_s = 0.0;
  double altitude_ft = 0.0;
  double inertial_velocity_ft_s = 0.0;
  double inertial_flight_path_deg = 0.0;
  double inclination_deg = 0.0;
  double weight_lb = 0.0;
  double perigee_altitude_nmi = 0.0;
  double apogee_altitude_nmi = 0.0;
  bool has_apogee = false;
};

nlohmann::ordered_json burnout_json(const Burnout& b) {
  nlohmann::ordered_json j;
  j["time_s"] = b.time_s;
  j["altitude_ft"] = b.altitude_ft;
  j["altitude_nmi"] = b.altitude_ft / kFeetPerNauticalMile;
  j["inertial_velocity_ft_s"] = b.inertial_velocity_ft_s;
  j["inertial_flight_path_deg"] = b.inertial_flight_path_deg;
  j["inclination_deg"] = b.inclination_deg;
  j["weight_lb"] = b.weight_lb;
  j["perigee_altitude_nmi"] = b.perigee_altitude_nmi;
  if (b.has_apogee) j["apogee_altitude_nmi"] = b.apogee_altitude_nmi;
  return j;
}

Burnout make_burnout(double time_s, double altitude_ft, double weight_lb, const OrbitElements& orbit,
                     double equatorial_radius_ft) {
  Burnout b;
  b.time_s = time_s;
  b.altitude_ft = altitude_ft;
  b.weight_lb = weight_lb;
  b.inertial_velocity_ft_s = orbit.inertial.velocity_ft_s;
  b.inertial_flight_path_deg = orbit.inertial.flight_path_angle_rad * kRadToDeg;
  b.inclination_deg = orbit.inclination_rad * kRadToDeg;
  b.perigee_altitude_nmi = (orbit.perigee_radius_ft - equatorial_radius_ft) / kFeetPerNauticalMile;
  b.has_apogee = orbit.type == OrbitType::kElliptic;
  b.apogee_altitude_nmi = (orbit.apogee_radius_ft - equatorial_radius_ft) / kFeetPerNauticalMile;
  return b;
}

}  // namespace

int run_hil_command(const HilCommandOptions& options, std::ostream& out, std::ostream& err) {
  // The command line first: scenario and rate.
  sim::BenchConfig config;
  if (!sim::find_scenario(options.scenario, &config.scenario)) {
    err << "tolip: --scenario '" << options.scenario
        << "': unknown scenario; the scenarios are: " << scenario_list() << '\n';
    return kExitBadInput;
  }
  if (!(options.rate_hz >= 10.0 && options.rate_hz <= 1000.0)) {
    err << "tolip: --rate-hz " << options.rate_hz << ": the minor-cycle rate must be in [10, 1000] Hz\n";
    return kExitBadInput;
  }
  config.cycle_hz = options.rate_hz;
  const bool on_qemu = options.target == "qemu";
  if (!on_qemu && options.target != "host") {
    err << "tolip: --target '" << options.target << "': the targets are host and qemu\n";
    return kExitBadInput;
  }
  if (on_qemu && options.rate_hz != hal::kDefaultMinorCycleHz) {
    err << "tolip: --rate-hz " << options.rate_hz << ": the processor-in-the-loop image flies "
        << hal::kDefaultMinorCycleHz << " Hz\n";
    return kExitBadInput;
  }
  if (!on_qemu && !options.image_path.empty()) {
    err << "tolip: --image: only with --target qemu\n";
    return kExitBadInput;
  }
  if (!(options.duration_s >= 0.0) || !std::isfinite(options.duration_s)) {
    err << "tolip: --duration-s " << options.duration_s << ": must be a positive number of seconds\n";
    return kExitBadInput;
  }
  config.duration_s = options.duration_s;
  const std::string image_path =
      options.image_path.empty() ? std::string(kDefaultPilImage) : options.image_path;
  config.seed = options.seed;
  for (const std::string* path : {&options.telemetry_path}) {
    if (!path->empty() &&
        (names_same_file(*path, options.deck_path) || names_same_file(*path, options.table_path))) {
      err << "tolip: --telemetry '" << *path << "' names an input file; name another file\n";
      return kExitBadInput;
    }
  }

  // The table image: read and checked with the flight-side decoder before anything flies.
  std::vector<std::uint8_t> image;
  std::string read_error;
  if (!read_table_image_file(options.table_path, &image, &read_error)) {
    err << "tolip: " << read_error << '\n';
    return kExitBadInput;
  }
  auto uploaded = std::make_unique<GuidanceTable>();
  const Status decoded = decode_table_image(image.data(), image.size(), uploaded.get());
  if (!ok(decoded)) {
    err << "tolip: " << options.table_path
        << ": the table image fails the flight-side validation: " << status_name(decoded) << ": "
        << status_message(decoded) << '\n';
    return kExitBadInput;
  }

  // The deck: one case, with the rigid-body data of blocks 33-37 and 44-45.
  Deck deck;
  DeckError deck_error;
  if (!load_deck(options.deck_path, &deck, &deck_error)) {
    err << "tolip: " << deck_error.to_string() << '\n';
    return kExitBadInput;
  }
  if (deck.cases.size() != 1) {
    err << "tolip: " << options.deck_path << ": the bench flies one case; the deck holds "
        << deck.cases.size() << '\n';
    return kExitBadInput;
  }
  const DeckCase& deck_case = deck.cases[0];
  std::unique_ptr<tolip::HardoverData> hardover;
  if (!prepare_hardover_data(options.deck_path, "", deck_case, &hardover, err)) return kExitBadInput;

  // The ground prediction for the table: the linearized trajectory under IP(7) = 1 (what export
  // made the table of), else the data block 40 trajectory.
  const Mission& deck_mission = *deck_case.mission;
  auto prepared = std::make_unique<PreparedCase>();
  const Status prepare = prepare_case(deck_mission, prepared.get());
  if (!ok(prepare)) {
    err << "tolip: " << status_name(prepare) << ": " << status_message(prepare) << '\n';
    return kExitFailure;
  }
  OptimizationRun run;
  const Mission* mission = &deck_mission;
  const PreparedCase* prepared_case = prepared.get();
  const LinearProgram* linearized = nullptr;
  auto flown = std::make_unique<Trajectory>();
  const Trajectory* prediction = flown.get();
  if (deck_mission.options.linearization()) {
    run_optimization(deck_mission, nullptr, &run);
    const JobVerdict verdict = optimization_job_verdict(run);
    if (!ok(verdict.status)) {
      err << "tolip: " << options.deck_path << ": no ground prediction: the " << verdict.failed_step
          << " did not succeed: " << status_name(verdict.status) << ": " << status_message(verdict.status)
          << '\n';
      return kExitFailure;
    }
    mission = &run.linearization.workspace->mission;
    prepared_case = &run.linearization.workspace->prepared;
    linearized = &run.linearization.result->program;
    prediction = &run.linearization.workspace->nominal;
  } else {
    const Status status = fly_trajectory(deck_mission, *prepared, flown.get());
    if (!ok(status)) {
      err << "tolip: trajectory: " << status_name(status) << ": " << status_message(status) << '\n';
      return kExitFailure;
    }
  }

  // Deck/table match: the mission identifier and the segment count of the table the deck exports.
  TableBuildOptions build;
  build.mission_id = options.mission_id;
  auto expected = std::make_unique<GuidanceTable>();
  std::string build_error;
  if (!build_guidance_table(*mission, deck_case.extras, *prepared_case, linearized, build, expected.get(),
                            &build_error)) {
    err << "tolip: " << options.deck_path << ": " << build_error << '\n';
    return kExitBadInput;
  }
  if (std::string(uploaded->mission_id) != expected->mission_id) {
    err << "tolip: " << options.table_path << ": the table does not belong to the deck: mission identifier '"
        << uploaded->mission_id << "', the deck's is '" << expected->mission_id
        << "' (a table exported with --mission-id needs the same --mission-id here)\n";
    return kExitBadInput;
  }
  if (uploaded->segment_count != expected->segment_count) {
    err << "tolip: " << options.table_path
        << ": the table does not belong to the deck: " << uploaded->segment_count
        << " segments, the deck's table has " << expected->segment_count << '\n';
    return kExitBadInput;
  }
  const TrajectoryPoint* predicted = predicted_burnout(*prediction);
  if (predicted == nullptr) {
    err << "tolip: the ground prediction has no completed powered stage\n";
    return kExitFailure;
  }

  // The bench.
  sim::BenchInputs inputs;
  inputs.mission = mission;
  inputs.prepared = prepared_case;
  inputs.hardover = hardover.get();
  inputs.table = image.data();
  inputs.table_size = image.size();
  auto result = std::make_unique<sim::BenchResult>();
  std::unique_ptr<sim::QemuTarget> qemu;
  if (on_qemu) {
    qemu = std::make_unique<sim::QemuTarget>();
    sim::QemuOptions qemu_options;
    qemu_options.image = image_path;
    std::string start_error;
    if (!qemu->start(qemu_options, &start_error)) {
      err << "tolip: --target qemu: " << start_error << '\n';
      return kExitBadInput;
    }
    inputs.flight = qemu.get();
  }
  const auto flight_start = std::chrono::steady_clock::now();
  const Status bench = sim::run_bench(inputs, config, result.get());
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - flight_start).count();
  const sim::BenchResult& r = *result;
  if (qemu) {
    std::string link_error = qemu->error();
    std::string stop_error;
    if (link_error.empty() && !qemu->stop(&stop_error)) link_error = stop_error;
    if (!link_error.empty()) {
      err << "tolip: --target qemu: " << link_error << '\n';
      return kExitBadInput;
    }
  }
  const double flown_s = static_cast<double>(r.telemetry.size()) / config.cycle_hz;

  if (!options.telemetry_path.empty()) {
    std::string write_error;
    if (!write_file_atomically(options.telemetry_path, sim::telemetry_csv(r), &write_error)) {
      err << "tolip: " << write_error << '\n';
      return kExitFailure;
    }
  }

  OrbitElements predicted_orbit;
  const Status predicted_orbit_status = compute_orbit_elements(
      mission->constants, predicted->state, mission->launch.launch_space_age_date_days, &predicted_orbit);
  const double re = mission->constants.earth_equatorial_radius_ft;
  const Burnout ground =
      make_burnout(predicted->time_s, predicted->altitude_ft, predicted->weight_lb, predicted_orbit, re);
  const Burnout achieved =
      make_burnout(r.end_time_s, r.burnout_altitude_ft, r.burnout_weight_lb, r.orbit, re);
  const double d_alt_nmi = (achieved.altitude_ft - ground.altitude_ft) / kFeetPerNauticalMile;
  const double d_vel = achieved.inertial_velocity_ft_s - ground.inertial_velocity_ft_s;
  const double d_inc = achieved.inclination_deg - ground.inclination_deg;
  const sim::ScenarioInfo& info = sim::scenarios()[static_cast<std::size_t>(config.scenario)];

  if (options.json) {
    nlohmann::ordered_json j;
    j["title"] = std::string("HIL bench, scenario ") + info.name;
    j["case_heading"] = uploaded->mission_id;
    j["deck"] = options.deck_path;
    j["table"] = options.table_path;
    j["table_crc"] = hex32(stored_table_crc(image.data()));
    j["mission_id"] = uploaded->mission_id;
    j["scenario"] = info.name;
    j["fault"] = info.fault;
    j["expected"] = info.expected;
    j["seed"] = config.seed;
    j["rate_hz"] = config.cycle_hz;
    j["status"] = status_name(bench);
    j["completed"] = r.completed;
    j["vehicle_lost"] = r.vehicle_lost;
    j["boot"] = status_name(r.boot_status);
    j["upload"] = status_name(r.upload_status);
    j["flown_table_crc"] = hex32(r.table_crc);
    j["achieved"] = burnout_json(achieved);
    j["predicted"] = burnout_json(ground);
    j["predicted_orbit_status"] = status_name(predicted_orbit_status);
    j["difference"] = {{"altitude_nmi", d_alt_nmi},
                       {"inertial_velocity_ft_s", d_vel},
                       {"inclination_deg", d_inc},
                       {"time_s", achieved.time_s - ground.time_s}};
    j["tracking"] = {{"cycles", r.tracked_cycles},
                     {"pitch_rms_deg", r.pitch_error_rms_rad * kRadToDeg},
                     {"pitch_max_deg", r.pitch_error_max_rad * kRadToDeg},
                     {"yaw_rms_deg", r.yaw_error_rms_rad * kRadToDeg},
                     {"yaw_max_deg", r.yaw_error_max_rad * kRadToDeg}};
    j["peak_qbar_alpha_lb_deg_ft2"] = r.peak_qbar_alpha_lbf_rad_ft2 * kRadToDeg;
    j["peak_qbar_alpha_time_s"] = r.peak_qbar_alpha_time_s;
    j["actuator_saturation_s"] = r.actuator_saturation_s;
    j["target"] = {{"kind", options.target},
                   {"image", on_qemu ? image_path : std::string()},
                   {"cycles", r.telemetry.size()},
                   {"wall_s", wall_s},
                   {"cycles_per_s", wall_s > 0.0 ? static_cast<double>(r.telemetry.size()) / wall_s : 0.0},
                   {"real_time_factor", wall_s > 0.0 ? flown_s / wall_s : 0.0},
                   {"console", qemu ? qemu->log() : std::string()}};
    j["truncated"] = r.truncated;
    j["flight_counters"] = counters_json(r.flight);
    j["sensor_link"] = link_json(r.sensor_link);
    j["actuator_link"] = link_json(r.actuator_link);
    j["telemetry_rows"] = r.telemetry.size();
    // Every 10th cycle for the plots (tolip plot: hil_theta, hil_tracking_error, hil_actuators).
    nlohmann::ordered_json series;
    std::vector<double> t, theta_c, theta, pitch_error, yaw_error, pitch, yaw;
    for (std::size_t i = 0; i < r.telemetry.size(); i += 10) {
      const sim::TelemetryRecord& rec = r.telemetry[i];
      const bool fins = rec.frame.stage_code == 1;
      t.push_back(rec.frame.time_s);
      theta_c.push_back(rec.frame.theta_command_rad * kRadToDeg);
      theta.push_back(rec.theta_true_rad * kRadToDeg);
      pitch_error.push_back((rec.frame.theta_command_rad - rec.theta_true_rad) * kRadToDeg);
      yaw_error.push_back((rec.frame.chi_command_rad - rec.chi_true_rad) * kRadToDeg);
      pitch.push_back(fins ? rec.fin_pitch_rad * kRadToDeg : rec.fin_pitch_rad * 100.0);
      yaw.push_back(fins ? rec.fin_yaw_rad * kRadToDeg : rec.fin_yaw_rad * 100.0);
    }
    series["time_s"] = t;
    series["theta_command_deg"] = theta_c;
    series["theta_true_deg"] = theta;
    series["pitch_error_deg"] = pitch_error;
    series["yaw_error_deg"] = yaw_error;
    series["pitch_actuator"] = pitch;
    series["yaw_actuator"] = yaw;
    j["hil_series"] = series;
    out << j.dump(2) << '\n';
  } else {
    char line[1024];
    out << "TOLIP HARDWARE-IN-THE-LOOP BENCH  scenario " << info.name << "  seed " << config.seed << "  "
        << config.cycle_hz << " Hz\n";
    out << "table " << options.table_path << " (CRC-32 " << hex32(stored_table_crc(image.data())) << ", '"
        << uploaded->mission_id << "')  boot " << status_name(r.boot_status);
    if (config.scenario == sim::Scenario::kCorruptUpload ||
        config.scenario == sim::Scenario::kTruncatedUpload) {
      out << "  upload " << status_name(r.upload_status);
    }
    out << "  flown " << hex32(r.table_crc) << '\n';
    out << "fault: " << info.fault << "\nexpected: " << info.expected << '\n';
    out << "outcome: "
        << (r.completed      ? "flew to the final burnout"
            : r.vehicle_lost ? "VEHICLE LOST"
            : r.truncated    ? "stopped by --duration-s"
                             : status_name(bench))
        << " at " << r.end_time_s << " s (stage " << r.final_stage << ")\n\n";
    out << "                          ACHIEVED      PREDICTED     DIFFERENCE\n";
    auto row = [&](const char* name, double a, double g) {
      std::snprintf(line, sizeof line, "%-22s %14.4f %14.4f %14.4f\n", name, a, g, a - g);
      out << line;
    };
    row("time (s)", achieved.time_s, ground.time_s);
    row("altitude (nmi)", achieved.altitude_ft / kFeetPerNauticalMile,
        ground.altitude_ft / kFeetPerNauticalMile);
    row("inertial V (ft/s)", achieved.inertial_velocity_ft_s, ground.inertial_velocity_ft_s);
    row("inertial gamma (deg)", achieved.inertial_flight_path_deg, ground.inertial_flight_path_deg);
    row("inclination (deg)", achieved.inclination_deg, ground.inclination_deg);
    row("perigee alt (nmi)", achieved.perigee_altitude_nmi, ground.perigee_altitude_nmi);
    if (achieved.has_apogee && ground.has_apogee) {
      row("apogee alt (nmi)", achieved.apogee_altitude_nmi, ground.apogee_altitude_nmi);
    }
    row("weight (lb)", achieved.weight_lb, ground.weight_lb);
    std::snprintf(line, sizeof line,
                  "\ntracking error (stages 1-3, %d cycles): pitch rms %.4f max %.4f deg, yaw rms %.4f max "
                  "%.4f deg\n",
                  r.tracked_cycles, r.pitch_error_rms_rad * kRadToDeg, r.pitch_error_max_rad * kRadToDeg,
                  r.yaw_error_rms_rad * kRadToDeg, r.yaw_error_max_rad * kRadToDeg);
    out << line;
    std::snprintf(
        line, sizeof line, "peak q-bar x alpha %.1f lb deg/ft^2 at %.2f s; actuator saturation %.2f s\n",
        r.peak_qbar_alpha_lbf_rad_ft2 * kRadToDeg, r.peak_qbar_alpha_time_s, r.actuator_saturation_s);
    out << line;
    const hal::FlightCounters& c = r.flight;
    out << "flight counters: cycles " << c.cycles << ", platform dropouts " << c.platform_dropouts
        << ", neutral cycles " << c.neutral_cycles << ", stage events refused " << c.stage_events_refused
        << ", table loads " << c.table_loads << ", rejections " << c.table_rejections << ", saturated cycles "
        << c.saturated_cycles << '\n';
    out << "link: sensor frames " << r.sensor_link.frames_sent << " (lost " << r.sensor_link.frames_lost
        << ", corrupt " << r.sensor_link.frames_corrupt << "), actuator frames "
        << r.actuator_link.frames_sent << " (lost " << r.actuator_link.frames_lost << ", corrupt "
        << r.actuator_link.frames_corrupt << ")\n";
    if (on_qemu) {
      std::snprintf(line, sizeof line,
                    "target: qemu (%s): %zu cycles in %.2f s wall, %.0f cycles/s, %.2fx real time\n",
                    image_path.c_str(), r.telemetry.size(), wall_s,
                    wall_s > 0.0 ? static_cast<double>(r.telemetry.size()) / wall_s : 0.0,
                    wall_s > 0.0 ? flown_s / wall_s : 0.0);
      out << line;
    }
    if (!options.telemetry_path.empty()) {
      out << "telemetry: " << r.telemetry.size() << " rows to " << options.telemetry_path << '\n';
    }
  }
  if (!ok(bench)) {
    err << "tolip: bench: " << status_name(bench) << ": " << status_message(bench) << '\n';
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace tolip::ground

// `tolip simulate`: load a deck, fly the forward trajectory, report it (listing, CSV, JSON).
#include <memory>
#include <ostream>
#include <string>

#include "tolip/core/status.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {
namespace {

void print_status(std::ostream& err, Status status) {
  err << "tolip: " << status_name(status) << ": " << status_message(status) << '\n';
}

}  // namespace

int run_simulate_command(const SimulateCommandOptions& options, std::ostream& out,
                         std::ostream& err) {
  std::unique_ptr<Mission> mission = make_mission();
  DeckError deck_error;
  if (!load_toml_deck(options.deck_path, mission.get(), &deck_error)) {
    err << "tolip: " << deck_error.to_string() << '\n';
    return kExitBadInput;
  }

  // PreparedCase and Trajectory are large fixed-capacity structures: keep them on the heap.
  auto prepared = std::make_unique<PreparedCase>();
  auto trajectory = std::make_unique<Trajectory>();

  SimulationReport report;
  report.mission = mission.get();
  report.trajectory = trajectory.get();
  report.deck_path = options.deck_path;

  Status status = prepare_case(*mission, prepared.get());
  if (ok(status)) {
    status = fly_trajectory(*mission, *prepared, trajectory.get());
    if (ok(status) && !ok(trajectory->status)) status = trajectory->status;
    if (ok(status) && stored_point_count(*trajectory) == 0) status = Status::kNotPrepared;
  } else {
    trajectory->status = status;
    trajectory->point_count = 0;
    trajectory->stage_count = 0;
  }
  if (ok(status)) {
    const TrajectoryPoint& final_point = trajectory->final_point();
    status = compute_orbit_elements(mission->constants, final_point.state,
                                    mission->launch.launch_space_age_date_days, &report.orbit);
    report.has_orbit = ok(status);
  }
  report.status = status;

  // Every point flown goes to the CSV, also after a failure (it shows where the run stopped).
  if (!options.csv_path.empty()) {
    std::string write_error;
    const bool written = write_file_atomically(
        options.csv_path,
        [&report](std::ostream& csv) {
          write_trajectory_csv(csv, report);
          return static_cast<bool>(csv);
        },
        &write_error);
    if (!written) {
      err << "tolip: " << write_error << '\n';
      return kExitFailure;
    }
  }

  if (options.json) {
    out << dump_json(trajectory_json(report));
  } else {
    write_trajectory_listing(out, report);
  }
  out.flush();

  if (!ok(status)) {
    print_status(err, status);
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace tolip::ground

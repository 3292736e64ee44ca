// Radar tracking of a case (tolip_ground/radar_run.hpp).
#include "tolip_ground/radar_run.hpp"

#include <cstring>

#include "tolip_ground/dispersion_run.hpp"

namespace tolip::ground {

void fill_radar_stations(const std::vector<RadarStation>& deck, tolip::RadarStations* stations) {
  *stations = tolip::RadarStations{};
  // More than the core holds is caught by the deck reader; the count check of the core names it
  // again should a caller skip the reader.
  stations->count = static_cast<int>(deck.size());
  const std::size_t held = std::min(deck.size(), static_cast<std::size_t>(kMaxRadarStations));
  for (std::size_t i = 0; i < held; ++i) {
    tolip::RadarStation& s = stations->stations[i];
    std::strncpy(s.id, deck[i].id.c_str(), kRadarStationIdLength);
    s.geodetic_latitude_rad = deck[i].geodetic_latitude_rad;
    s.longitude_rad = deck[i].longitude_rad;
    s.altitude_ft = deck[i].altitude_ft;
  }
}

void run_radar_step(const Constants& constants, const std::vector<RadarStation>& deck,
                    const Trajectory& trajectory, const std::string& kind, RadarStep* step) {
  step->outcome = StepOutcome::kRun;
  step->trajectory_kind = kind;
  step->deck_stations = deck;
  step->stations = std::make_unique<tolip::RadarStations>();
  fill_radar_stations(deck, step->stations.get());
  step->result = std::make_unique<RadarResult>();
  step->status = compute_radar_tracking(constants, *step->stations, trajectory, step->result.get());
}

void skip_radar_step(const std::vector<RadarStation>& deck, Status why, RadarStep* step) {
  step->outcome = StepOutcome::kSkipped;
  step->status = why;
  step->deck_stations = deck;
}

const Trajectory* final_nominal_trajectory(const Mission& mission, const OptimizationRun& run,
                                           std::string* kind, Status* why) {
  DispersionNominal nominal;
  if (!final_dispersion_nominal(mission, run, &nominal, kind, why)) return nullptr;
  return mission.options.linearization() ? &run.linearization.workspace->nominal : &run.workspace->nominal;
}

}  // namespace tolip::ground

// Deck data blocks 33-37 (DeckExtras::body_dynamics) -> the core's Mission::body_dynamics.
//
// The deck keeps the manual's units (body stations in inches); the core works in ft (docs/
// architecture.md, units policy), so the conversion happens here, at the edge.
#include <string>

#include "tolip_ground/deck_extras.hpp"

namespace tolip::ground {
namespace {

constexpr double kFtPerInch = 1.0 / 12.0;

template <int N>
bool fill_table(const DeckTable& deck, double y_scale, Table<N>* table, int block, int stage, const std::string& field,
                const std::string& what, BodyDynamicsMappingFault* fault) {
  table->clear();
  if (deck.empty()) return true;
  if (deck.size() > N) {
    if (fault != nullptr) {
      fault->data_block = block;
      fault->stage_code = stage;
      fault->field = field;
      fault->message = what + " has " + std::to_string(deck.size()) + " points; the core holds at most " +
                       std::to_string(N);
    }
    return false;
  }
  for (int i = 0; i < deck.size(); ++i) {
    const std::size_t at = static_cast<std::size_t>(i);
    (void)table->append(deck.x[at], deck.y[at] * y_scale);  // fits; finite and increasing (deck reader)
  }
  (void)table->finalize();
  return true;
}

}  // namespace

bool fill_mission_body_dynamics(const BodyDynamicsData& deck, Mission* mission, BodyDynamicsMappingFault* fault) {
  BodyDynamicsBlocks& core = mission->body_dynamics;
  core = BodyDynamicsBlocks{};
  if (!deck.present) return true;
  core.present = true;
  for (int k = 0; k < kBodyDynamicsStages; ++k) {
    const std::size_t at = static_cast<std::size_t>(k);
    core.position_gain[k] = deck.position_gain[at];
    core.rate_gain_s[k] = deck.rate_gain_s[at];
    core.control_station_ft[k] = deck.control_station_in[at] * kFtPerInch;
  }
  core.jet_vane_effectiveness_per_rad = deck.jet_vane_effectiveness_per_rad_per_vane;
  core.moment_reference_station_ft = deck.moment_reference_station_in * kFtPerInch;
  core.reference_length_ft = deck.reference_length_ft;
  core.reference_area_ft2 = mission->vehicle.stages[stage_index(1)].reference_area_ft2;
  if (!fill_table(deck.fin_normal_force_per_rad_per_fin, 1.0, &core.fin_normal_force_per_rad, 34, 0,
                  "body_dynamics.fin_normal_force", "the C_N_delta table (data block 34)", fault) ||
      !fill_table(deck.pitching_moment_per_rad, 1.0, &core.pitching_moment_per_rad, 35, 0,
                  "body_dynamics.pitching_moment", "the C_M_alpha table (data block 35)", fault) ||
      !fill_table(deck.fin_pitching_moment_per_rad_per_fin, 1.0, &core.fin_pitching_moment_per_rad, 36, 0,
                  "body_dynamics.fin_pitching_moment", "the C_M_delta table (data block 36)", fault)) {
    return false;
  }
  for (int k = 0; k < kCgTableStages; ++k) {
    const std::string stage = std::to_string(k + 1);
    if (!fill_table(deck.cg_station_in[static_cast<std::size_t>(k)], kFtPerInch, &core.cg_station_ft[k], 37, k + 1,
                    "body_dynamics.cg." + stage, "the stage " + stage + " c.g. history (data block 37)", fault)) {
      return false;
    }
  }
  return true;
}

}  // namespace tolip::ground

// Listing, JSON and CSV of the dispersion analysis (tolip_ground/dispersion_report.hpp).
#include "tolip_ground/dispersion_report.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "dispersion_quantities.hpp"
#include "listing_pager.hpp"
#include "number_format.hpp"
#include "tolip/core/constants.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::ordered_json;
using report_detail::fixed_cell;
using report_detail::json_number;
using report_detail::kOrbitQuantities;
using report_detail::kStagingQuantities;
using report_detail::left_aligned;
using report_detail::right_aligned;
using report_detail::round_trip;

std::string e_cell(double value, int width) {
  if (!std::isfinite(value)) return right_aligned("-", width);
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6E", value);
  return right_aligned(buffer, width);
}

const char* code_name(int code) {
  DispersionCodeInfo info;
  return dispersion_code_info(code, &info) ? info.name : "";
}
const char* plane_name(int code) {
  DispersionCodeInfo info;
  if (!dispersion_code_info(code, &info)) return "";
  return info.plane == DispersionPlane::kYaw       ? "yaw"
         : info.plane == DispersionPlane::kHighLow ? "high/low"
                                                   : "none";
}

constexpr double kLbDegPerLbRad = kRadToDeg;

void write_trajectory_block(report_detail::Pager& pager, const DispersionResult& r,
                            const DispersedTrajectory& t, bool nominal) {
  const int columns = r.staging_count;
  pager.reserve(6 + 2 * kStagingVariables + 5);
  std::string head = nominal ? " NOMINAL TRAJECTORY (GIANT PLANE 40)"
                             : " DISPERSED TRAJECTORY  CODE " + right_aligned(std::to_string(t.code), 2) +
                                   "  " + left_aligned(t.title, 12) + "  (" + code_name(t.code) + ")";
  pager.emit(head);
  if (!ok(t.status)) {
    pager.emit(std::string("   NOT COMPUTED: ") + status_name(t.status) + ": " + status_message(t.status));
    pager.emit("");
    return;
  }
  std::string columns_line = left_aligned("", 22);
  for (int j = 0; j < columns; ++j)
    columns_line += right_aligned(staging_point_name(r.staging_stage_code[j]), 18);
  pager.emit(columns_line);
  for (int i = 0; i < kStagingVariables; ++i) {
    std::string line = "   " + left_aligned(kStagingQuantities[i].label, 19);
    std::string disp = "     " + left_aligned("DISPERSION", 17);
    for (int j = 0; j < columns; ++j) {
      line += fixed_cell(t.values[j][i] * kStagingQuantities[i].scale, kStagingQuantities[i].decimals, 18);
      disp +=
          fixed_cell(t.dispersions[j][i] * kStagingQuantities[i].scale, kStagingQuantities[i].decimals, 18);
    }
    pager.emit(line);
    if (!nominal) pager.emit(disp);
  }
  std::string names = left_aligned("   ORBIT ELEMENTS", 22);
  std::string values = left_aligned("     VALUE", 22);
  std::string disps = left_aligned("     DISPERSION", 22);
  for (int i = 0; i < kOrbitDispersionElements; ++i) {
    names += right_aligned(kOrbitQuantities[i].label, 16);
    values += e_cell(t.orbit[i] * kOrbitQuantities[i].scale, 16);
    disps += e_cell(t.orbit_dispersions[i] * kOrbitQuantities[i].scale, 16);
  }
  pager.emit(names);
  pager.emit(values);
  if (!nominal) pager.emit(disps);
  pager.emit("   MAX QBAR*ALPHA " + fixed_cell(t.max_qbar_alpha_lbf_rad_ft2 * kLbDegPerLbRad, 1, 12) +
             " LB DEG/FT2 AT T =" + fixed_cell(t.max_qbar_alpha_time_s, 2, 10) + " S");
  pager.emit("");
}

void write_group(report_detail::Pager& pager, const DispersionResult& r, const ThreeSigmaGroup& g,
                 const char* title) {
  const int columns = r.staging_count;
  pager.reserve(4 + 2 * kStagingVariables);
  std::string members;
  for (int k = 0; k < g.member_count; ++k) {
    if (k > 0) members += ' ';
    members += std::to_string(g.members[k]);
  }
  pager.emit(std::string(" ") + title + "  CODES: " + (members.empty() ? "(none)" : members));
  std::string columns_line = left_aligned("", 22);
  for (int j = 0; j < columns; ++j)
    columns_line += right_aligned(staging_point_name(r.staging_stage_code[j]), 18);
  pager.emit(columns_line);
  for (int i = 0; i < kStagingVariables; ++i) {
    std::string sum = "   " + left_aligned(kStagingQuantities[i].label, 13) + left_aligned(" SUM", 6);
    std::string rss = "   " + left_aligned("", 13) + left_aligned(" RSS", 6);
    for (int j = 0; j < columns; ++j) {
      sum += fixed_cell(g.sum[j][i] * kStagingQuantities[i].scale, kStagingQuantities[i].decimals, 18);
      rss += fixed_cell(g.rss[j][i] * kStagingQuantities[i].scale, kStagingQuantities[i].decimals, 18);
    }
    pager.emit(sum);
    pager.emit(rss);
  }
  pager.emit("");
}

json matrix_json(const double (&m)[kMaxStagingPoints][kStagingVariables], int columns) {
  json rows = json::array();
  for (int j = 0; j < columns; ++j) {
    json row = json::object();
    for (int i = 0; i < kStagingVariables; ++i)
      row[kStagingQuantities[i].key] = json_number(m[j][i] * kStagingQuantities[i].scale);
    rows.push_back(std::move(row));
  }
  return rows;
}

json trajectory_json(const DispersionResult& r, const DispersedTrajectory& t, bool nominal) {
  json out = json::object();
  out["code"] = t.code;
  out["title"] = std::string(t.title);
  out["name"] = code_name(t.code);
  out["plane"] = plane_name(t.code);
  out["status"] = status_name(t.status);
  if (!ok(t.status)) {
    out["status_message"] = status_message(t.status);
    return out;
  }
  out["values"] = matrix_json(t.values, r.staging_count);
  if (!nominal) out["dispersions"] = matrix_json(t.dispersions, r.staging_count);
  json orbit = json::object();
  json orbit_d = json::object();
  for (int i = 0; i < kOrbitDispersionElements; ++i) {
    orbit[kOrbitQuantities[i].key] = json_number(t.orbit[i] * kOrbitQuantities[i].scale);
    orbit_d[kOrbitQuantities[i].key] = json_number(t.orbit_dispersions[i] * kOrbitQuantities[i].scale);
  }
  out["orbit_elements"] = std::move(orbit);
  if (!nominal) out["orbit_element_dispersions"] = std::move(orbit_d);
  out["max_qbar_alpha_lb_deg_ft2"] = json_number(t.max_qbar_alpha_lbf_rad_ft2 * kLbDegPerLbRad);
  out["max_qbar_alpha_time_s"] = json_number(t.max_qbar_alpha_time_s);
  return out;
}

json group_json(const DispersionResult& r, const ThreeSigmaGroup& g) {
  json members = json::array();
  for (int k = 0; k < g.member_count; ++k) members.push_back(g.members[k]);
  return json{{"codes", members},
              {"sum", matrix_json(g.sum, r.staging_count)},
              {"rss", matrix_json(g.rss, r.staging_count)}};
}

}  // namespace

std::string staging_point_name(int stage_code) {
  if (stage_code == 0) return "FINAL POINT";
  std::string name = "STAGE ";
  name += std::to_string(stage_code);
  name += " IGNITION";
  return name;
}
std::string staging_point_key(int stage_code) {
  if (stage_code == 0) return "final_point";
  std::string key = "stage_";
  key += std::to_string(stage_code);
  key += "_ignition";
  return key;
}

namespace report_detail {

void write_dispersion_pages(Pager& pager, const DispersionStep& step) {
  if (step.outcome == StepOutcome::kNotRequested) return;
  pager.new_page("DISPERSION ANALYSIS", false);
  pager.emit(" DISPERSION ANALYSIS (SEC. 15, IP(21) = 1): DISPERSION = DISPERSED - NOMINAL");
  if (step.outcome != StepOutcome::kRun || step.result == nullptr || !ok(step.status)) {
    std::string where;
    if (step.result != nullptr && step.result->fault_code != 0)
      where = " (data block 46 code " + std::to_string(step.result->fault_code) + ")";
    pager.emit(std::string("   NOT COMPUTED: ") + status_name(step.status) + ": " +
               status_message(step.status) + where);
    pager.emit("");
    return;
  }
  const DispersionResult& r = *step.result;
  pager.emit("   ABOUT THE FINAL NOMINAL: THE " +
             std::string(step.nominal_kind == "optimum" ? "OPTIMUM" : "LINEARIZED PROGRAM") +
             ", FROM ITS PAYLOAD; " + std::string(std::to_string(r.count)) + " DISPERSED TRAJECTORIES");
  pager.emit("");
  write_trajectory_block(pager, r, r.nominal, true);
  for (int k = 0; k < r.count; ++k) write_trajectory_block(pager, r, r.trajectories[k], false);

  // The summary of the individual dispersions at the final point.
  pager.new_page("DISPERSION SUMMARY", false);
  const int final_column = r.staging_count - 1;
  pager.emit(" SUMMARY OF INDIVIDUAL DISPERSIONS AT THE FINAL POINT");
  pager.emit(
      "   CODE  TITLE         PLANE        ALTITUDE FT  VELOCITY FT/S      GAMMA DEG  DOWNRANGE NMI "
      "CROSSRANGE NMI"
      "     RP FT  QBAR*ALPHA");
  for (int k = 0; k < r.count; ++k) {
    const DispersedTrajectory& t = r.trajectories[k];
    std::string line = right_aligned(std::to_string(t.code), 7) + "  " + left_aligned(t.title, 12) + "  " +
                       left_aligned(plane_name(t.code), 9);
    if (!ok(t.status)) {
      pager.emit(line + "  NOT COMPUTED: " + status_name(t.status));
      continue;
    }
    for (int i = 0; i < kStagingVariables; ++i) {
      line += fixed_cell(t.dispersions[final_column][i] * kStagingQuantities[i].scale,
                         kStagingQuantities[i].decimals, 15);
    }
    line += fixed_cell(t.orbit_dispersions[2], 0, 10) +
            fixed_cell(t.max_qbar_alpha_lbf_rad_ft2 * kLbDegPerLbRad, 0, 12);
    pager.emit(line);
  }
  pager.emit("");

  const ThreeSigmaSummary& s = r.three_sigma;
  if (!s.computed) {
    pager.emit(" THREE-SIGMA VARIATIONS NOT ASKED FOR (NO CODE 40 CARD IN DATA BLOCK 46)");
    return;
  }
  pager.new_page("THREE SIGMA VARIATIONS", false);
  pager.emit(" THREE-SIGMA VARIATIONS: SUM OF THE DISPERSIONS AND ROOT SUM SQUARE (SEC. 15, 22)");
  pager.emit("   HIGH/LOW BY THE SIGN OF THE FINAL ALTITUDE DISPERSION (VELOCITY WHEN IT IS ZERO)");
  pager.emit("");
  write_group(pager, r, s.yaw, "YAW DISPERSIONS");
  write_group(pager, r, s.high, "HIGH, WITHOUT WINDS");
  write_group(pager, r, s.low, "LOW, WITHOUT WINDS");
  write_group(pager, r, s.high_with_winds, "HIGH, WITH WINDS");
  write_group(pager, r, s.low_with_winds, "LOW, WITH WINDS");
}

}  // namespace report_detail

void write_dispersion_listing(std::ostream& out, const DeckListingOptions* listing,
                              const DispersionStep& step) {
  report_detail::Pager pager(out, listing);
  report_detail::write_dispersion_pages(pager, step);
}

json dispersion_json(const DispersionStep& step) {
  json out = json::object();
  out["status"] = status_name(step.status);
  out["status_message"] = status_message(step.status);
  if (step.result != nullptr && step.result->fault_code != 0) out["fault_code"] = step.result->fault_code;
  out["outcome"] = step.outcome == StepOutcome::kRun       ? "run"
                   : step.outcome == StepOutcome::kSkipped ? "skipped"
                                                           : "not requested";
  if (step.outcome != StepOutcome::kRun || step.result == nullptr || !ok(step.status)) return out;
  const DispersionResult& r = *step.result;
  out["nominal_kind"] = step.nominal_kind;
  json points = json::array();
  for (int j = 0; j < r.staging_count; ++j) points.push_back(staging_point_key(r.staging_stage_code[j]));
  out["staging_points"] = std::move(points);
  out["nominal"] = trajectory_json(r, r.nominal, true);
  json list = json::array();
  for (int k = 0; k < r.count; ++k) list.push_back(trajectory_json(r, r.trajectories[k], false));
  out["trajectories"] = std::move(list);
  const ThreeSigmaSummary& s = r.three_sigma;
  if (s.computed) {
    out["three_sigma"] = json{{"yaw", group_json(r, s.yaw)},
                              {"high", group_json(r, s.high)},
                              {"low", group_json(r, s.low)},
                              {"high_with_winds", group_json(r, s.high_with_winds)},
                              {"low_with_winds", group_json(r, s.low_with_winds)}};
  } else {
    out["three_sigma"] = nullptr;
  }
  return out;
}

void write_dispersion_csv(std::ostream& out, const DispersionStep& step) {
  out << "code,title,status,staging_point";
  for (const report_detail::DispersionQuantity& v : kStagingQuantities) out << ',' << v.key;
  for (const report_detail::DispersionQuantity& v : kStagingQuantities) out << ",d_" << v.key;
  for (const report_detail::DispersionQuantity& o : kOrbitQuantities) out << ',' << o.key;
  for (const report_detail::DispersionQuantity& o : kOrbitQuantities) out << ",d_" << o.key;
  out << ",max_qbar_alpha_lb_deg_ft2,max_qbar_alpha_time_s\n";
  if (step.outcome != StepOutcome::kRun || step.result == nullptr || !ok(step.status)) return;
  const DispersionResult& r = *step.result;
  const auto row = [&](const DispersedTrajectory& t) {
    std::string title(t.title);
    for (char& c : title) {
      if (c == ',' || c == '"') c = ' ';
    }
    if (!ok(t.status)) {
      out << t.code << ',' << title << ',' << status_name(t.status) << ",\n";
      return;
    }
    for (int j = 0; j < r.staging_count; ++j) {
      const bool final_row = j + 1 == r.staging_count;
      out << t.code << ',' << title << ',' << status_name(t.status) << ','
          << staging_point_key(r.staging_stage_code[j]);
      for (int i = 0; i < kStagingVariables; ++i)
        out << ',' << round_trip(t.values[j][i] * kStagingQuantities[i].scale);
      for (int i = 0; i < kStagingVariables; ++i)
        out << ',' << round_trip(t.dispersions[j][i] * kStagingQuantities[i].scale);
      for (int i = 0; i < kOrbitDispersionElements; ++i)
        out << ',' << (final_row ? round_trip(t.orbit[i] * kOrbitQuantities[i].scale) : "");
      for (int i = 0; i < kOrbitDispersionElements; ++i) {
        out << ',' << (final_row ? round_trip(t.orbit_dispersions[i] * kOrbitQuantities[i].scale) : "");
      }
      out << ',' << (final_row ? round_trip(t.max_qbar_alpha_lbf_rad_ft2 * kLbDegPerLbRad) : "") << ','
          << (final_row ? round_trip(t.max_qbar_alpha_time_s) : "") << '\n';
    }
  };
  row(r.nominal);
  for (int k = 0; k < r.count; ++k) row(r.trajectories[k]);
}

}  // namespace tolip::ground

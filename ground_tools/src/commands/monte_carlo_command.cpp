// `tolip montecarlo` (tolip_ground/monte_carlo_command.hpp).
#include "tolip_ground/monte_carlo_command.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "case_output.hpp"
#include "cli_options.hpp"
#include "tolip/core/constants.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/dispersion_run.hpp"
#include "tolip_ground/impact_run.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_ground/plot_files.hpp"
#include "tolip_ground/unused_inputs.hpp"

namespace tolip::ground {
namespace {

constexpr double kMaxOrbitPerigee_nmi = 100000.0;

// The data block and TOML key of a scalar dispersion source's value, in deck units; false for a
// table source (thrust, C_M_alpha, winds).
struct ScalarValue {
  int block = 0;
  const char* key = "";
  double deck_value = 0.0;
  const char* unit = "";
};
bool scalar_value(const DispersionCase& d, DispersionKind kind, ScalarValue* out) {
  switch (kind) {
    case DispersionKind::kWeightIncrement:
      *out = {47, "weight_increment_lb", d.weight_increment_lb, "lb"};
      return true;
    case DispersionKind::kDrag:
      *out = {48, "drag_variation_fraction", d.drag_variation_fraction, ""};
      return true;
    case DispersionKind::kThrustMisalignment:
      *out = {49, "misalignment_deg", d.misalignment_rad * kRadToDeg, "deg"};
      return true;
    case DispersionKind::kControlDeadband:
      *out = {50, "deadband_deg", d.deadband_rad * kRadToDeg, "deg"};
      return true;
    case DispersionKind::kTipoff: *out = {51, "tipoff_deg", d.tipoff_rad * kRadToDeg, "deg"}; return true;
    case DispersionKind::kLaunchAzimuth:
      *out = {52, "launch_azimuth_change_deg", d.launch_change_rad * kRadToDeg, "deg"};
      return true;
    case DispersionKind::kLaunchAttitude:
      *out = {52, "launch_attitude_change_deg", d.launch_change_rad * kRadToDeg, "deg"};
      return true;
    default: return false;
  }
}

// The Monte Carlo's one sigma of a scalar source is its three-sigma value / 3, signed as Sec. 22
// signs the code (high and yaw codes positive, low codes negative): a value of the other sign would
// be a negative sigma. "" when every source is well signed, else the message naming the first.
std::string negative_sigma_fault(const Deck& deck, const std::vector<DispersionCase>& dispersions) {
  for (std::size_t k = 0; k < dispersions.size(); ++k) {
    const DispersionCase& d = dispersions[k];
    DispersionCodeInfo info;
    ScalarValue value;
    if (!dispersion_code_info(d.code, &info) || !scalar_value(d, info.kind, &value)) continue;
    const bool positive = info.plane == DispersionPlane::kYaw || info.high;
    const double sigma = (positive ? value.deck_value : -value.deck_value) / 3.0;
    if (!(sigma < 0.0)) continue;
    std::ostringstream message;
    message << deck.path << ": data block " << value.block << ", dispersion code " << d.code << " ("
            << info.name << "), dispersion[" << k << "]." << value.key << " = " << value.deck_value
            << ": a negative Monte Carlo sigma (" << sigma << (value.unit[0] ? " " : "") << value.unit
            << "); the draw's sigma is the value / 3, signed as Sec. 22 signs the code: "
            << (positive ? "a high or yaw code's value is positive" : "a low code's value is negative");
    return message.str();
  }
  return {};
}

// Whether any source is of a kind the Monte Carlo draws (before the nominal is known; which are
// drawn then depends on it: monte_carlo_draws_source).
bool any_sampled_kind(const DispersionData& data) {
  for (int k = 0; k < data.count; ++k) {
    DispersionCodeInfo info;
    if (!dispersion_code_info(data.sources[k].code, &info)) continue;
    ScalarValue ignored;
    DispersionCase none;
    if (scalar_value(none, info.kind, &ignored)) return true;
    // The table sources: thrust (1-8), C_M_alpha (19-20), winds (36-38).
    if (info.kind == DispersionKind::kVacuumThrust || info.kind == DispersionKind::kPitchingMoment ||
        info.kind == DispersionKind::kWind)
      return true;
  }
  return false;
}

// The casings the samples fly (--impacts, --impact-stages, --no-impacts; by default those of the
// deck's impact analysis, IP(23) = 1) with their data block 43 in *data: "" and *request set (data
// null when off), or the message naming the block, the table and the deck field.
std::string impact_request(const MonteCarloCommandOptions& options, const Deck& deck, ImpactLocusData* data,
                           MonteCarloImpactRequest* request) {
  *request = MonteCarloImpactRequest{};
  const DeckCase& deck_case = deck.cases.front();
  const Mission& mission = *deck_case.mission;
  const bool asked = options.impacts == ImpactMode::kOn || !options.impact_stages.empty();
  const bool on = asked || (options.impacts == ImpactMode::kAuto && mission.options.impact());
  if (!on) return {};
  const std::string needed_by = !options.impact_stages.empty() ? "--impact-stages"
                                : asked                        ? "--impacts"
                                                               : "options.impact (IP(23))";
  bool stages[kImpactStages] = {};
  for (int stage : options.impact_stages) {
    if (stage < 1 || stage > kImpactStages) {
      return "--impact-stages " + std::to_string(stage) +
             ": expected stages 1 to 3 (the expended casings of data block 43)";
    }
    stages[stage - 1] = true;
  }
  if (options.impact_stages.empty()) {
    for (int stage = 1; stage <= kImpactStages; ++stage)
      stages[stage - 1] = mission.vehicle.stages[stage_index(stage)].in_sequence;
  }
  if (!deck_case.extras.impact.present) {
    return deck.path + ": data block 43 (impact.casing_drag): " + needed_by +
           " needs the expended-casing drag tables [impact.casing_drag.N] of the stages flown to impact";
  }
  ImpactMappingFault fault;
  if (!fill_casing_impact_data(mission, deck_case.extras, stages, needed_by, data, &fault)) {
    return impact_fault_text(deck.path, fault);
  }
  request->data = data;
  for (int k = 0; k < kImpactStages; ++k) request->stages[k] = stages[k];
  return {};
}

int fail(std::ostream& err, int code, const std::string& message) {
  err << "tolip: " << message << '\n';
  return code;
}

}  // namespace

void add_monte_carlo_options(CLI::App& command, MonteCarloCommandOptions* options) {
  add_deck_argument(command, &options->deck_path,
                    "TOML deck or card deck of one case with data blocks\n"
                    "46-55 ([[dispersion]]; docs/deck-format.md)");
  command
      .add_option("--samples", options->samples,
                  "Number of dispersed trajectories, 1 to " + std::to_string(kMaxMonteCarloSamples))
      ->required()
      ->type_name("N");
  command
      .add_option("--seed", options->seed,
                  "Key of the counter-based generator, 0 to 2^64 - 1: the same\n"
                  "seed gives the same samples for any threads or ranks")
      ->required()
      ->type_name("S");
  command
      .add_option("--threads", options->threads,
                  "Threads that fly the samples, 1 to " + std::to_string(kMaxMonteCarloThreads) +
                      " (default: one per\nhardware thread); the results do not depend on it")
      ->type_name("K");
  add_json_flag(command, &options->json, "Print one JSON document instead of the listing (docs/cli.md)");
  add_csv_option(command, &options->csv_path,
                 "Also write one row per sample (status, staging-point values\n"
                 "and dispersions, orbit elements, perigee and apogee, max\n"
                 "q-bar alpha, casing impacts) to FILE as CSV, atomically");
  command
      .add_option("--plots", options->plots_dir,
                  "Also draw the figures (burnout altitude, velocity and\n"
                  "flight-path angle histograms, perigee vs apogee, Monte\n"
                  "Carlo vs RSS three-sigma, the casing impact points) into\n"
                  "DIR as PNG and SVG")
      ->type_name("DIR");
  command.add_option("--gnuplot", options->gnuplot, "The gnuplot program for --plots (as 'tolip plot')")
      ->type_name("PROGRAM");
  command
      .add_option("--orbit-perigee-nmi", options->orbit_perigee_nmi,
                  "A sample reaches orbit when its perigee altitude is above\n"
                  "H n.mi. (default 100; 0 to 100000)")
      ->type_name("H");
  CLI::Option* impacts_on = command.add_flag_callback(
      "--impacts", [options] { options->impacts = ImpactMode::kOn; },
      "Also fly every sample's expended casings of stages 1-3 to\n"
      "impact (Sec. 17, data block 43) and report their 99.7 %\n"
      "ellipses (default: when the deck sets IP(23))");
  CLI::Option* impacts_off = command.add_flag_callback(
      "--no-impacts", [options] { options->impacts = ImpactMode::kOff; }, "Never fly the casings to impact");
  impacts_on->excludes(impacts_off);
  command
      .add_option("--impact-stages", options->impact_stages,
                  "The casings to fly, e.g. 1,3 (implies --impacts; default:\n"
                  "every stage 1-3 in the sequence)")
      ->delimiter(',')
      ->type_name("LIST")
      ->excludes(impacts_off);
  add_progress_flags(command, &options->progress,
                     "Show the progress line on stderr even when it is not a terminal",
                     "Never show the progress line");
}

CLI::App* add_monte_carlo_command(CLI::App& app, MonteCarloCommandOptions* options) {
  CLI::App* command = add_command(
      app, "montecarlo",
      "Monte Carlo dispersions (beyond the manual): optimize the deck's\n"
      "case, take the final nominal the dispersion analysis takes\n"
      "(Sec. 15: the linearized program under IP(7) = 1, else the\n"
      "optimum), and fly N samples, each drawing every source of data\n"
      "blocks 46-55 at once (normal, 1 sigma = the deck's value / 3;\n"
      "a table source scaled by its draw). Prints the mean, standard deviation and 0.135/50/99.865 %\n"
      "points of every staging-point quantity and orbit element beside\n"
      "the manual's linear RSS three-sigma, the fraction reaching orbit\n"
      "and the 99.7 % ellipse of the burnout point; with --impacts (by\n"
      "default under IP(23)) the 99.7 % ellipses of the casings' impacts.",
      "Examples:\n"
      "  tolip montecarlo examples/scout/mission.toml --samples 1000 --seed 1\n"
      "  tolip montecarlo examples/scout/mission.toml --samples 1000 --seed 1 \\\n"
      "      --json --csv samples.csv --plots mc\n"
      "  mpirun -np 4 tolip_montecarlo_mpi examples/scout/mission.toml --samples 1000 --seed 1 --json\n"
      "Exit codes: 0 written; 1 the optimization or the nominal failed, or\n"
      "an output could not be written (nothing printed); 2 bad command\n"
      "line (N = 0 or above the cap), deck, no dispersion data, or a\n"
      "negative sigma (the message names the data block and field).\n"
      "Full reference: docs/cli.md, 'tolip montecarlo'.");
  add_monte_carlo_options(*command, options);
  return command;
}

bool fly_on_threads(const MonteCarloJob& job, MonteCarloSamples* samples) {
  MonteCarloProgress progress;
  if (job.progress != nullptr && job.progress->enabled()) {
    ProgressLine* line = job.progress;
    progress = [line](int flown, int count) {
      if (flown == count) line->clear();  // the last count is always shown, however soon it comes
      line->update("sample", flown, count);
    };
  }
  (void)run_monte_carlo(*job.nominal, *job.data, job.seed, job.count, job.threads, samples, progress,
                        job.impacts);
  return true;
}

int run_monte_carlo_command(const MonteCarloCommandOptions& options, std::ostream& out, std::ostream& err) {
  return run_monte_carlo_command(options, fly_on_threads, out, err);
}

int run_monte_carlo_command(const MonteCarloCommandOptions& options, const MonteCarloFlier& flier,
                            std::ostream& out, std::ostream& err) {
  // The command line first: nothing is read or run on a bad one.
  if (options.samples < 1 || options.samples > kMaxMonteCarloSamples) {
    return fail(err, kExitBadInput,
                "--samples " + std::to_string(options.samples) + ": expected 1 to " +
                    std::to_string(kMaxMonteCarloSamples) + " samples (docs/cli.md, 'tolip montecarlo')");
  }
  int threads = options.threads;
  if (threads == -1) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (threads < 1 || threads > kMaxMonteCarloThreads) {
    return fail(err, kExitBadInput,
                "--threads " + std::to_string(options.threads) + ": expected 1 to " +
                    std::to_string(kMaxMonteCarloThreads));
  }
  if (!std::isfinite(options.orbit_perigee_nmi) || options.orbit_perigee_nmi < 0.0 ||
      options.orbit_perigee_nmi > kMaxOrbitPerigee_nmi) {
    std::ostringstream message;
    message << "--orbit-perigee-nmi " << options.orbit_perigee_nmi << ": expected 0 to "
            << kMaxOrbitPerigee_nmi << " n.mi.";
    return fail(err, kExitBadInput, message.str());
  }

  Deck deck;
  DeckError deck_error;
  if (!load_deck(options.deck_path, &deck, &deck_error))
    return fail(err, kExitBadInput, deck_error.to_string());
  if (deck.cases.size() != 1) {
    return fail(err, kExitBadInput,
                options.deck_path + ": a deck of " + std::to_string(deck.cases.size()) +
                    " cases: montecarlo takes a deck of one case");
  }
  if (std::string error; !csv_spares_the_deck(options.csv_path, options.deck_path, 1, &error)) {
    return fail(err, kExitBadInput, error);
  }
  const DeckCase& deck_case = deck.cases.front();
  const Mission& mission = *deck_case.mission;
  const std::vector<DispersionCase>& dispersions = deck_case.extras.dispersions;
  auto data = std::make_unique<DispersionData>();
  DispersionMappingFault fault;
  if (!fill_dispersion_data(dispersions, data.get(), &fault)) {
    return fail(err, kExitBadInput,
                deck.path + ": data block " + std::to_string(fault.data_block) + ", dispersion code " +
                    std::to_string(fault.code) + ", " + fault.field + ": " + fault.message);
  }
  if (data->count == 0 || !any_sampled_kind(*data)) {
    return fail(err, kExitBadInput,
                deck.path +
                    ": data block 46: no dispersion source the Monte Carlo draws: give [[dispersion]] "
                    "entries of codes 1-38 with their data blocks 30, 35, 38 and 47-54 "
                    "(docs/theory/dispersions.md)");
  }
  if (const std::string sign = negative_sigma_fault(deck, dispersions); !sign.empty()) {
    return fail(err, kExitBadInput, sign);
  }
  // The casing impacts: asked for, or the deck's impact analysis (IP(23)); their data checked now.
  auto impact_data = std::make_unique<ImpactLocusData>();
  MonteCarloImpactRequest impacts;
  if (const std::string bad = impact_request(options, deck, impact_data.get(), &impacts); !bad.empty()) {
    return fail(err, kExitBadInput, bad);
  }
  print_deck_input_warnings(err, options.deck_path, deck);

  // The nominal: the optimization job, then the dispersion analysis' choice of the final nominal.
  ProgressLine progress(err, progress_enabled(options.progress));
  OptimizerProgress observer(progress, mission);
  OptimizationRun run;
  run_optimization(mission, progress.enabled() ? &observer : nullptr, &run);
  progress.clear();
  DispersionNominal nominal;
  std::string kind;
  Status why = Status::kOk;
  if (!final_dispersion_nominal(mission, run, &nominal, &kind, &why)) {
    return fail(
        err, kExitFailure,
        std::string("no final nominal to disperse about: ") + status_name(why) + ": " + status_message(why));
  }
  // The manual's deterministic analysis of the same data: the staging columns and the linear RSS.
  auto linear_workspace = std::make_unique<DispersionWorkspace>();
  auto linear = std::make_unique<DispersionResult>();
  if (const Status status = run_dispersions(nominal, *data, linear_workspace.get(), linear.get());
      !ok(status)) {
    return fail(
        err, kExitFailure,
        std::string("the nominal did not fly: ") + status_name(status) + ": " + status_message(status));
  }
  // Every drawn table fits the core's tables once merged with what a sample blends it with.
  int code = 0;
  if (const Status status = check_monte_carlo_data(nominal, *data, &code); !ok(status)) {
    DispersionCodeInfo info;
    (void)dispersion_code_info(code, &info);
    const char* block = info.kind == DispersionKind::kVacuumThrust     ? "30 and 38"
                        : info.kind == DispersionKind::kPitchingMoment ? "35"
                                                                       : "53 and 54";
    return fail(err, kExitBadInput,
                deck.path + ": data block " + block + ", dispersion code " + std::to_string(code) + " (" +
                    info.name + "): " + status_name(status) + ": " + status_message(status) +
                    " once merged with the grid it is blended with (the nominal's table, or the yaw "
                    "wind profile)");
  }
  bool any_drawn = false;
  for (int k = 0; k < data->count; ++k) any_drawn = any_drawn || monte_carlo_draws_source(nominal, *data, k);
  if (!any_drawn) {
    return fail(err, kExitBadInput,
                deck.path +
                    ": data block 46: no dispersion source the Monte Carlo draws about this nominal "
                    "(misalignment needs a body-dynamics nominal, tip-off a spun stage)");
  }

  MonteCarloJob job;
  job.nominal = &nominal;
  job.data = data.get();
  job.seed = options.seed;
  job.count = static_cast<int>(options.samples);
  job.threads = threads;
  job.progress = &progress;
  job.impacts = impacts;
  MonteCarloSamples samples;
  const bool reports = flier(job, &samples);
  progress.clear();
  if (!reports) return kExitOk;  // a helper rank: rank 0 reports
  if (!ok(samples.status)) {
    return fail(err, kExitFailure,
                std::string("the nominal did not fly: ") + status_name(samples.status) + ": " +
                    status_message(samples.status));
  }

  MonteCarloInputs inputs;
  inputs.seed = options.seed;
  inputs.deck_path = options.deck_path;
  inputs.nominal_kind = kind;
  inputs.orbit_perigee_nmi = options.orbit_perigee_nmi;
  inputs.constants = &nominal.mission->constants;
  inputs.nominal = nominal;
  inputs.data = data.get();
  inputs.linear = linear.get();
  inputs.samples = &samples;
  const MonteCarloSummary summary = summarize_monte_carlo(inputs);

  // Every output is made in memory and checked before any is written; stdout comes last.
  std::vector<DrawnImage> images;
  std::string error;
  if (!options.plots_dir.empty()) {
    if (!prepare_output_directory(options.plots_dir, &error) ||
        !draw_figures(monte_carlo_figures(inputs, summary), options.gnuplot, &images, &error)) {
      return fail(err, kExitFailure, error);
    }
  }
  if (!options.csv_path.empty()) {
    const bool written = write_file_atomically(
        options.csv_path,
        [&](std::ostream& csv) {
          write_monte_carlo_csv(csv, inputs, summary);
          return static_cast<bool>(csv);
        },
        &error);
    if (!written) return fail(err, kExitFailure, error);
  }
  if (!images.empty() && !write_drawn_images(options.plots_dir, images, nullptr, &error)) {
    return fail(err, kExitFailure, error);
  }
  if (options.json) {
    out << monte_carlo_json(inputs, summary).dump(1) << '\n';
  } else {
    write_monte_carlo_listing(out, inputs, summary);
  }
  return kExitOk;
}

}  // namespace tolip::ground

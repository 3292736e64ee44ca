// `tolip optimize` on a card deck of several cases: the cases run in order, the listing holds each,
// --json prints an array of one document per case (a one-case deck still one object), --csv one
// file per case, and the exit code is non-zero when any case fails. The deck is the bundled
// mission.dat with a second case appended by hand (only the changed words, then the case's
// optional groups again, as manual Sec. 22 stacks cases).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "support/repository_paths.hpp"

namespace tolip::test {
namespace {

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

// mission.dat split at its blank cards: [0] the case (blocks 1-40), then each optional group up to
// and including its blank card; the 999 card dropped.
struct DeckParts {
  std::string first_case;  // through the blank card ending case 1
  std::string groups;      // the optional groups with their blank cards
};

DeckParts mission_parts() {
  std::istringstream in(
      read_text_file(std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.dat"));
  DeckParts parts;
  std::string line;
  bool in_groups = false;
  while (std::getline(in, line)) {
    if (line.rfind("999", 0) == 0) break;
    (in_groups ? parts.groups : parts.first_case) += line + "\n";
    if (!in_groups && line.find_first_not_of(' ') == std::string::npos) in_groups = true;
  }
  return parts;
}

// The example with a second case: `changes` (header and data cards of the changed words), its
// blank card and the optional groups again.
std::string two_case_deck(const ScratchDirectory& scratch, const std::string& changes) {
  const DeckParts parts = mission_parts();
  const std::string path = (scratch / "two_cases.dat").string();
  std::ofstream(path) << parts.first_case << parts.groups << changes << "\n" << parts.groups << "999\n";
  return path;
}

const char* const kSecondCase =
    "  2  1 12     CASE HEADING\n"
    "SECOND CASE: INITIAL PAYLOAD 260 LB\n"
    " 15  1  1     EXTENSIONS: PAYLOAD\n"
    "        260.\n";

TEST(OptimizeCases, EveryCaseRunsInOrder) {
  ScratchDirectory scratch("optimize_cases");
  const std::string deck = two_case_deck(scratch, kSecondCase);
  const std::string csv = (scratch / "final.csv").string();

  const CommandResult json_run = run_tolip_executable({"optimize", deck, "--json", "--csv", csv});
  ASSERT_EQ(json_run.exit_code, 0) << json_run.err;
  const nlohmann::json documents = nlohmann::json::parse(json_run.out);
  ASSERT_TRUE(documents.is_array());
  ASSERT_EQ(documents.size(), 2u);
  EXPECT_EQ(documents[0]["case_heading"], "MAXIMUM PAYLOAD FROM THE CRUDE INITIAL PITCH PROGRAM");
  EXPECT_EQ(documents[1]["case_heading"], "SECOND CASE: INITIAL PAYLOAD 260 LB");
  EXPECT_EQ(documents[0]["initial_payload_lb"], 250.0);
  EXPECT_EQ(documents[1]["initial_payload_lb"], 260.0);
  for (const nlohmann::json& document : documents) {
    EXPECT_EQ(document["converged"], true);
    EXPECT_EQ(document["deck"], deck);
  }
  EXPECT_TRUE(std::filesystem::exists(scratch / "final.case1.csv"));
  EXPECT_TRUE(std::filesystem::exists(scratch / "final.case2.csv"));
  EXPECT_FALSE(std::filesystem::exists(csv));

  const CommandResult listing = run_tolip_executable({"optimize", deck});
  ASSERT_EQ(listing.exit_code, 0) << listing.err;
  EXPECT_EQ(count(listing.out, "\n OPTIMIZATION SUMMARY\n"), 2u) << "one listing per case";
  const std::size_t second = listing.out.find("SECOND CASE: INITIAL PAYLOAD 260 LB");
  ASSERT_NE(second, std::string::npos);
  EXPECT_LT(listing.out.find("MAXIMUM PAYLOAD FROM THE CRUDE INITIAL PITCH PROGRAM"), second)
      << "in case order";
}

TEST(OptimizeCases, OneCaseDeckStillPrintsOneObject) {
  const CommandResult run = run_tolip_executable(
      {"optimize", std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.dat", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(nlohmann::json::parse(run.out).is_object());
}

TEST(OptimizeCases, AFailedCaseMakesTheExitCodeNonZero) {
  ScratchDirectory scratch("optimize_cases_fail");
  // Case 2 gets a forward-run budget (data block 28 word 3) far too small to converge: the initial
  // nominal and one guidance run leave V_I - V_circ outside its deadband (3 runs already meet
  // every deadband at this payload).
  const std::string deck = two_case_deck(scratch, std::string(kSecondCase) +
                                                      " 28  3  3     CONVERGENCE DATA DA13\n"
                                                      "          2.\n");
  const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_TRUE(contains(run.err, "tolip: case 2: optimization: kGuidanceDidNotConverge: ")) << run.err;
  EXPECT_FALSE(contains(without_input_warnings(run.err), "case 1:")) << run.err;
  const nlohmann::json documents = nlohmann::json::parse(run.out);
  ASSERT_EQ(documents.size(), 2u) << "both cases are still reported";
  EXPECT_EQ(documents[0]["converged"], true);
  EXPECT_EQ(documents[1]["converged"], false);
}

}  // namespace
}  // namespace tolip::test

// The page machinery of the manual-style listings (private to ground_tools/src/report): page
// titles from data blocks 1-3, page numbers, CT1(8) lines per page. Shared by the trajectory
// listing of `simulate` and the optimization listing of `optimize`, so both number their pages
// in one sequence and the final trajectory prints exactly as `simulate` prints it.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "tolip/mission/mission.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground::report_detail {

// Writes lines and starts a new page (title block and, on trajectory pages, the column headings)
// when one is full.
class Pager {
 public:
  // `listing`: the deck's page titles (data blocks 1-3) and layout (data block 10 word 8); null:
  // blank titles and the nominal 54 lines.
  Pager(std::ostream& out, const DeckListingOptions* listing);

  // Starts a page of the given kind; `columns` adds the trajectory column headings (with
  // all_columns set, the third line group too).
  void new_page(const std::string& section, bool columns);
  void set_all_columns(bool all) { all_columns_ = all; }

  // Makes sure `count` lines fit on this page (starting a new page of the same kind if not).
  void reserve(int count);

  // Whether `count` more lines fit on the page in progress (false before the first page).
  bool fits(int count) const { return page_ > 0 && line_ + count <= lines_per_page_; }

  // One line, trailing blanks removed.
  void emit(const std::string& text);

 private:
  std::ostream& out_;
  int lines_per_page_ = 54;
  int page_ = 0;
  int line_ = 0;
  bool columns_ = false;
  bool all_columns_ = false;
  std::string section_;
  std::string title_, heading_, date_;
};

// The pages of write_trajectory_listing (FINAL TRAJECTORY, then TERMINAL CONDITIONS with the stage
// events, terminal conditions and orbit elements), continuing the pager's page numbers.
void write_trajectory_pages(Pager& pager, const SimulationReport& report);

// The constraint table (desired, achieved, error, tolerance in data block 19 units, angles also in
// deg, MET) under `heading`; shared by optimize's summary and simulate's terminal conditions.
void write_constraint_table(Pager& pager, const std::vector<ConstraintSummary>& constraints,
                            const std::string& heading);

}  // namespace tolip::ground::report_detail

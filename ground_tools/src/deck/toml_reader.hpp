// Private helpers of the TOML deck reader (ground_tools/src/deck/).
//
// A Section wraps one TOML table: every accessor names the key, the manual data block and the
// unit, records the key as known (for typo protection) and the line where it was found (for
// messages about faults found later by validate_mission), and throws DeckFailure with a complete
// DeckError on any fault. finish() rejects keys nobody asked for. The public entry points catch
// DeckFailure; nothing escapes load_toml_deck()/parse_toml_deck().
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "field_description.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/deck_extras.hpp"

namespace tolip::ground::deck_detail {

struct DeckFailure {
  DeckError error;
};

// One key the reader accepts in a table it read (the reader's own schema: every key a section
// asked for, present in the deck or not), with the data block the section names in its messages.
struct AcceptedKey {
  std::string path;  // "stage.1.duration_s", "dispersion[3].thrust.time_s"
  int data_block = 0;
  bool present = false;  // given in the deck read
};

// Per-deck context: the file name for messages and the line of every key path read.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(int line, int data_block, const std::string& field,
                         const std::string& message) const;

  void remember(const std::string& path, int line) {
    if (line > 0) lines_[path] = line;
  }
  // Line of a key path, or of its closest recorded parent; 0 when unknown.
  int line_of(const std::string& path) const;
  const std::string& file() const { return file_; }

  // When set, every section's finish() adds the keys it accepts (deck_schema.hpp).
  void record_accepted_keys(std::vector<AcceptedKey>* keys) { accepted_ = keys; }
  std::vector<AcceptedKey>* accepted_keys() const { return accepted_; }

 private:
  std::string file_;
  std::map<std::string, int> lines_;
  std::vector<AcceptedKey>* accepted_ = nullptr;
};

int line_of_node(const toml::node& node);
std::string describe_type(const toml::node& node);
std::string format_number(double value);

// Deck-side table: abscissae and ordinates with the line of every abscissa (for messages).
struct ReadTable {
  std::vector<double> x;
  std::vector<double> y;
  int line = 0;
};

class Section {
 public:
  Section(Reader* reader, const toml::table* table, std::string path, int data_block);

  const std::string& path() const { return path_; }
  int line() const { return line_; }
  int data_block() const { return data_block_; }
  Reader& reader() const { return *reader_; }
  std::string key_path(std::string_view key) const;
  const toml::table& table() const { return *table_; }

  // True when the key is present (and marks it known).
  bool has(std::string_view key);
  const toml::node* node(std::string_view key);

  [[noreturn]] void fail(int data_block, const std::string& field, const std::string& message) const;
  [[noreturn]] void fail_at(std::string_view key, int data_block, const std::string& message);
  [[noreturn]] void missing(std::string_view key, int data_block, const std::string& what);

  // Numbers: TOML integers or floats, finite. `what` describes the quantity and its unit for
  // messages ("stage duration in s").
  double number(std::string_view key, int data_block, const std::string& what);
  std::optional<double> optional_number(std::string_view key, int data_block, const std::string& what);
  double number_or(std::string_view key, int data_block, const std::string& what, double fallback);

  int integer(std::string_view key, int data_block, const std::string& what);
  std::optional<int> optional_integer(std::string_view key, int data_block, const std::string& what);

  // A 0/1 option: true/false or the integers 0/1.
  std::optional<int> optional_flag(std::string_view key, int data_block, const std::string& what);

  std::optional<std::string> optional_text(std::string_view key, int data_block, const std::string& what,
                                           std::size_t max_length);

  // Arrays of numbers / integers; `exact_size` > 0 demands that many elements.
  std::vector<double> numbers(std::string_view key, int data_block, const std::string& what,
                              int exact_size = 0);
  std::optional<std::vector<double>> optional_numbers(std::string_view key, int data_block,
                                                      const std::string& what, int exact_size = 0);
  std::vector<int> integers(std::string_view key, int data_block, const std::string& what);
  int element_line(std::string_view key, std::size_t index) const;

  // Sub-tables (a [header] table or an inline table).
  Section table(std::string_view key, int data_block, const std::string& what);
  std::optional<Section> optional_table(std::string_view key, int data_block);
  // An array of tables ([[key]]); empty when absent.
  std::vector<Section> array_of_tables(std::string_view key, int data_block);

  // Reads this section's x and y arrays as a table: equal lengths, at least min_points points,
  // strictly increasing x. x_what / y_what name the quantities and units for messages.
  // restarts_at_zero: an x of 0 may also start a new increasing run (the stacked stage 4, coast
  // and stage 5 tables of codes 7-8 with data block 55, manual page 22-30).
  ReadTable xy(std::string_view x_key, std::string_view y_key, int data_block, const std::string& x_what,
               const std::string& y_what, int min_points = 1, bool restarts_at_zero = false);

  // Rejects every key not asked for, naming it and listing the keys this table accepts.
  void finish();

 private:
  void mark(std::string_view key);

  Reader* reader_;
  const toml::table* table_;
  std::string path_;
  int data_block_;
  int line_;
  std::vector<std::string> known_;
};

// Table helpers shared by the mission and extras readers.
DeckTable to_deck_table(const ReadTable& table, double y_scale = 1.0);

// Reads one described field (field_description.hpp) for stage `code` (0 when not stage-coded) from
// `section` into `target`: present or not as its Presence says (required_when asks `options_of`),
// its range, its conversion to core units, its default when absent.
void read_field(Section& section, const FieldDescription& field, const FieldTarget& target,
                const Mission& options_of, int code = 0);
// Every described field of the TOML table `section_path` ("stage.{n}" fields with their code).
void read_fields(Section& section, const std::string& section_path, const FieldTarget& target,
                 const Mission& options_of, int code = 0);

// Reads a TOML deck (as parse_toml_deck) and lists every key of every table the reader read: the
// reader's own schema, for the input walker (tests/ground/input_walker_test.cpp).
bool accepted_toml_keys(const std::string& text, const std::string& path, std::vector<AcceptedKey>* keys,
                        DeckError* error);

// Readers of the deck sections (mission_sections.cpp, extras_sections.cpp).
void read_mission_sections(Section& root, Mission* mission, DeckExtras* extras);
void read_extras_sections(Section& root, Mission* mission, DeckExtras* extras);

}  // namespace tolip::ground::deck_detail

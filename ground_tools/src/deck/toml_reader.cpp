// Section and Reader: typed, located access to a TOML deck (toml_reader.hpp).
#include "toml_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace tolip::ground::deck_detail {

void Reader::fail(int line, int data_block, const std::string& field, const std::string& message) const {
  DeckFailure failure;
  failure.error.file = file_;
  failure.error.line = line;
  failure.error.data_block = data_block;
  failure.error.field = field;
  failure.error.message = message;
  throw failure;
}

int Reader::line_of(const std::string& path) const {
  std::string probe = path;
  while (!probe.empty()) {
    const auto it = lines_.find(probe);
    if (it != lines_.end()) return it->second;
    const std::size_t cut = probe.find_last_of(".[");
    if (cut == std::string::npos) break;
    probe.resize(cut);
  }
  return 0;
}

int line_of_node(const toml::node& node) {
  const int line = static_cast<int>(node.source().begin.line);
  if (line > 0) return line;
  // Tables created implicitly by a dotted header ([stage.1.thrust] creates "stage" and "stage.1")
  // have no source of their own: use their first child's.
  if (const toml::table* table = node.as_table()) {
    int best = 0;
    for (auto&& [key, value] : *table) {
      const int child = line_of_node(value);
      if (child > 0 && (best == 0 || child < best)) best = child;
    }
    return best;
  }
  return 0;
}

std::string describe_type(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

std::string format_number(double value) {
  // Shortest text that reads back to the same double (what the deck would hold).
  char buffer[64];
  const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  if (result.ec != std::errc()) return "?";
  return std::string(buffer, result.ptr);
}

Section::Section(Reader* reader, const toml::table* table, std::string path, int data_block)
    : reader_(reader), table_(table), path_(std::move(path)), data_block_(data_block),
      line_(line_of_node(*table)) {
  reader_->remember(path_, line_);
}

std::string Section::key_path(std::string_view key) const {
  if (path_.empty()) return std::string(key);
  return path_ + "." + std::string(key);
}

void Section::mark(std::string_view key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
}

bool Section::has(std::string_view key) { return node(key) != nullptr; }

const toml::node* Section::node(std::string_view key) {
  mark(key);
  const toml::node* found = table_->get(key);
  if (found != nullptr) reader_->remember(key_path(key), line_of_node(*found));
  return found;
}

void Section::fail(int data_block, const std::string& field, const std::string& message) const {
  reader_->fail(reader_->line_of(field) > 0 ? reader_->line_of(field) : line_, data_block, field, message);
}

void Section::fail_at(std::string_view key, int data_block, const std::string& message) {
  const toml::node* found = table_->get(key);
  const int line = found != nullptr ? line_of_node(*found) : line_;
  reader_->fail(line, data_block, key_path(key), message);
}

namespace {

// Levenshtein distance, to point at a misspelt key when a required one is missing.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

void Section::missing(std::string_view key, int data_block, const std::string& what) {
  std::string where = path_.empty() ? std::string("the top level") : "[" + path_ + "]";
  std::string hint;
  for (auto&& [present, value] : *table_) {
    const std::string_view name = present.str();
    if (std::find(known_.begin(), known_.end(), name) != known_.end()) continue;
    if (edit_distance(name, key) <= 2 || name.substr(0, name.rfind('_')) == key.substr(0, key.rfind('_'))) {
      hint = "; found unknown key '" + std::string(name) + "' (misspelt, or a different unit?)";
      break;
    }
  }
  reader_->fail(line_, data_block, key_path(key),
                "missing required key '" + std::string(key) + "' in " + where + ": expected " + what + hint);
}

namespace {

bool as_double(const toml::node& node, double* value) {
  if (const auto* integer = node.as_integer()) {
    *value = static_cast<double>(integer->get());
    return true;
  }
  if (const auto* floating = node.as_floating_point()) {
    *value = floating->get();
    return true;
  }
  return false;
}

}  // namespace

std::optional<double> Section::optional_number(std::string_view key, int data_block,
                                               const std::string& what) {
  const toml::node* found = node(key);
  if (found == nullptr) return std::nullopt;
  double value = 0.0;
  if (!as_double(*found, &value)) {
    fail_at(key, data_block, "expected a number (" + what + "), got " + describe_type(*found));
  }
  if (!std::isfinite(value)) {
    fail_at(key, data_block, "expected a finite number (" + what + "), got " + format_number(value));
  }
  return value;
}

double Section::number(std::string_view key, int data_block, const std::string& what) {
  const std::optional<double> value = optional_number(key, data_block, what);
  if (!value) missing(key, data_block, "a number (" + what + ")");
  return *value;
}

double Section::number_or(std::string_view key, int data_block, const std::string& what, double fallback) {
  return optional_number(key, data_block, what).value_or(fallback);
}

std::optional<int> Section::optional_integer(std::string_view key, int data_block, const std::string& what) {
  const toml::node* found = node(key);
  if (found == nullptr) return std::nullopt;
  const auto* integer = found->as_integer();
  if (integer == nullptr) {
    fail_at(key, data_block, "expected an integer (" + what + "), got " + describe_type(*found));
  }
  const std::int64_t value = integer->get();
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
    fail_at(key, data_block, "integer out of range (" + what + ")");
  }
  return static_cast<int>(value);
}

int Section::integer(std::string_view key, int data_block, const std::string& what) {
  const std::optional<int> value = optional_integer(key, data_block, what);
  if (!value) missing(key, data_block, "an integer (" + what + ")");
  return *value;
}

std::optional<int> Section::optional_flag(std::string_view key, int data_block, const std::string& what) {
  const toml::node* found = node(key);
  if (found == nullptr) return std::nullopt;
  if (const auto* boolean = found->as_boolean()) return boolean->get() ? 1 : 0;
  if (const auto* integer = found->as_integer()) {
    if (integer->get() == 0 || integer->get() == 1) return static_cast<int>(integer->get());
    fail_at(key, data_block,
            "expected true/false or 0/1 (" + what + "), got " + std::to_string(integer->get()));
  }
  fail_at(key, data_block, "expected true/false or 0/1 (" + what + "), got " + describe_type(*found));
}

std::optional<std::string> Section::optional_text(std::string_view key, int data_block,
                                                  const std::string& what, std::size_t max_length) {
  const toml::node* found = node(key);
  if (found == nullptr) return std::nullopt;
  const auto* text = found->as_string();
  if (text == nullptr)
    fail_at(key, data_block, "expected a string (" + what + "), got " + describe_type(*found));
  const std::string& value = text->get();
  if (value.size() > max_length) {
    fail_at(key, data_block,
            "text too long (" + std::to_string(value.size()) + " characters): " + what + " holds at most " +
                std::to_string(max_length) + " characters");
  }
  for (char c : value) {
    if (c == '\n' || c == '\r' || c == '\t') {
      fail_at(key, data_block, "expected one line of text (" + what + "), without tabs or line breaks");
    }
  }
  return value;
}

int Section::element_line(std::string_view key, std::size_t index) const {
  const toml::node* found = table_->get(key);
  if (found == nullptr) return line_;
  if (const toml::array* array = found->as_array()) {
    if (index < array->size()) {
      const int line = line_of_node(*array->get(index));
      if (line > 0) return line;
    }
  }
  return line_of_node(*found);
}

std::optional<std::vector<double>> Section::optional_numbers(std::string_view key, int data_block,
                                                             const std::string& what, int exact_size) {
  const toml::node* found = node(key);
  if (found == nullptr) return std::nullopt;
  const toml::array* array = found->as_array();
  if (array == nullptr) {
    fail_at(key, data_block, "expected an array of numbers (" + what + "), got " + describe_type(*found));
  }
  if (exact_size > 0 && static_cast<int>(array->size()) != exact_size) {
    fail_at(key, data_block,
            "expected exactly " + std::to_string(exact_size) + " numbers (" + what + "), got " +
                std::to_string(array->size()));
  }
  std::vector<double> values;
  values.reserve(array->size());
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    double value = 0.0;
    const std::string element_path = key_path(key) + "[" + std::to_string(i) + "]";
    if (!as_double(element, &value)) {
      reader_->fail(element_line(key, i), data_block, element_path,
                    "expected a number (" + what + "), got " + describe_type(element));
    }
    if (!std::isfinite(value)) {
      reader_->fail(element_line(key, i), data_block, element_path,
                    "expected a finite number (" + what + "), got " + format_number(value));
    }
    values.push_back(value);
  }
  return values;
}

std::vector<double> Section::numbers(std::string_view key, int data_block, const std::string& what,
                                     int exact_size) {
  std::optional<std::vector<double>> values = optional_numbers(key, data_block, what, exact_size);
  if (!values) missing(key, data_block, "an array of numbers (" + what + ")");
  return std::move(*values);
}

std::vector<int> Section::integers(std::string_view key, int data_block, const std::string& what) {
  const toml::node* found = node(key);
  if (found == nullptr) missing(key, data_block, "an array of integers (" + what + ")");
  const toml::array* array = found->as_array();
  if (array == nullptr) {
    fail_at(key, data_block, "expected an array of integers (" + what + "), got " + describe_type(*found));
  }
  std::vector<int> values;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    const auto* integer = element.as_integer();
    if (integer == nullptr || integer->get() < std::numeric_limits<int>::min() ||
        integer->get() > std::numeric_limits<int>::max()) {
      reader_->fail(element_line(key, i), data_block, key_path(key) + "[" + std::to_string(i) + "]",
                    "expected an integer (" + what + "), got " + describe_type(element));
    }
    values.push_back(static_cast<int>(integer->get()));
  }
  return values;
}

std::optional<Section> Section::optional_table(std::string_view key, int data_block) {
  const toml::node* found = node(key);
  if (found == nullptr) return std::nullopt;
  const toml::table* sub = found->as_table();
  if (sub == nullptr) {
    fail_at(key, data_block,
            "expected a table ([" + key_path(key) + "] or an inline table), got " + describe_type(*found));
  }
  return Section(reader_, sub, key_path(key), data_block);
}

Section Section::table(std::string_view key, int data_block, const std::string& what) {
  std::optional<Section> sub = optional_table(key, data_block);
  if (!sub) {
    reader_->fail(path_.empty() ? 0 : line_, data_block, key_path(key),
                  "missing required table [" + key_path(key) + "]: expected " + what);
  }
  return *sub;
}

std::vector<Section> Section::array_of_tables(std::string_view key, int data_block) {
  std::vector<Section> sections;
  const toml::node* found = node(key);
  if (found == nullptr) return sections;
  const toml::array* array = found->as_array();
  if (array == nullptr) {
    fail_at(key, data_block,
            "expected an array of tables ([[" + key_path(key) + "]]), got " + describe_type(*found));
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    const std::string element_path = key_path(key) + "[" + std::to_string(i) + "]";
    const toml::table* sub = element.as_table();
    if (sub == nullptr) {
      reader_->fail(element_line(key, i), data_block, element_path,
                    "expected a table ([[" + key_path(key) + "]] entry), got " + describe_type(element));
    }
    sections.emplace_back(reader_, sub, element_path, data_block);
  }
  return sections;
}

ReadTable Section::xy(std::string_view x_key, std::string_view y_key, int data_block,
                      const std::string& x_what, const std::string& y_what, int min_points,
                      bool restarts_at_zero) {
  ReadTable result;
  result.line = line_;
  result.x = numbers(x_key, data_block, x_what);
  result.y = numbers(y_key, data_block, y_what);
  if (result.x.size() != result.y.size()) {
    fail_at(y_key, data_block,
            "'" + std::string(x_key) + "' has " + std::to_string(result.x.size()) + " values but '" +
                std::string(y_key) + "' has " + std::to_string(result.y.size()) + "; expected one " + y_what +
                " per " + x_what);
  }
  if (static_cast<int>(result.x.size()) < min_points) {
    fail_at(x_key, data_block,
            "expected at least " + std::to_string(min_points) + " point" + (min_points == 1 ? "" : "s") +
                " in the table, got " + std::to_string(result.x.size()));
  }
  for (std::size_t i = 1; i < result.x.size(); ++i) {
    if (restarts_at_zero && result.x[i] == 0.0) continue;  // a new run (the core splits it)
    if (!(result.x[i] > result.x[i - 1])) {
      reader_->fail(element_line(x_key, i), data_block, key_path(x_key) + "[" + std::to_string(i) + "]",
                    "table not monotonic: " + std::string(x_key) + "[" + std::to_string(i) +
                        "] = " + format_number(result.x[i]) + " is not greater than " + std::string(x_key) +
                        "[" + std::to_string(i - 1) + "] = " + format_number(result.x[i - 1]) +
                        "; expected strictly increasing " + x_what);
    }
  }
  return result;
}

void Section::finish() {
  if (std::vector<AcceptedKey>* accepted = reader_->accepted_keys()) {
    for (const std::string& known : known_)
      accepted->push_back(AcceptedKey{key_path(known), data_block_, table_->get(known) != nullptr});
  }
  for (auto&& [key, value] : *table_) {
    const std::string_view name = key.str();
    if (std::find(known_.begin(), known_.end(), name) != known_.end()) continue;
    std::string expected;
    for (const std::string& known : known_) {
      if (!expected.empty()) expected += ", ";
      expected += known;
    }
    int line = static_cast<int>(key.source().begin.line);
    if (line == 0) line = line_of_node(value);
    const std::string where = path_.empty() ? std::string("at the top level") : "in [" + path_ + "]";
    reader_->fail(line, data_block_, key_path(name),
                  "unknown key '" + std::string(name) + "' " + where +
                      (expected.empty() ? std::string("; this table takes no keys")
                                        : "; expected one of: " + expected));
  }
}

DeckTable to_deck_table(const ReadTable& table, double y_scale) {
  DeckTable out;
  out.x = table.x;
  out.y.reserve(table.y.size());
  for (double y : table.y) out.y.push_back(y * y_scale);
  return out;
}

// ---- described fields ---------------------------------------------------------------------------

namespace {

void check_range(Section& section, const FieldDescription& field, const std::string& what, double value) {
  const std::string key = field.key;
  const int block = message_block(field);
  switch (field.range) {
    case Range::kAny:
    case Range::kFlag: return;
    case Range::kPositive:
      if (!(value > 0.0)) {
        section.fail_at(key, block, "expected a positive value (" + what + "), got " + format_number(value));
      }
      return;
    case Range::kAtLeastOne:
      if (!(value >= 1.0)) {
        if (field.count > 1) section.fail_at(key, block, "every value must be at least 1 (" + what + ")");
        section.fail_at(key, block,
                        "expected a positive integer (" + what + "), got " + format_number(value));
      }
      return;
    case Range::kChoice:
      if (value < field.low || value > field.high) {
        section.fail_at(key, block,
                        "value " + format_number(value) + " out of range: expected " +
                            std::to_string(field.low) + "-" + std::to_string(field.high) + " (" + what + ")");
      }
      return;
  }
}

}  // namespace

void read_field(Section& section, const FieldDescription& field, const FieldTarget& target,
                const Mission& options_of, int code) {
  const std::string what = what_of(field, code);
  const std::string key = field.key;
  const int block = message_block(field);
  const bool required = field.presence == Presence::kRequired ||
                        (field.presence == Presence::kRequiredWhen && field.required_when(options_of)) ||
                        (field.presence == Presence::kRequiredForPowered && is_powered_stage(code));
  std::vector<double> values;
  if (field.count == 1) {
    std::optional<double> value;
    if (field.range == Range::kFlag) {
      if (const std::optional<int> flag = section.optional_flag(key, block, what)) value = *flag;
    } else if (field.integer) {
      if (required) value = section.integer(key, block, what);
      else if (const std::optional<int> read = section.optional_integer(key, block, what)) value = *read;
    } else {
      value = required ? std::optional<double>(section.number(key, block, what))
                       : section.optional_number(key, block, what);
    }
    if (value) values.push_back(*value);
  } else if (required || section.has(key)) {
    if (field.integer) {
      const std::vector<int> read = section.integers(key, block, what);
      if (static_cast<int>(read.size()) != field.count) {
        section.fail_at(key, block,
                        "expected " + std::to_string(field.count) + " integers (" + what + "), got " +
                            std::to_string(static_cast<int>(read.size())));
      }
      values.assign(read.begin(), read.end());
    } else {
      values = section.numbers(key, block, what, field.count);
    }
  }
  if (values.empty()) {
    if (!field.has_default) return;  // the target keeps its value (the core's nominal one)
    values.assign(static_cast<std::size_t>(field.count), field.default_value);
  } else {
    for (double value : values) check_range(section, field, what, value);
  }
  for (int i = 0; i < field.count; ++i) {
    set_field_value(field, target, code, i, to_core(field.conversion, values[static_cast<std::size_t>(i)]));
  }
}

void read_fields(Section& section, const std::string& section_path, const FieldTarget& target,
                 const Mission& options_of, int code) {
  for (const FieldDescription& field : field_descriptions()) {
    // The cheap tests first: section_of builds a string.
    if ((field.stage_coding == StageCoding::kNone) == (code == 0) && applies_to_stage(field, code) &&
        section_of(field, code) == section_path) {
      read_field(section, field, target, options_of, code);
    }
  }
}

}  // namespace tolip::ground::deck_detail

// Per-case output names and message prefixes (case_output.hpp).
#include "case_output.hpp"

#include <algorithm>

#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {

std::string case_file_path(const std::string& path, int case_number, std::size_t cases) {
  if (cases <= 1) return path;
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  const std::string tag = ".case" + std::to_string(case_number);
  // No extension: no dot, a dot in a directory name, or a leading dot of a hidden file's name.
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) || dot == 0 ||
      (slash != std::string::npos && dot == slash + 1)) {
    return path + tag;
  }
  return path.substr(0, dot) + tag + path.substr(dot);
}

bool csv_spares_the_deck(const std::string& csv_path, const std::string& deck_path, std::size_t cases,
                         std::string* error) {
  if (csv_path.empty()) return true;
  for (std::size_t number = 1; number <= std::max<std::size_t>(cases, 1); ++number) {
    const std::string name = case_file_path(csv_path, static_cast<int>(number), cases);
    if (names_same_file(name, deck_path)) {
      *error = "the --csv file '" + name + "' is the input deck '" + deck_path +
               "': writing it would destroy the deck; name another file";
      return false;
    }
  }
  return true;
}

std::string case_message_prefix(int case_number, std::size_t cases) {
  return cases > 1 ? "case " + std::to_string(case_number) + ": " : "";
}

void write_case_outputs(std::ostream& out, std::ostream& err, bool json,
                        const nlohmann::ordered_json& documents, const std::string& listing,
                        const std::vector<std::string>& failures) {
  if (json) {
    out << dump_json(documents.size() == 1 ? documents[0] : documents);
  } else {
    out << listing;
  }
  out.flush();
  for (const std::string& failure : failures) err << failure;
}

}  // namespace tolip::ground

// Ground side of the guidance table image (docs/table-format.md): building the table contents from
// a case, the C header for images linked into flight software, and the engineering-unit listing of
// `tolip inspect`.
//
// The segments come from the linearized pitch program (Sec. 6, 10) when one is given: each segment
// as linearize_pitch_program left it (stage, start in stage time, theta at the start, rate), then a
// hold segment (rate 0) at the program's end, which the linearization flies after it (the coast
// before the spun stages). Without one (a deck without IP(7)), the interim source is the data
// block 40 pitch table of the deck. Every table interval that starts in a stage that flies the pitch
// program (stages 1-3 and coasts 6-8; stages 4, 5 and coasts 9, 10 unless IP(9) spins them:
// is_segment_stage) becomes one segment (stage, start in stage time, theta at the start, rate of
// the interval); a hold segment (rate 0) is appended at the last node when that node still lies in
// such a stage, and one is prepended at the end of the lift-off when the table
// starts after it. Intervals that end by the end of the lift-off are dropped (the executor holds
// 90 deg there). docs/table-format.md, "Contents", gives every other source.
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tolip/mission/mission.hpp"
#include "tolip/optimizer/linearization.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/deck_extras.hpp"

namespace tolip::ground {

// Maximum deflection when the deck gives no data block 45 word 11: 10 deg.
inline constexpr double kDefaultMaxDeflectionRad = 10.0 * kDegToRad;
// The image's deflection limit: data block 45 word 11 when the deck has [hardover], else the default.
double table_max_deflection_rad(const DeckExtras& extras);
// Section the C header places the image in (the flight image's linker script maps it).
inline constexpr const char* kTableLinkerSection = ".tolip_table";
inline constexpr const char* kDefaultTableSymbol = "tolip_pitch_table";

struct TableBuildOptions {
  std::string mission_id;           // empty: default_mission_id()
  std::int64_t created_unix_s = 0;  // creation stamp
};

// The default mission identifier: the case title (data block 1) with runs of blanks collapsed,
// cut to 32 characters, non-printable characters replaced by '?'; "TOLIP CASE" when empty.
std::string default_mission_id(const DeckListingOptions& listing);

// Builds the table from a validated Mission, its DeckExtras and PreparedCase, with the segments of
// `linearized` (null: data block 40, see above). With a linearized program, `mission` and
// `prepared` must be the case it was linearized for (optimized spun attitudes and coasts). Returns
// false and sets *error (a sentence naming the data block) on any fault; the table then fails
// validate_guidance_table() or the case cannot be represented.
bool build_guidance_table(const Mission& mission, const DeckExtras& extras, const PreparedCase& prepared,
                          const LinearProgram* linearized, const TableBuildOptions& options,
                          GuidanceTable* table, std::string* error);

// The C header holding `image` as a const array named `symbol`, placed in kTableLinkerSection.
// `origin` is a comment line naming the source (deck path).
std::string table_image_c_header(const std::uint8_t* image, std::size_t size, const std::string& symbol,
                                 const std::string& origin);

// Engineering-unit listing of a valid image (degrees, deg/s, s, UTC stamp), as `tolip inspect`
// prints it.
void write_table_listing(std::ostream& out, const GuidanceTable& table, std::uint32_t crc);

// The same contents as one JSON document (degrees, deg/s, s; schema in docs/cli.md, 'tolip
// inspect --json').
nlohmann::ordered_json table_json(const GuidanceTable& table, std::uint32_t crc, std::size_t image_size);

// Reads a table image file into bytes, never more than kTableImageSize (the format's fixed size;
// read_file_capped, capped_read.hpp). Returns false and sets *error, naming the file, when it
// cannot be opened, is a directory, is larger than an image or cannot be read.
bool read_table_image_file(const std::string& path, std::vector<std::uint8_t>* bytes, std::string* error);

}  // namespace tolip::ground

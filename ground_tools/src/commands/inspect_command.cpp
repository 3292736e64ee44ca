// `tolip inspect`: validate a guidance table image with the flight-side decoder and print it in
// engineering units (docs/table-format.md, docs/cli.md).
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "tolip/table/table_image.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/guidance_table.hpp"
#include "tolip_ground/report.hpp"
#include "tolip_ground/table_commands.hpp"

namespace tolip::ground {

int run_inspect_command(const InspectCommandOptions& options, std::ostream& out, std::ostream& err) {
  std::vector<std::uint8_t> bytes;
  std::string read_error;
  if (!read_table_image_file(options.image_path, &bytes, &read_error)) {
    err << "tolip: " << read_error << '\n';
    return kExitBadInput;
  }
  auto table = std::make_unique<GuidanceTable>();
  const Status status = decode_table_image(bytes.data(), bytes.size(), table.get());
  if (!ok(status)) {
    err << "tolip: " << options.image_path << ": invalid guidance table image (" << bytes.size()
        << " bytes): " << status_name(status) << ": " << status_message(status) << '\n';
    return kExitBadInput;
  }
  if (options.json) {
    out << dump_json(table_json(*table, stored_table_crc(bytes.data()), bytes.size()));
    return kExitOk;
  }
  out << options.image_path << '\n';
  write_table_listing(out, *table, stored_table_crc(bytes.data()));
  return kExitOk;
}

}  // namespace tolip::ground

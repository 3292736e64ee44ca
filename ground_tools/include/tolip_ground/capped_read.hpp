// Reading an input file whole, with a cap on its size: the one reader of every input of the
// `tolip` program (decks, table images, result JSON). A file is never read past its cap, so an
// endless or huge input (`/dev/zero`, a FIFO fed forever, a runaway file) is refused with a
// message instead of filling the memory. docs/cli.md, "Input limits", lists the caps.
#pragma once

#include <cstddef>
#include <string>

namespace tolip::ground {

// The caps (bytes). A table image has the fixed size of its format (kTableImageSize, 1580 bytes);
// the others are generous documented limits, far above any real input.
inline constexpr std::size_t kMaxDeckFileBytes = std::size_t{8} << 20;     // 8 MiB: ~100,000 cards
inline constexpr std::size_t kMaxResultFileBytes = std::size_t{64} << 20;  // 64 MiB: ~240 cases of Scout JSON

// Reads the file at `path` into *contents, at most `max_bytes` bytes. `kind` names the file in
// messages ("deck file", "guidance table image", "result file"). Returns false and sets *error
// to a message without the path (callers put the path in front), one of
//   "cannot open the <kind>: <system error>"
//   "is a directory, not a <kind>"
//   "more than <max_bytes> bytes: a <kind> is at most <max_bytes> bytes (docs/cli.md, Input limits)"
//   "cannot read the <kind>: <system error>"
// Regular files, FIFOs and character devices are read the same way; a regular file larger than
// the cap is refused from its size without reading it.
bool read_file_capped(const std::string& path, std::size_t max_bytes, const std::string& kind,
                      std::string* contents, std::string* error);

}  // namespace tolip::ground

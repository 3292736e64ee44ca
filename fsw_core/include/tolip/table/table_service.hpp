// Flight-side table service for the guidance table image, in the style of flight table services:
// two buffers, one active and one inactive. An uploaded image is copied into the inactive buffer
// (stage), checked and decoded there (validate), and only then made active by one atomic store of
// the active index (commit). A rejected image leaves the active table untouched, and the status
// names the cause (docs/table-format.md, "Loading").
//
// Storage is inside the object (two raw images and two decoded tables, about 3.3 KiB): a flight
// build keeps the service in static storage. Nothing allocates; every loop is bounded by the
// fixed image size or the segment capacity.
//
// Concurrency: one writer (the task that loads tables) and any number of readers (the guidance
// minor cycle). Readers call active() once per cycle and use that table for the whole cycle. The
// writer only ever touches the inactive buffer; a load must not be started while a reader may
// still be using the table that the previous commit made inactive (in the minor-cycle design the
// loader runs between cycles, which guarantees it).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>

#include "tolip/core/status.hpp"
#include "tolip/table/table_image.hpp"

namespace tolip {

class GuidanceTableService {
 public:
  GuidanceTableService() = default;
  GuidanceTableService(const GuidanceTableService&) = delete;
  GuidanceTableService& operator=(const GuidanceTableService&) = delete;

  // stage + validate_staged + commit. On any failure the active table is unchanged.
  Status load(const std::uint8_t* image, std::size_t size);

  // Copies `size` bytes into the inactive buffer. Fails (kTableImageTruncated /
  // kTableImageSizeMismatch) when size is not the format's fixed size; then nothing is staged.
  Status stage(const std::uint8_t* image, std::size_t size);
  // Checks and decodes the staged image in the inactive buffer (decode_table_image).
  Status validate_staged();
  // Makes the validated inactive buffer the active one (one atomic store).
  Status commit();

  bool has_active_table() const { return active_index_.load(std::memory_order_acquire) >= 0; }
  // The table in force, or nullptr when none was ever committed.
  const GuidanceTable* active() const;
  // The raw image in force (kTableImageSize bytes), or nullptr.
  const std::uint8_t* active_image() const;
  // CRC of the image in force (0 when none).
  std::uint32_t active_crc() const;
  // Number of successful commits since construction.
  std::uint32_t commit_count() const { return commit_count_; }

 private:
  enum class BufferState : std::uint8_t { kEmpty, kStaged, kValidated };

  int inactive_index() const;

  std::uint8_t raw_[2][kTableImageSize] = {};
  GuidanceTable tables_[2];
  BufferState state_[2] = {BufferState::kEmpty, BufferState::kEmpty};
  std::atomic<int> active_index_{-1};
  std::uint32_t commit_count_ = 0;
};

}  // namespace tolip

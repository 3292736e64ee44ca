// Double-buffered guidance table service: stage, validate, then commit by one atomic store.
#include "tolip/table/table_service.hpp"

namespace tolip {

static_assert(std::atomic<int>::is_always_lock_free, "the active-buffer switch must be lock free");

int GuidanceTableService::inactive_index() const {
  return active_index_.load(std::memory_order_acquire) == 0 ? 1 : 0;
}

Status GuidanceTableService::stage(const std::uint8_t* image, std::size_t size) {
  const int target = inactive_index();
  state_[target] = BufferState::kEmpty;
  const Status sized = table_image_size_status(image, size);
  if (!ok(sized)) return sized;
  for (std::size_t i = 0; i < kTableImageSize; ++i) raw_[target][i] = image[i];
  state_[target] = BufferState::kStaged;
  return Status::kOk;
}

Status GuidanceTableService::validate_staged() {
  const int target = inactive_index();
  if (state_[target] == BufferState::kEmpty) return Status::kTableNotStaged;
  if (state_[target] == BufferState::kValidated) return Status::kOk;
  const Status status = decode_table_image(raw_[target], kTableImageSize, &tables_[target]);
  if (!ok(status)) {
    state_[target] = BufferState::kEmpty;
    return status;
  }
  state_[target] = BufferState::kValidated;
  return Status::kOk;
}

Status GuidanceTableService::commit() {
  const int target = inactive_index();
  if (state_[target] == BufferState::kEmpty) return Status::kTableNotStaged;
  if (state_[target] != BufferState::kValidated) return Status::kTableNotValidated;
  // The previously active buffer becomes the inactive one; its contents stay as they were until
  // the next stage() overwrites them.
  const int previous = active_index_.load(std::memory_order_acquire);
  active_index_.store(target, std::memory_order_release);
  if (previous >= 0) state_[previous] = BufferState::kEmpty;
  ++commit_count_;
  return Status::kOk;
}

Status GuidanceTableService::load(const std::uint8_t* image, std::size_t size) {
  Status status = stage(image, size);
  if (ok(status)) status = validate_staged();
  if (ok(status)) status = commit();
  return status;
}

const GuidanceTable* GuidanceTableService::active() const {
  const int index = active_index_.load(std::memory_order_acquire);
  return index >= 0 ? &tables_[index] : nullptr;
}

const std::uint8_t* GuidanceTableService::active_image() const {
  const int index = active_index_.load(std::memory_order_acquire);
  return index >= 0 ? raw_[index] : nullptr;
}

std::uint32_t GuidanceTableService::active_crc() const {
  const std::uint8_t* image = active_image();
  return image != nullptr ? stored_table_crc(image) : 0u;
}

}  // namespace tolip

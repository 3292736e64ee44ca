// write_file_atomically (tolip_ground/atomic_file.hpp): success, replacement, and that every
// failure leaves an existing file untouched and no temporary file behind.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "cli_runner.hpp"
#include "tolip_ground/atomic_file.hpp"

namespace tolip::test {
namespace {

using ground::AtomicWriteStep;
using ground::write_file_atomically;

void write_plain(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// Fault injection at one step; the hook is a plain function pointer, so the step is global.
AtomicWriteStep g_failing_step = AtomicWriteStep::kOpen;
bool fail_at_selected_step(AtomicWriteStep step) { return step == g_failing_step; }

class FaultHookGuard {
 public:
  explicit FaultHookGuard(AtomicWriteStep step) {
    g_failing_step = step;
    ground::set_atomic_write_fault_hook(&fail_at_selected_step);
  }
  ~FaultHookGuard() { ground::set_atomic_write_fault_hook(nullptr); }
};

TEST(AtomicFile, WritesANewFile) {
  ScratchDirectory scratch("atomic_new");
  const std::filesystem::path path = scratch / "table.csv";
  std::string error;
  ASSERT_TRUE(write_file_atomically(path.string(), "a,b\n1,2\n", &error)) << error;
  EXPECT_EQ(read_text_file(path), "a,b\n1,2\n");
  EXPECT_FALSE(scratch.has_temp_file());
}

TEST(AtomicFile, WritesAnEmptyFile) {
  ScratchDirectory scratch("atomic_empty");
  const std::filesystem::path path = scratch / "empty.txt";
  std::string error;
  ASSERT_TRUE(write_file_atomically(path.string(), "", &error)) << error;
  EXPECT_TRUE(std::filesystem::exists(path));
  EXPECT_EQ(std::filesystem::file_size(path), 0u);
}

TEST(AtomicFile, ReplacesAnExistingFileKeepingItsPermissions) {
  ScratchDirectory scratch("atomic_replace");
  const std::filesystem::path path = scratch / "table.csv";
  write_plain(path, "old contents that are longer than the new ones\n");
  ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
  std::string error;
  ASSERT_TRUE(write_file_atomically(path.string(), "new\n", &error)) << error;
  EXPECT_EQ(read_text_file(path), "new\n");
  struct stat info {};
  ASSERT_EQ(::stat(path.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0640u);
  EXPECT_EQ(scratch.entries().size(), 1u);
}

TEST(AtomicFile, RenderedContentsAreWritten) {
  ScratchDirectory scratch("atomic_render");
  const std::filesystem::path path = scratch / "rendered.txt";
  std::string error;
  ASSERT_TRUE(write_file_atomically(
      path.string(), [](std::ostream& out) { return static_cast<bool>(out << "x=" << 42 << '\n'); }, &error))
      << error;
  EXPECT_EQ(read_text_file(path), "x=42\n");
}

TEST(AtomicFile, TempPathIsInTheSameDirectoryAndNamesThePid) {
  const std::string temp = ground::atomic_temp_path("/some/dir/out.csv");
  EXPECT_EQ(temp, "/some/dir/out.csv.tmp." + std::to_string(static_cast<long long>(::getpid())));
}

TEST(AtomicFile, InjectedFailureAtEveryStepLeavesTheOldFileAndNoTemp) {
  for (AtomicWriteStep step : {AtomicWriteStep::kOpen, AtomicWriteStep::kWrite, AtomicWriteStep::kSync,
                               AtomicWriteStep::kClose, AtomicWriteStep::kRename}) {
    ScratchDirectory scratch("atomic_fault_" + std::to_string(static_cast<int>(step)));
    const std::filesystem::path path = scratch / "table.csv";
    write_plain(path, "precious\n");
    std::string error;
    {
      FaultHookGuard guard(step);
      EXPECT_FALSE(write_file_atomically(path.string(), "replacement\n", &error))
          << "step " << static_cast<int>(step);
    }
    EXPECT_FALSE(error.empty());
    EXPECT_EQ(read_text_file(path), "precious\n") << "step " << static_cast<int>(step);
    EXPECT_FALSE(scratch.has_temp_file()) << "step " << static_cast<int>(step);
    EXPECT_EQ(scratch.entries().size(), 1u);
  }
}

TEST(AtomicFile, InjectedFailureCreatesNoFileWhenNoneExisted) {
  ScratchDirectory scratch("atomic_fault_new");
  const std::filesystem::path path = scratch / "table.csv";
  std::string error;
  {
    FaultHookGuard guard(AtomicWriteStep::kWrite);
    EXPECT_FALSE(write_file_atomically(path.string(), "data\n", &error));
  }
  EXPECT_TRUE(scratch.entries().empty());
}

TEST(AtomicFile, RealRenameFailureLeavesTargetAndNoTemp) {
  // The target is a non-empty directory: the rename fails after the temp file was written.
  ScratchDirectory scratch("atomic_rename_dir");
  const std::filesystem::path target = scratch / "occupied";
  std::filesystem::create_directories(target);
  write_plain(target / "inside.txt", "keep me\n");
  std::string error;
  EXPECT_FALSE(write_file_atomically(target.string(), "data\n", &error));
  EXPECT_NE(error.find(target.string()), std::string::npos) << error;
  EXPECT_TRUE(std::filesystem::is_directory(target));
  EXPECT_EQ(read_text_file(target / "inside.txt"), "keep me\n");
  EXPECT_FALSE(scratch.has_temp_file());
}

TEST(AtomicFile, MissingDirectoryFailsNamingTheFile) {
  ScratchDirectory scratch("atomic_missing_dir");
  const std::filesystem::path path = scratch / "no" / "such" / "dir" / "out.csv";
  std::string error;
  EXPECT_FALSE(write_file_atomically(path.string(), "data\n", &error));
  EXPECT_NE(error.find("out.csv"), std::string::npos) << error;
}

TEST(AtomicFile, FailedRenderingWritesNothing) {
  ScratchDirectory scratch("atomic_render_fail");
  const std::filesystem::path path = scratch / "table.csv";
  write_plain(path, "precious\n");
  std::string error;
  EXPECT_FALSE(write_file_atomically(
      path.string(),
      [](std::ostream& out) {
        out << "partial";
        return false;
      },
      &error));
  EXPECT_FALSE(write_file_atomically(
      path.string(),
      [](std::ostream& out) -> bool {
        out << "partial";
        throw std::runtime_error("renderer broke");
      },
      &error));
  EXPECT_NE(error.find("renderer broke"), std::string::npos) << error;
  EXPECT_EQ(read_text_file(path), "precious\n");
  EXPECT_EQ(scratch.entries().size(), 1u);
}

}  // namespace
}  // namespace tolip::test

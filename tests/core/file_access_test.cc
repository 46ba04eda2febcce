#include "lvslam/core/file_access.h"

#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::errorMessageOf;
using testing::TempDir;

TEST(FileAccess, KindsOfPaths) {
  TempDir dir;
  dir.write("f.txt", "x");
  EXPECT_EQ(fileKind(dir.file("f.txt")), FileKind::kRegular);
  EXPECT_EQ(fileKind(dir.path().string()), FileKind::kDirectory);
  EXPECT_EQ(fileKind(dir.file("none")), FileKind::kMissing);
  EXPECT_EQ(fileKind(dir.file("f.txt/below")), FileKind::kMissing) << "a file as a folder is missing, not an error";
}

TEST(FileAccess, NameTooLongIsAnErrorNamingWhereItCameFrom) {
  TempDir dir;
  const std::string name = dir.file(std::string(300, 'n') + ".bin");
  const std::string msg = errorMessageOf([&] { fileKind(name, "lidar/times.txt:7"); });
  EXPECT_EQ(msg.rfind("lidar/times.txt:7: cannot access", 0), 0u) << msg;
  EXPECT_NE(msg.find("too long"), std::string::npos) << msg;
}

TEST(FileAccess, SymlinkLoopIsAnError) {
  TempDir dir;
  std::filesystem::create_symlink(dir.file("loop"), dir.file("loop"));
  const std::string msg = errorMessageOf([&] { fileKind(dir.file("loop")); });
  EXPECT_NE(msg.find("loop: cannot access"), std::string::npos) << msg;
  EXPECT_NE(msg.find("symbolic links"), std::string::npos) << msg;
}

TEST(FileAccess, OpenInputFileNamesWhatIsWrong) {
  TempDir dir;
  dir.write("f.txt", "hello");
  std::string text;
  openInputFile(dir.file("f.txt")) >> text;
  EXPECT_EQ(text, "hello");
  EXPECT_NE(errorMessageOf([&] { openInputFile(dir.path().string()); }).find("is a folder, not a file"),
            std::string::npos);
  const std::string msg = errorMessageOf([&] { openInputFile(dir.file("gone.txt"), "list.txt:2"); });
  EXPECT_NE(msg.find("list.txt:2: '"), std::string::npos) << msg;
  EXPECT_NE(msg.find("gone.txt' file not found"), std::string::npos) << msg;
}

TEST(FileAccess, UnreadableFileGivesTheSystemsReason) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads files without permission (checked as nobody in the fault matrix)";
  TempDir dir;
  dir.write("secret.txt", "x");
  std::filesystem::permissions(dir.file("secret.txt"), std::filesystem::perms::none);
  const std::string msg = errorMessageOf([&] { openInputFile(dir.file("secret.txt")); });
  EXPECT_NE(msg.find("Permission denied"), std::string::npos) << msg;
}

}  // namespace
}  // namespace lvslam

#include "confvis/base/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "confvis/base/error.hpp"

namespace fs = std::filesystem;
using namespace confvis;

namespace {
fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("confvis_" + name + std::to_string(getpid()));
  fs::remove_all(dir);
  return dir;
}
}  // namespace

TEST(AtomicFile, WritesIntoNewDirectoriesAndLeavesNoTemporary) {
  const fs::path dir = freshDir("atomic");
  writeTextAtomically(dir / "a" / "b.txt", "hello");
  EXPECT_EQ(readTextFile(dir / "a" / "b.txt"), "hello");
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir / "a")) ++entries;
  EXPECT_EQ(entries, 1);
  fs::remove_all(dir);
}

TEST(AtomicFile, FailedWriterKeepsOldContentsAndCleansUp) {
  const fs::path dir = freshDir("atomic_fail");
  writeTextAtomically(dir / "keep.txt", "old");
  EXPECT_THROW(writeFileAtomically(dir / "keep.txt",
                                   [](const fs::path& temp) {
                                     writeTextAtomically(temp, "partial");
                                     throw std::runtime_error("disk full");
                                   }),
               Error);
  EXPECT_EQ(readTextFile(dir / "keep.txt"), "old");
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1);
  fs::remove_all(dir);
}

TEST(AtomicFile, MissingFileNamesThePath) {
  try {
    readTextFile("/nonexistent/confvis/file.json");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::FileNotFound);
    EXPECT_NE(std::string(e.what()).find("/nonexistent/confvis/file.json"), std::string::npos);
  }
}

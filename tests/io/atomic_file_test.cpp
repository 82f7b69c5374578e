#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void expect_only(const fs::path& dir, const std::set<std::string>& names) {
  std::set<std::string> found;
  for (const auto& entry : fs::directory_iterator(dir)) found.insert(entry.path().filename());
  EXPECT_EQ(found, names);
}

TEST(AtomicFile, WritesTheWholeFileUnderItsName) {
  const fs::path dir = test::temp_dir("atomic");
  write_file_atomically(dir / "a.txt", [](std::ostream& out) { out << "one\ntwo\n"; });
  EXPECT_EQ(read_text(dir / "a.txt"), "one\ntwo\n");
  expect_only(dir, {"a.txt"});
}

TEST(AtomicFile, MissingFolderIsAnErrorNamingThePathAndLeavesNothing) {
  const fs::path dir = test::temp_dir("atomic");
  try {
    write_file_atomically(dir / "missing" / "a.txt", [](std::ostream& out) { out << "x"; });
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing/a.txt: cannot write file"), std::string::npos)
        << e.what();
  }
  expect_only(dir, {});
}

TEST(AtomicFile, ReadOnlyFolderLeavesNoPartialFile) {
  if (geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders";
  const fs::path dir = test::temp_dir("atomic");
  fs::create_directories(dir / "ro");
  fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THROW(write_file_atomically(dir / "ro" / "a.txt", [](std::ostream& out) { out << "x"; }),
               InputError);
  fs::permissions(dir / "ro", fs::perms::owner_all);
  expect_only(dir / "ro", {});
}

TEST(AtomicFile, AWriterFailingHalfwayKeepsThePreviousFileAndRemovesTheTemporary) {
  const fs::path dir = test::temp_dir("atomic");
  std::ofstream(dir / "a.txt") << "old\n";
  EXPECT_THROW(write_file_atomically(dir / "a.txt",
                                     [](std::ostream& out) {
                                       out << "half of the new";
                                       throw std::runtime_error("crash");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read_text(dir / "a.txt"), "old\n");
  expect_only(dir, {"a.txt"});
}

}  // namespace
}  // namespace slamkit

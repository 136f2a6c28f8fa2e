// Output files written whole or not at all (formats/output_file.hpp): the bytes go to a temporary file beside
// the target, renamed into place on commit; until then the target is untouched, and a file dropped or failed
// leaves nothing behind. Messages open with what the file is and name the system's reason.
#include "formats/output_file.hpp"

#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

namespace circles::formats {
namespace {

using circles::testing::TempDir;
using circles::testing::thrown;

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(output_file, writes_the_bytes_under_a_temporary_name_beside_the_target_until_commit) {
  const TempDir dir;
  const std::string target = (dir.path / "out.txt").string();
  OutputFile file(target, "report " + target);
  const std::string temp = file.temp_path();
  ASSERT_TRUE(temp.starts_with(target + ".partial-")) << temp;
  EXPECT_TRUE(std::regex_match(temp.substr(target.size()), std::regex(R"(\.partial-[A-Za-z0-9]{6})"))) << temp;
  file.write(std::string("a\0b\n", 4));
  file.write("second");
  EXPECT_EQ(dir.files(), std::vector<std::string>{std::filesystem::path(temp).filename().string()})
      << "the target appeared before commit";
  file.commit();
  EXPECT_EQ(dir.files(), std::vector<std::string>{"out.txt"});
  EXPECT_EQ(contents(target), std::string("a\0b\nsecond", 10));
}

TEST(output_file, dropped_without_commit_leaves_the_target_as_it_was_and_no_temporary_file) {
  const TempDir dir;
  const std::string target = dir.write("out.txt", "before");
  {
    OutputFile file(target, "trace " + target);
    file.write("after");
    file.close();
  }
  EXPECT_EQ(dir.files(), std::vector<std::string>{"out.txt"});
  EXPECT_EQ(contents(target), "before");
  write_file(target, "trace " + target, "after");
  EXPECT_EQ(contents(target), "after") << "write_file did not replace the existing file";
  EXPECT_EQ(dir.files(), std::vector<std::string>{"out.txt"});
}

// mkstemp makes its file 0600; an output gets the mode a plain fopen would, 0666 less the umask.
TEST(output_file, gives_the_file_the_mode_of_a_plain_fopen) {
  const TempDir dir;
  const mode_t before = umask(022);
  write_file((dir.path / "a").string(), "a", "x");
  umask(027);
  write_file((dir.path / "b").string(), "b", "x");
  umask(before);
  struct stat a{}, b{};
  ASSERT_EQ(stat((dir.path / "a").c_str(), &a), 0);
  ASSERT_EQ(stat((dir.path / "b").c_str(), &b), 0);
  EXPECT_EQ(a.st_mode & 0777, 0644u);
  EXPECT_EQ(b.st_mode & 0777, 0640u);
}

TEST(output_file, names_the_file_and_the_reason_when_it_cannot_create_it) {
  const TempDir dir;
  const std::string target = (dir.path / "missing" / "t.jsonl").string();
  const auto e = thrown<OutputError>([&] { OutputFile file(target, "trace t.jsonl"); });
  ASSERT_TRUE(e);
  const std::string what = e->what();
  EXPECT_TRUE(what.starts_with("trace t.jsonl: cannot create " + target + ".partial-")) << what;
  EXPECT_TRUE(what.ends_with(": No such file or directory")) << what;
  EXPECT_TRUE(dir.files().empty());
}

// A directory where the file should go: the rename fails, and the temporary file goes when the OutputFile does.
TEST(output_file, names_the_temporary_file_when_the_rename_fails_and_removes_it) {
  const TempDir dir;
  std::filesystem::create_directories(dir.path / "out" / "inside");
  const std::string target = (dir.path / "out").string();
  std::string temp;
  const auto e = thrown<OutputError>([&] {
    OutputFile file(target, "picture out");
    temp = file.temp_path();
    file.write("<svg/>");
    file.commit();
  });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()), "picture out: cannot rename " + temp + " to it: Is a directory");
  EXPECT_EQ(dir.files(), std::vector<std::string>{"out"});
  EXPECT_EQ(dir.files("out"), std::vector<std::string>{"inside"});
}

}  // namespace
}  // namespace circles::formats

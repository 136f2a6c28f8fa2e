// Output files written where their paths point, whole or not at all (formats/output_file.hpp): the bytes go to a
// temporary file beside the target (or beside what a link leads to), renamed into place on commit; until then the
// target is untouched, and a file dropped or failed leaves nothing behind. A FIFO, a device and stdout are written
// in place. Messages open with what the file is and name the system's reason.
#include "formats/output_file.hpp"

#include "tests/temp_dir.hpp"
#include "tests/thrown.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/types.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <thread>
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

// A directory where the file should go is refused before anything is made.
TEST(output_file, refuses_a_directory_and_makes_nothing) {
  const TempDir dir;
  std::filesystem::create_directories(dir.path / "out" / "inside");
  const auto e = thrown<OutputError>([&] { OutputFile file((dir.path / "out").string(), "picture out"); });
  ASSERT_TRUE(e);
  EXPECT_EQ(std::string(e->what()), "picture out: it is a directory");
  EXPECT_EQ(dir.files(), std::vector<std::string>{"out"});
  EXPECT_EQ(dir.files("out"), std::vector<std::string>{"inside"});
}

// A regular file replaced keeps its permissions: a trace a user made private stays private.
TEST(output_file, keeps_the_permissions_of_the_file_it_replaces) {
  const TempDir dir;
  const std::string target = dir.write("private.jsonl", "before");
  ASSERT_EQ(chmod(target.c_str(), 0600), 0);
  write_file(target, "trace", "after");
  struct stat st{};
  ASSERT_EQ(stat(target.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_EQ(contents(target), "after");
}

bool is_link(const std::filesystem::path& path) { return std::filesystem::is_symlink(std::filesystem::symlink_status(path)); }

// A symbolic link (here two, the first relative to its own directory) leads to the file written: its temporary
// file is made in the target's directory, renamed over the target, and the links stay links.
TEST(output_file, writes_what_a_link_leads_to_in_the_targets_own_directory_and_keeps_the_link) {
  const TempDir dir;
  std::filesystem::create_directories(dir.path / "a");
  std::filesystem::create_directories(dir.path / "b");
  const std::string target = dir.write("b/target.jsonl", "before");
  std::filesystem::create_symlink("../b/target.jsonl", dir.path / "a" / "first");
  std::filesystem::create_symlink(dir.path / "a" / "first", dir.path / "second");
  {
    OutputFile file((dir.path / "second").string(), "trace second");
    EXPECT_EQ(file.kind(), OutputFile::Kind::renamed);
    EXPECT_EQ(std::filesystem::path(file.temp_path()).parent_path(), dir.path / "a" / ".." / "b") << file.temp_path();
    file.write("after");
    file.commit();
  }
  EXPECT_TRUE(is_link(dir.path / "second"));
  EXPECT_TRUE(is_link(dir.path / "a" / "first"));
  EXPECT_EQ(contents(target), "after");
  EXPECT_EQ(dir.files("a"), std::vector<std::string>{"first"});
  EXPECT_EQ(dir.files("b"), std::vector<std::string>{"target.jsonl"});
}

// A dangling link: the file it names is made, and the link then leads to it.
TEST(output_file, makes_the_file_a_dangling_link_names) {
  const TempDir dir;
  std::filesystem::create_directories(dir.path / "b");
  std::filesystem::create_symlink("b/new.jsonl", dir.path / "link");
  write_file((dir.path / "link").string(), "trace link", "made");
  EXPECT_TRUE(is_link(dir.path / "link"));
  EXPECT_EQ(contents(dir.path / "b" / "new.jsonl"), "made");
  EXPECT_EQ(dir.files("b"), std::vector<std::string>{"new.jsonl"});
}

// A FIFO is written in place, as a shell's > would: what its reader reads is the output, and the FIFO stays.
TEST(output_file, writes_a_fifo_in_place) {
  const TempDir dir;
  const std::filesystem::path fifo = dir.path / "fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::string read;
  std::thread reader([&] { read = contents(fifo); });
  {
    OutputFile file(fifo.string(), "trace fifo");
    EXPECT_EQ(file.kind(), OutputFile::Kind::in_place);
    EXPECT_EQ(file.temp_path(), "");
    file.write("through the fifo\n");
    file.commit();
  }
  reader.join();
  EXPECT_EQ(read, "through the fifo\n");
  struct stat st{};
  ASSERT_EQ(lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(dir.files(), std::vector<std::string>{"fifo"});
}

// A device is written in place and stays a device: a copy of /dev/null (major 1, minor 3) made in the test's
// directory where the tests run as root, as in CI containers, else /dev/null itself, which a user cannot
// replace anyway.
TEST(output_file, writes_a_device_in_place_and_leaves_it_a_device) {
  const TempDir dir;
  std::filesystem::path null = dir.path / "null";
  if (mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) null = "/dev/null";
  {
    OutputFile file(null.string(), "report null");
    EXPECT_EQ(file.kind(), OutputFile::Kind::in_place);
    file.write("into nothing");
    file.commit();
  }
  EXPECT_EQ(output_kind(null.string()), OutputFile::Kind::in_place);
  struct stat st{};
  ASSERT_EQ(lstat(null.c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << null << " is no longer a device";
  EXPECT_EQ(contents(null), "");
  if (null != "/dev/null") {
    EXPECT_EQ(dir.files(), std::vector<std::string>{"null"});
  }
}

// The program's stdout, pointed at a file for the test, and put back at the end.
class StdoutToFile {
 public:
  explicit StdoutToFile(const std::filesystem::path& file) {
    std::fflush(stdout);
    saved_ = dup(STDOUT_FILENO);
    const int fd = open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDOUT_FILENO);
    ::close(fd);
  }
  ~StdoutToFile() {
    std::fflush(stdout);
    dup2(saved_, STDOUT_FILENO);
    ::close(saved_);
  }
  StdoutToFile(const StdoutToFile&) = delete;
  StdoutToFile& operator=(const StdoutToFile&) = delete;

 private:
  int saved_;
};

// "-" is stdout, and so is any name of the file stdout is (/dev/fd/1): written in place through it, after what
// stdout already holds, and the file stays the one stdout writes to.
TEST(output_file, writes_dash_and_any_name_of_stdout_through_stdout) {
  const TempDir dir;
  const std::filesystem::path out = dir.path / "stdout.txt";
  struct stat before{}, after{};
  {
    const StdoutToFile redirected(out);
    ASSERT_EQ(stat(out.c_str(), &before), 0);
    EXPECT_TRUE(is_standard_output("-"));
    EXPECT_TRUE(is_standard_output("/dev/fd/1"));
    EXPECT_TRUE(is_standard_output(out.string()));
    EXPECT_FALSE(is_standard_output((dir.path / "other").string()));
    write_file("-", "trace -", "first\n");
    OutputFile file("/dev/fd/1", "trace /dev/fd/1");
    EXPECT_EQ(file.kind(), OutputFile::Kind::in_place);
    file.write("second\n");
    file.commit();
  }
  ASSERT_EQ(stat(out.c_str(), &after), 0);
  EXPECT_EQ(after.st_ino, before.st_ino) << "stdout's file was replaced";
  EXPECT_EQ(contents(out), "first\nsecond\n");
  EXPECT_EQ(dir.files(), std::vector<std::string>{"stdout.txt"});
}

// An interrupt ends a command through remove_temporary_files (cli/interrupt.hpp): every temporary file not yet
// renamed goes, and the program writing one (ffmpeg for a video) is stopped first.
TEST(output_file, remove_temporary_files_removes_each_file_being_written_and_stops_its_writer) {
  const TempDir dir;
  OutputFile trace((dir.path / "t.jsonl").string(), "trace");
  OutputFile video((dir.path / "v.mp4").string(), "video");
  trace.write("a line");
  const pid_t writer = fork();
  if (writer == 0) {
    pause();
    _exit(0);
  }
  video.written_by(writer);
  ASSERT_EQ(dir.files().size(), 2u);
  remove_temporary_files();
  EXPECT_TRUE(dir.files().empty());
  EXPECT_EQ(kill(writer, 0), -1) << "the writer still runs";
  write_file((dir.path / "after").string(), "after", "x");  // a file committed is no longer listed
  remove_temporary_files();
  EXPECT_EQ(dir.files(), std::vector<std::string>{"after"});
}

}  // namespace
}  // namespace circles::formats

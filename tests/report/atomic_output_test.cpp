#include "grpvss/report/atomic_output.hpp"

#include <filesystem>
#include <fstream>
#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "support/text_files.hpp"

namespace grpvss::report {
namespace {

using test::directory_entries;
using test::make_temporary_directory;
using test::read_text_file;

void write_plain(const std::string& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

TEST(AtomicOutput, WritesANewFileAndLeavesNoTemporary) {
  const std::string dir = make_temporary_directory("atomic");
  const std::string content("line 1\nline 2 \0 with a NUL\n", 26);
  write_file_atomically(dir + "/out.txt", content, false);
  EXPECT_EQ(read_text_file(dir + "/out.txt"), content);
  EXPECT_EQ(directory_entries(dir), std::vector<std::string>{"out.txt"});
  std::filesystem::remove_all(dir);
}

TEST(AtomicOutput, RefusesAnExistingFileAndLeavesItByteIdentical) {
  const std::string dir = make_temporary_directory("atomic");
  const std::string path = dir + "/out.txt";
  write_plain(path, "the user's precious file\n");
  try {
    write_file_atomically(path, "replacement", false);
    FAIL() << "an existing output was overwritten";
  } catch (const OutputExistsError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.line(), 0);
    EXPECT_EQ(error.expected(), "a path that does not exist yet (use --force to overwrite)");
  }
  EXPECT_EQ(read_text_file(path), "the user's precious file\n");
  EXPECT_EQ(directory_entries(dir), std::vector<std::string>{"out.txt"});
  std::filesystem::remove_all(dir);
}

TEST(AtomicOutput, OutputExistsErrorIsAnInputError) {
  const std::string dir = make_temporary_directory("atomic");
  write_plain(dir + "/x", "");
  EXPECT_THROW(write_file_atomically(dir + "/x", "y", false), InputError);
  std::filesystem::remove_all(dir);
}

TEST(AtomicOutput, RefusesADanglingSymlinkInsteadOfWritingThroughIt) {
  const std::string dir = make_temporary_directory("atomic");
  std::filesystem::create_symlink(dir + "/target-that-does-not-exist", dir + "/out.txt");
  EXPECT_THROW(write_file_atomically(dir + "/out.txt", "data", false), OutputExistsError);
  EXPECT_FALSE(std::filesystem::exists(dir + "/target-that-does-not-exist"));
  EXPECT_EQ(directory_entries(dir), std::vector<std::string>{"out.txt"});
  std::filesystem::remove_all(dir);
}

TEST(AtomicOutput, ForceReplacesAnExistingFile) {
  const std::string dir = make_temporary_directory("atomic");
  const std::string path = dir + "/out.txt";
  write_plain(path, "old content that is longer than the new one\n");
  write_file_atomically(path, "new\n", true);
  EXPECT_EQ(read_text_file(path), "new\n");
  EXPECT_EQ(directory_entries(dir), std::vector<std::string>{"out.txt"});
  std::filesystem::remove_all(dir);
}

TEST(AtomicOutput, ForceOnAFreshPathCreatesIt) {
  const std::string dir = make_temporary_directory("atomic");
  write_file_atomically(dir + "/fresh.txt", "x", true);
  EXPECT_EQ(read_text_file(dir + "/fresh.txt"), "x");
  EXPECT_EQ(directory_entries(dir), std::vector<std::string>{"fresh.txt"});
  std::filesystem::remove_all(dir);
}

TEST(AtomicOutput, MissingDirectoryIsAClearInputError) {
  const std::string dir = make_temporary_directory("atomic");
  const std::string path = dir + "/no/such/dir/out.txt";
  try {
    write_file_atomically(path, "data", false);
    FAIL() << "wrote into a missing directory";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.expected(), "a writable output location");
    EXPECT_EQ(error.found(), "creating a temporary file failed: No such file or directory");
  }
  EXPECT_TRUE(directory_entries(dir).empty());
  std::filesystem::remove_all(dir);
}

// A read-only directory. Root ignores permission bits, so the write happens in a child
// process that, when run as root, first drops to the unprivileged uid/gid 65534 ("nobody").
TEST(AtomicOutput, ReadOnlyDirectoryIsAClearInputError) {
  const std::string dir = make_temporary_directory("atomic");
  ASSERT_EQ(::chmod(dir.c_str(), 0555), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(3);
    try {
      write_file_atomically(dir + "/out.txt", "data", false);
      ::_exit(1);  // wrote into a read-only directory
    } catch (const InputError& error) {
      const bool clear = error.file() == dir + "/out.txt" &&
                         error.expected() == "a writable output location" &&
                         error.found() == "creating a temporary file failed: Permission denied";
      ::_exit(clear ? 0 : 2);
    } catch (...) {
      ::_exit(4);
    }
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: wrote, 2: unclear error, 3: cannot drop root, 4: other";
  EXPECT_TRUE(directory_entries(dir).empty());
  ::chmod(dir.c_str(), 0755);
  std::filesystem::remove_all(dir);
}

// A regular file used as a directory is unwritable for everybody, root included.
TEST(AtomicOutput, FileInPlaceOfDirectoryIsAClearInputError) {
  const std::string dir = make_temporary_directory("atomic");
  write_plain(dir + "/plain", "not a directory");
  try {
    write_file_atomically(dir + "/plain/out.txt", "data", true);
    FAIL() << "wrote below a regular file";
  } catch (const InputError& error) {
    EXPECT_EQ(error.found(), "creating a temporary file failed: Not a directory");
  }
  EXPECT_EQ(read_text_file(dir + "/plain"), "not a directory");
  EXPECT_EQ(directory_entries(dir), std::vector<std::string>{"plain"});
  std::filesystem::remove_all(dir);
}

// Fails after the temporary file was written: the temporary must still be removed.
TEST(AtomicOutput, FailedPublicationRemovesTheTemporaryFile) {
  const std::string dir = make_temporary_directory("atomic");
  std::filesystem::create_directories(dir + "/out/child");
  try {
    write_file_atomically(dir + "/out", "data", true);  // rename(2) onto a non-empty directory
    FAIL() << "replaced a directory";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), dir + "/out");
    EXPECT_NE(error.found().find("renaming the temporary file over the output failed"),
              std::string::npos)
        << error.found();
  }
  EXPECT_EQ(directory_entries(dir), std::vector<std::string>{"out"});
  EXPECT_EQ(directory_entries(dir + "/out"), std::vector<std::string>{"child"});
  EXPECT_THROW(write_file_atomically(dir + "/out", "data", false), OutputExistsError);
  EXPECT_EQ(directory_entries(dir), std::vector<std::string>{"out"});
  std::filesystem::remove_all(dir);
}

TEST(AtomicOutput, RelativePathUsesTheCurrentDirectory) {
  const std::string dir = make_temporary_directory("atomic");
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  write_file_atomically("relative.txt", "r", false);
  EXPECT_THROW(write_file_atomically("relative.txt", "r2", false), OutputExistsError);
  std::filesystem::current_path(previous);
  EXPECT_EQ(read_text_file(dir + "/relative.txt"), "r");
  EXPECT_EQ(directory_entries(dir), std::vector<std::string>{"relative.txt"});
  std::filesystem::remove_all(dir);
}


// No check-then-act race: of several writers racing for one new name, exactly one wins and
// the file holds exactly the winner's content.
TEST(AtomicOutput, ConcurrentWritersWithoutForceExactlyOneWins) {
  const std::string dir = make_temporary_directory("atomic");
  for (int round = 0; round < 20; ++round) {
    const std::string path = dir + "/race" + std::to_string(round) + ".txt";
    std::atomic<int> wins{0};
    std::atomic<int> refusals{0};
    std::atomic<int> winner{-1};
    std::vector<std::thread> writers;
    for (int w = 0; w < 6; ++w) {
      writers.emplace_back([&, w] {
        try {
          write_file_atomically(path, "writer " + std::to_string(w) + "\n", false);
          ++wins;
          winner = w;
        } catch (const OutputExistsError&) {
          ++refusals;
        }
      });
    }
    for (auto& writer : writers) writer.join();
    EXPECT_EQ(wins.load(), 1);
    EXPECT_EQ(refusals.load(), 5);
    EXPECT_EQ(read_text_file(path), "writer " + std::to_string(winner.load()) + "\n");
  }
  EXPECT_EQ(directory_entries(dir).size(), 20u);  // the 20 outputs, no temporary left
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace grpvss::report

#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputError.h"
#include "IO/Testing/FileSizeLimit.h"
#include "IO/Testing/ScratchFolderTest.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using proxima::AtomicOutputFile;
using proxima::OutputError;
using proxima::testing_support::messageUnderFileSizeLimit;

class AtomicOutput : public proxima::testing_support::ScratchFolderTest
{
protected:
  AtomicOutput()
    : ScratchFolderTest("proxima-output-")
  {}

  std::vector<std::string> folderNames() const
  {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(m_dir))
    {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

  static std::string contentOf(const std::string& path)
  {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
  }
};

TEST_F(AtomicOutput, CommitPutsTheWholeFileInPlaceAndNothingElse)
{
  const std::string target = pathOf("trace.csv");
  {
    AtomicOutputFile file(target);
    file.write("a,b\n");
    // Not there before it is complete.
    EXPECT_FALSE(fs::exists(target));
    file.write("1,2\n");
    file.commit();
  }
  EXPECT_EQ(contentOf(target), "a,b\n1,2\n");
  EXPECT_EQ(folderNames(), std::vector<std::string>{"trace.csv"});
  // A new file gets 0666 less the umask, like any other the user creates.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  struct stat info
  {};
  ASSERT_EQ(::stat(target.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0666 & ~mask);
}

TEST_F(AtomicOutput, ManyWritesLargerThanTheBufferArriveInOrder)
{
  const std::string target = pathOf("big.csv");
  std::string expected;
  {
    AtomicOutputFile file(target);
    for (int i = 0; i < 200000; ++i)
    {
      const std::string row = std::to_string(i) + ",0.125\n";
      file.write(row);
      expected += row;
    }
    file.write(std::string(3 << 20, 'x'));
    expected += std::string(3 << 20, 'x');
    file.commit();
  }
  EXPECT_EQ(contentOf(target), expected);
}

TEST_F(AtomicOutput, ReplacingAFileKeepsItsPermissions)
{
  const std::string target = write("mesh.obj", "old");
  ::chmod(target.c_str(), 0600);
  proxima::writeFileAtomically(target, "new");
  EXPECT_EQ(contentOf(target), "new");
  struct stat info
  {};
  ASSERT_EQ(::stat(target.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0600u);
}

TEST_F(AtomicOutput, ThroughALinkTheLinkedFileIsReplacedAndTheLinkKept)
{
  const std::string real = write("real.csv", "old");
  const std::string link = pathOf("link.csv");
  fs::create_symlink(real, link);
  proxima::writeFileAtomically(link, "new");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(contentOf(real), "new");
}

TEST_F(AtomicOutput, DestroyedWithoutCommitLeavesTheOldFileAndNoTemporary)
{
  const std::string target = write("trace.csv", "old trace\n");
  {
    AtomicOutputFile file(target);
    file.write("half a new tr");
  }
  EXPECT_EQ(contentOf(target), "old trace\n");
  EXPECT_EQ(folderNames(), std::vector<std::string>{"trace.csv"});
}

TEST_F(AtomicOutput, FinishedButNeverCommittedLeavesNothing)
{
  // A command's other output failed after this one was finished: this one must go too.
  {
    AtomicOutputFile file(pathOf("trace.csv"));
    file.write("a whole trace\n");
    file.finish();
    EXPECT_THROW(file.write("more"), OutputError);
  }
  EXPECT_TRUE(folderNames().empty());
}

TEST_F(AtomicOutput, AFileSizeLimitFailsWithTheReasonAndLeavesNothing)
{
  const std::string target = pathOf("trace.csv");
  const std::string message = messageUnderFileSizeLimit(4096, [&] {
    AtomicOutputFile file(target);
    for (int i = 0; i < 100000; ++i)
    {
      file.write("0,0.001,0.0125,0.25,-0.5\n");
    }
    file.commit();
  });
  EXPECT_EQ(message, target + ": cannot write the file (File too large)");
  EXPECT_TRUE(folderNames().empty());
}

TEST_F(AtomicOutput, AFailedWriteLeavesAnExistingTargetUntouched)
{
  const std::string target = write("mesh.obj", "the old mesh\n");
  const std::string message = messageUnderFileSizeLimit(
    1024, [&] { proxima::writeFileAtomically(target, std::string(100000, 'v')); });
  EXPECT_EQ(message, target + ": cannot write the file (File too large)");
  EXPECT_EQ(contentOf(target), "the old mesh\n");
  EXPECT_EQ(folderNames(), std::vector<std::string>{"mesh.obj"});
}

TEST_F(AtomicOutput, ADeviceIsWrittenInPlaceAndItsErrorsReported)
{
  // /dev/null takes everything, in place (never replaced: it is not ours to rename over).
  AtomicOutputFile sink("/dev/null");
  EXPECT_TRUE(sink.writesInPlace());
  sink.write("anything");
  sink.commit();
  // /dev/full refuses every byte, as a full disk does.
  try
  {
    proxima::writeFileAtomically("/dev/full", "a report\n");
    ADD_FAILURE() << "writing /dev/full succeeded";
  }
  catch (const OutputError& error)
  {
    EXPECT_STREQ(error.what(), "/dev/full: cannot write the file (No space left on device)");
  }
  struct stat info
  {};
  ASSERT_EQ(::stat("/dev/full", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
}

TEST_F(AtomicOutput, APipeIsWrittenInPlaceNotReplaced)
{
  const std::string fifo = pathOf("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // The reader first, so that opening the writing end does not wait.
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  {
    AtomicOutputFile file(fifo);
    EXPECT_TRUE(file.writesInPlace());
    file.write("through the pipe\n");
    file.commit();
  }
  char bytes[64] = {};
  const ssize_t n = ::read(reader, bytes, sizeof bytes);
  ::close(reader);
  EXPECT_EQ(std::string(bytes, n > 0 ? static_cast<std::size_t>(n) : 0), "through the pipe\n");
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(folderNames(), std::vector<std::string>{"fifo"});
}

TEST_F(AtomicOutput, RefusesDashAFolderAndAMissingFolderInOneLine)
{
  const auto messageOf = [](const std::string& path) {
    try
    {
      proxima::writeFileAtomically(path, "x");
    }
    catch (const OutputError& error)
    {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(messageOf("-"),
            "-: is not a file name here (give /dev/stdout to mean standard output)");
  EXPECT_EQ(messageOf(m_dir.string()), m_dir.string() + ": cannot write the file (Is a directory)");
  EXPECT_EQ(messageOf(pathOf("no/such/folder/x.csv")),
            pathOf("no/such/folder/x.csv") + ": cannot write the file (No such file or directory)");
  EXPECT_FALSE(fs::exists("-"));
  EXPECT_TRUE(folderNames().empty());
}

TEST_F(AtomicOutput, AnOutputErrorIsAnInputErrorForTheCommandLine)
{
  EXPECT_THROW(proxima::writeFileAtomically("/dev/full", "x"), proxima::InputError);
}
} // namespace

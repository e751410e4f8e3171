// A test fixture with a folder of its own for the files a test writes: made before each test
// (named for the process and the test, so parallel ctest runs never share one), removed after.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace proxima::testing_support
{

class ScratchFolderTest : public testing::Test
{
protected:
  /// `prefix` starts the folder's name, e.g. "proxima-io-".
  explicit ScratchFolderTest(std::string prefix)
    : m_prefix(std::move(prefix))
  {}

  void SetUp() override
  {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    m_dir = std::filesystem::temp_directory_path() /
            (m_prefix + std::to_string(::getpid()) + "-" + info->name());
    std::filesystem::create_directories(m_dir);
  }
  void TearDown() override { std::filesystem::remove_all(m_dir); }

  std::string pathOf(const std::string& name) const { return (m_dir / name).string(); }

  /// Writes `content` as file `name` in the folder and returns its path.
  std::string write(const std::string& name, const std::string& content) const
  {
    const std::string path = pathOf(name);
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }

  std::filesystem::path m_dir;

private:
  std::string m_prefix;
};

} // namespace proxima::testing_support

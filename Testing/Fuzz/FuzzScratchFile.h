// The readers take paths, so each fuzz input goes through one scratch file per process (in
// /dev/shm when it exists, to spare the disk), named by the process and the format's extension.
// The process number is padded to a fixed width: the path appears in the readers' messages, and a
// path one digit longer changes loop counts, so libFuzzer's coverage, so which inputs a run with a
// fixed seed and input count tries (CI's run must try the same ones on every machine).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace proxima::fuzz
{

class ScratchFile
{
public:
  explicit ScratchFile(const std::string& extension)
  {
    const std::filesystem::path folder = std::filesystem::exists("/dev/shm")
                                           ? std::filesystem::path("/dev/shm")
                                           : std::filesystem::temp_directory_path();
    char process[16];
    std::snprintf(process, sizeof(process), "%010d", static_cast<int>(::getpid()));
    m_path = (folder / ("proxima-fuzz-" + std::string(process) + extension)).string();
  }
  ~ScratchFile() { std::remove(m_path.c_str()); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  void write(const std::uint8_t* data, std::size_t size) const
  {
    std::FILE* out = std::fopen(m_path.c_str(), "wb");
    if (out == nullptr || (size > 0 && std::fwrite(data, 1, size, out) != size))
    {
      std::perror(m_path.c_str());
      std::abort();
    }
    std::fclose(out);
  }
  const std::string& path() const { return m_path; }

private:
  std::string m_path;
};

} // namespace proxima::fuzz

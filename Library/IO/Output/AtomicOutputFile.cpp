#include "IO/Output/AtomicOutputFile.h"

#include "IO/Output/OutputError.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace proxima
{
namespace
{
namespace fs = std::filesystem;

// Large enough that a trace of millions of rows costs few system calls.
constexpr std::size_t kBufferBytes = std::size_t(1) << 20;

/// The process's umask. Reading it means setting it, so it is read once (a thread creating a
/// file at that very moment could see 0); new outputs get 0666 less it, as fopen's would.
mode_t processUmask()
{
  static const mode_t mask = [] {
    const mode_t current = ::umask(0);
    ::umask(current);
    return current;
  }();
  return mask;
}

std::string systemReason(int error)
{
  return std::strerror(error);
}
} // namespace

AtomicOutputFile::AtomicOutputFile(const std::string& path)
  : m_path(path)
{
  if (path == "-")
  {
    throw OutputError::refused(path, "is not a file name here (give /dev/stdout to mean standard "
                                     "output)");
  }
  if (path.empty())
  {
    throw OutputError::cannotWrite(path, "the file name is empty");
  }
  (void)processUmask();
  struct stat target
  {};
  if (::stat(path.c_str(), &target) == 0)
  {
    if (S_ISDIR(target.st_mode))
    {
      throw OutputError::cannotWrite(path, systemReason(EISDIR));
    }
    if (!S_ISREG(target.st_mode))
    {
      // A pipe or a device cannot be replaced by a rename, and should not be: write into it.
      m_inPlace = true;
      m_descriptor = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
      if (m_descriptor < 0)
      {
        throw OutputError::cannotWrite(path, systemReason(errno));
      }
      m_buffer.reserve(kBufferBytes);
      return;
    }
    m_mode = target.st_mode & 07777;
    // Through a symbolic link, replace the file it names and keep the link.
    std::error_code error;
    const fs::path resolved = fs::canonical(path, error);
    m_finalPath = error ? path : resolved.string();
  }
  else if (errno == ENOENT)
  {
    m_mode = 0666 & ~processUmask();
    m_finalPath = path;
  }
  else
  {
    throw OutputError::cannotWrite(path, systemReason(errno));
  }

  const fs::path finalPath(m_finalPath);
  const std::string name = finalPath.filename().string();
  if (name.empty() || name == "." || name == "..")
  {
    throw OutputError::cannotWrite(path, systemReason(EISDIR));
  }
  const fs::path folder = finalPath.has_parent_path() ? finalPath.parent_path() : fs::path(".");
  std::string pattern = (folder / ("." + name + ".XXXXXX")).string();
  m_descriptor = ::mkostemp(pattern.data(), O_CLOEXEC);
  if (m_descriptor < 0)
  {
    throw OutputError::cannotWrite(path, systemReason(errno));
  }
  m_temporaryPath = pattern;
  m_buffer.reserve(kBufferBytes);
}

AtomicOutputFile::~AtomicOutputFile()
{
  if (!m_committed)
  {
    discard();
  }
}

void AtomicOutputFile::write(std::string_view bytes)
{
  if (m_failed || m_finished)
  {
    throw OutputError::cannotWrite(m_path, m_failed ? "an earlier write failed"
                                                    : "written after it was complete");
  }
  if (m_buffer.size() + bytes.size() > kBufferBytes)
  {
    writeBuffer();
  }
  if (bytes.size() >= kBufferBytes)
  {
    writeAll(bytes.data(), bytes.size());
    return;
  }
  m_buffer.insert(m_buffer.end(), bytes.begin(), bytes.end());
}

void AtomicOutputFile::writeBuffer()
{
  writeAll(m_buffer.data(), m_buffer.size());
  m_buffer.clear();
}

void AtomicOutputFile::writeAll(const char* bytes, std::size_t size)
{
  // write() may take fewer bytes than given (a signal, a pipe, the last blocks of a disk): go on
  // until all are taken or it says why not.
  std::size_t done = 0;
  while (done < size)
  {
    const ssize_t written = ::write(m_descriptor, bytes + done, size - done);
    if (written < 0)
    {
      if (errno == EINTR)
      {
        continue;
      }
      fail(systemReason(errno));
    }
    if (written == 0)
    {
      // POSIX allows it only for a zero-length write; never loop on it.
      fail("the system accepted no bytes");
    }
    done += static_cast<std::size_t>(written);
  }
}

void AtomicOutputFile::finish()
{
  if (m_finished)
  {
    return;
  }
  if (m_failed)
  {
    throw OutputError::cannotWrite(m_path, "an earlier write failed");
  }
  writeBuffer();
  if (!m_inPlace)
  {
    if (::fchmod(m_descriptor, static_cast<mode_t>(m_mode)) != 0)
    {
      fail(systemReason(errno));
    }
    // On the disk before the rename: a crash then shows the old file or the whole new one. Some
    // file systems report a full disk only here.
    if (::fsync(m_descriptor) != 0)
    {
      fail(systemReason(errno));
    }
  }
  const int descriptor = m_descriptor;
  m_descriptor = -1;
  if (::close(descriptor) != 0)
  {
    fail(systemReason(errno));
  }
  m_finished = true;
}

void AtomicOutputFile::commit()
{
  if (m_committed)
  {
    return;
  }
  finish();
  if (!m_inPlace)
  {
    if (::rename(m_temporaryPath.c_str(), m_finalPath.c_str()) != 0)
    {
      fail(systemReason(errno));
    }
    m_temporaryPath.clear();
  }
  m_committed = true;
}

void AtomicOutputFile::fail(const std::string& reason)
{
  discard();
  m_failed = true;
  throw OutputError::cannotWrite(m_path, reason);
}

void AtomicOutputFile::discard() noexcept
{
  if (m_descriptor >= 0)
  {
    ::close(m_descriptor);
    m_descriptor = -1;
  }
  if (!m_temporaryPath.empty())
  {
    ::unlink(m_temporaryPath.c_str());
    m_temporaryPath.clear();
  }
  m_buffer.clear();
}

void writeFileAtomically(const std::string& path, std::string_view bytes)
{
  AtomicOutputFile file(path);
  file.write(bytes);
  file.commit();
}

} // namespace proxima

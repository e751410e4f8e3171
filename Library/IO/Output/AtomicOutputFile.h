// One output file written so that it is never seen half-written (DESIGN.md section 6): the bytes
// go to a temporary file beside the target (".<name>.XXXXXX", same folder, so same file system),
// every write, the flush to disk and the close are checked, and the temporary is renamed over the
// target only by commit(). Any failure, or destruction without commit(), removes the temporary
// and leaves an existing target untouched. A target that exists and is not a regular file (a
// pipe, /dev/stdout, /dev/null, /dev/full) is written in place instead: it cannot be replaced,
// and its writes are checked all the same.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace proxima
{

/// One output file, all or nothing: written to a temporary beside the target and renamed over
/// it by commit() (a target that is not a regular file is written in place). Not copyable.
class AtomicOutputFile
{
public:
  /// Creates the temporary file (or opens a non-regular target). Throws OutputError naming
  /// `path` and the reason when it cannot, and for "-", which is not a file name here: each
  /// command says what it does with standard output.
  explicit AtomicOutputFile(const std::string& path);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicOutputFile();
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;

  /// Appends bytes (buffered). Throws OutputError, and removes the temporary, when the system
  /// refuses them; later calls throw too.
  void write(std::string_view bytes);
  /// Writes what is buffered, flushes it to the disk and closes it: everything that a full disk
  /// can fail, but not yet the rename. For a command with several outputs, which finishes each
  /// before it commits any, so that one failing leaves none. Throws OutputError (and removes
  /// the temporary) when any of it fails. No write() after it.
  void finish();
  /// finish(), then renames the temporary over the target. Throws OutputError (and removes the
  /// temporary) when any of it fails.
  void commit();

  /// The target as the caller named it.
  const std::string& path() const { return m_path; }
  /// True when the target is not a regular file and is written in place.
  bool writesInPlace() const { return m_inPlace; }

private:
  void writeBuffer();
  void writeAll(const char* bytes, std::size_t size);
  [[noreturn]] void fail(const std::string& reason);
  void discard() noexcept;

  std::string m_path;
  std::string m_finalPath;
  std::string m_temporaryPath;
  std::vector<char> m_buffer;
  int m_descriptor = -1;
  unsigned m_mode = 0;
  bool m_inPlace = false;
  bool m_failed = false;
  bool m_finished = false;
  bool m_committed = false;
};

/// Writes `bytes` to `path` through an AtomicOutputFile: all of them or, with an OutputError,
/// none.
void writeFileAtomically(const std::string& path, std::string_view bytes);

} // namespace proxima

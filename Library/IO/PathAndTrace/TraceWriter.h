// Trace file v2 (DESIGN.md section 3): one CSV row per servo tick, SI units, world frame:
// tick,t,finger_x,finger_y,finger_z,proxy_x,proxy_y,proxy_z,force_x,force_y,force_z,contacts,
// iterations,solve_ns,object,flags
// v1's columns first and in v1's order, so that a v1 reader (by name or by position) keeps
// working; `object` is the object of the first active contact (-1 free), `flags` the tick's
// conditions, TickConditions::bits() (Documentation/CommandLine.md).
#pragma once

#include "IO/Output/AtomicOutputFile.h"
#include "Runtime/HapticState.h"

#include <string>

namespace proxima
{

/// Writes a run's trace (v2): a header, one row per servo tick, and the file put in place only
/// by close().
class TraceWriter
{
public:
  /// The file's first line, its column names.
  static constexpr const char* kHeader =
    "tick,t,finger_x,finger_y,finger_z,proxy_x,proxy_y,proxy_z,force_x,force_y,force_z,"
    "contacts,iterations,solve_ns,object,flags";

  /// Starts `path` (under a temporary name until close(), AtomicOutputFile) with the header.
  /// Throws OutputError if it cannot.
  explicit TraceWriter(const std::string& path);

  /// Throws OutputError when the system refuses the row (a full disk): a run stops there.
  void write(const HapticState& record);
  /// Writes out the rest and checks that it reached the disk, without putting the trace in place
  /// yet: a run finishes its trace, then writes its other outputs, then closes the trace, so
  /// that a failure of any leaves none. Throws OutputError.
  void finish();
  /// Puts the complete trace in place; throws OutputError if the data did not reach the file.
  /// A trace never closed (a run that failed) leaves nothing behind.
  void close();

private:
  AtomicOutputFile m_file;
};

} // namespace proxima

// Trace file v2 (DESIGN.md section 3): one CSV row per servo tick, SI units, world frame:
// tick,t,finger_x,finger_y,finger_z,proxy_x,proxy_y,proxy_z,force_x,force_y,force_z,contacts,
// iterations,solve_ns,object,flags
// v1's columns first and in v1's order, so that a v1 reader (by name or by position) keeps
// working; `object` is the object of the first active contact (-1 free), `flags` the tick's
// TickFlag bits (Documentation/CommandLine.md).
#pragma once

#include "Runtime/HapticState.h"

#include <cstdio>
#include <string>

namespace proxima
{

class TraceWriter
{
public:
  static constexpr const char* kHeader =
    "tick,t,finger_x,finger_y,finger_z,proxy_x,proxy_y,proxy_z,force_x,force_y,force_z,"
    "contacts,iterations,solve_ns,object,flags";

  /// Opens `path` and writes the header. Throws std::runtime_error if it cannot.
  explicit TraceWriter(const std::string& path);
  ~TraceWriter();
  TraceWriter(const TraceWriter&) = delete;
  TraceWriter& operator=(const TraceWriter&) = delete;

  void write(const HapticState& record);
  /// Flushes and closes; throws std::runtime_error if the data did not reach the file.
  void close();

private:
  std::string m_path;
  std::FILE* m_file = nullptr;
};

} // namespace proxima

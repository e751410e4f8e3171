// The tissue file of `proxima run --tissue-out` (Documentation/Tissue.md): one row per tissue
// per tick, `tick,t,object,max_displacement,indentation,force,touched`: the largest distance of
// any of the solid's vertices from where it rests (m, as its last step left it), how far the
// proxy presses in (m: its deepest point below the rest tangent plane of the surface point it
// touches, TissueReading::indentation; 0 without contact), the magnitude of the force the proxy's spring pressed it with (N), and 1
// when the proxy touched it. Written atomically, like a trace.
#pragma once

#include "IO/Output/AtomicOutputFile.h"

#include <cstdint>
#include <string>

namespace proxima
{

/// Writes the tissue file of a run: a header, one row per tissue per tick, and the file put in
/// place only by close().
class TissueStateWriter
{
public:
  /// The file's first line, its column names.
  static constexpr const char* kHeader = "tick,t,object,max_displacement,indentation,force,touched";

  /// Starts `path` (under a temporary name until close()) with the header. Throws OutputError.
  explicit TissueStateWriter(const std::string& path);

  /// One row. Throws OutputError.
  void write(std::uint64_t tick, double time, std::uint32_t object, double maxDisplacement,
             double indentation, double force, bool touched);
  /// As TraceWriter::finish(): writes out the rest and checks that it reached the disk, without
  /// putting the file in place yet. Throws OutputError.
  void finish();
  /// As TraceWriter::close(): puts the complete file in place. Throws OutputError.
  void close();

private:
  AtomicOutputFile m_file;
};

} // namespace proxima

// The bodies file of `proxima run --bodies-out` (DESIGN.md section 3, "Bodies"): one row per
// moving object per tick, `tick,t,object,x,y,z,qw,qx,qy,qz,q`, the world pose of the object's
// frame (a point p of the object as placed is now at (x, y, z) + rotate(q, p)) and the joint
// coordinate in radians or metres (BodyWorld::jointPosition: for ball, free and mechanism bodies
// the angle of their turn from the start). Written atomically, like a trace.
#pragma once

#include "Core/Vec3.h"
#include "IO/Output/AtomicOutputFile.h"

#include <cstdint>
#include <string>

namespace proxima
{

/// Writes the bodies file of a run: a header, one row per moving object per tick, and the file
/// put in place only by close().
class BodyPoseWriter
{
public:
  /// The file's first line, its column names.
  static constexpr const char* kHeader = "tick,t,object,x,y,z,qw,qx,qy,qz,q";

  /// Starts `path` (under a temporary name until close()) with the header. Throws OutputError.
  explicit BodyPoseWriter(const std::string& path);

  /// One row; `jointPosition` null for a joint with no single coordinate. Throws OutputError.
  void write(std::uint64_t tick, double time, std::uint32_t object, const Vec3& position,
             const double orientation[4], const double* jointPosition);
  /// As TraceWriter::finish(): writes out the rest and checks that it reached the disk, without
  /// putting the file in place yet. Throws OutputError.
  void finish();
  /// As TraceWriter::close(): puts the complete file in place. Throws OutputError.
  void close();

private:
  AtomicOutputFile m_file;
};

} // namespace proxima

#include "IO/PathAndTrace/BodyPoseWriter.h"

#include <cstdio>
#include <string_view>

namespace proxima
{

BodyPoseWriter::BodyPoseWriter(const std::string& path)
  : m_file(path)
{
  m_file.write(kHeader);
  m_file.write("\n");
}

void BodyPoseWriter::write(std::uint64_t tick, double time, std::uint32_t object,
                           const Vec3& position, const double orientation[4],
                           const double* jointPosition)
{
  // %.17g, as the trace: poses round-trip exactly.
  char row[512];
  int length =
    std::snprintf(row, sizeof row, "%llu,%.17g,%u,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,",
                  static_cast<unsigned long long>(tick), time, object, position.x, position.y,
                  position.z, orientation[0], orientation[1], orientation[2], orientation[3]);
  if (jointPosition != nullptr)
  {
    length += std::snprintf(row + length, sizeof row - static_cast<std::size_t>(length), "%.17g",
                            *jointPosition);
  }
  row[length++] = '\n';
  m_file.write(std::string_view(row, static_cast<std::size_t>(length)));
}

void BodyPoseWriter::finish()
{
  m_file.finish();
}

void BodyPoseWriter::close()
{
  m_file.commit();
}

} // namespace proxima

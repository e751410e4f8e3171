#include "IO/PathAndTrace/TraceWriter.h"

#include <cstdio>
#include <string_view>

namespace proxima
{

TraceWriter::TraceWriter(const std::string& path)
  : m_file(path)
{
  m_file.write(kHeader);
  m_file.write("\n");
}

void TraceWriter::write(const HapticState& r)
{
  // %.17g: positions round-trip exactly, so traces compare bit for bit. 16 fields of at most 24
  // characters each fit the row.
  char row[512];
  const int length = std::snprintf(
    row, sizeof row,
    "%llu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d,%lld,%d,%u\n",
    static_cast<unsigned long long>(r.tick), r.time, r.finger.x, r.finger.y, r.finger.z, r.proxy.x,
    r.proxy.y, r.proxy.z, r.force.x, r.force.y, r.force.z, r.numContacts, r.iterations,
    static_cast<long long>(r.solveNanoseconds), r.contactObject,
    static_cast<unsigned>(r.conditions.bits()));
  m_file.write(std::string_view(row, static_cast<std::size_t>(length)));
}

void TraceWriter::finish()
{
  m_file.finish();
}

void TraceWriter::close()
{
  m_file.commit();
}

} // namespace proxima

#include "IO/PathAndTrace/TissueStateWriter.h"

#include <cstdio>
#include <string_view>

namespace proxima
{

TissueStateWriter::TissueStateWriter(const std::string& path)
  : m_file(path)
{
  m_file.write(kHeader);
  m_file.write("\n");
}

void TissueStateWriter::write(std::uint64_t tick, double time, std::uint32_t object,
                              double maxDisplacement, double indentation, double force,
                              bool touched)
{
  // %.17g, as the trace: the values round-trip exactly.
  char row[256];
  const int length = std::snprintf(row, sizeof row, "%llu,%.17g,%u,%.17g,%.17g,%.17g,%d\n",
                                   static_cast<unsigned long long>(tick), time, object,
                                   maxDisplacement, indentation, force, touched ? 1 : 0);
  m_file.write(std::string_view(row, static_cast<std::size_t>(length)));
}

void TissueStateWriter::finish()
{
  m_file.finish();
}

void TissueStateWriter::close()
{
  m_file.commit();
}

} // namespace proxima

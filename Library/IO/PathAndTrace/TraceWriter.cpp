#include "IO/PathAndTrace/TraceWriter.h"

#include "IO/InputChecks/InputError.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace proxima
{

TraceWriter::TraceWriter(const std::string& path)
  : m_path(path)
{
  m_file = std::fopen(path.c_str(), "w");
  if (m_file == nullptr)
  {
    // A trace the user cannot have is bad input, like an unwritable mesh (status 2).
    throw InputError(path, std::string("cannot write the file (") + std::strerror(errno) + ")");
  }
  // A large buffer: a long run writes millions of rows.
  std::setvbuf(m_file, nullptr, _IOFBF, 1 << 20);
  std::fprintf(m_file, "%s\n", kHeader);
}

TraceWriter::~TraceWriter()
{
  if (m_file != nullptr)
  {
    std::fclose(m_file);
  }
}

void TraceWriter::write(const HapticState& r)
{
  // %.17g: positions round-trip exactly, so traces compare bit for bit.
  std::fprintf(m_file,
               "%llu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d,%lld,"
               "%d,%u\n",
               static_cast<unsigned long long>(r.tick), r.time, r.finger.x, r.finger.y, r.finger.z,
               r.proxy.x, r.proxy.y, r.proxy.z, r.force.x, r.force.y, r.force.z, r.numContacts,
               r.iterations, static_cast<long long>(r.solveNanoseconds), r.contactObject,
               static_cast<unsigned>(tickFlags(r)));
}

void TraceWriter::close()
{
  if (m_file == nullptr)
  {
    return;
  }
  const bool failed = std::ferror(m_file) != 0;
  const bool closeFailed = std::fclose(m_file) != 0;
  m_file = nullptr;
  if (failed || closeFailed)
  {
    throw std::runtime_error(m_path + ": writing the trace failed");
  }
}

} // namespace proxima

#include "IO/PathAndTrace/FingerPathFile.h"

#include "IO/Output/AtomicOutputFile.h"

#include <cerrno>
#include <cstring>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace proxima
{
namespace
{
std::string trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
  {
    return {};
  }
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::string withoutSpaces(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    if (c != ' ' && c != '\t' && c != '\r')
    {
      out.push_back(c);
    }
  }
  return out;
}

// Parses one field as a double; the whole field must be the number.
bool parseNumber(const std::string& field, double& value)
{
  const std::string text = trim(field);
  if (text.empty())
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size())
  {
    return false;
  }
  // strtod also reads C's hexadecimal ("0x10" as 16), which no path file means; a finite value
  // must be written in decimal. "nan" and "inf" stay numbers here, refused next as not finite.
  return !std::isfinite(value) || text.find_first_not_of("0123456789.eE+-") == std::string::npos;
}
} // namespace

FingerPath readFingerPathFile(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
  {
    throw InputError(path, "cannot open the file for reading");
  }
  std::string line;
  std::size_t lineNumber = 0;
  bool haveHeader = false;
  FingerPath fingerPath;
  static const char* const kAxes[] = {"t", "x", "y", "z"};
  while (std::getline(in, line))
  {
    ++lineNumber;
    if (trim(line).empty())
    {
      continue;
    }
    if (!haveHeader)
    {
      if (withoutSpaces(line) != "t,x,y,z")
      {
        throw InputError(path, "line " + std::to_string(lineNumber) +
                                 ": expected the header 't,x,y,z', found '" + trim(line) + "'");
      }
      haveHeader = true;
      continue;
    }
    std::stringstream fields(line);
    std::string field;
    double values[4] = {0, 0, 0, 0};
    int count = 0;
    while (std::getline(fields, field, ','))
    {
      if (count == 4)
      {
        ++count;
        break;
      }
      if (!parseNumber(field, values[count]))
      {
        throw InputError(path, "line " + std::to_string(lineNumber) + ": " + kAxes[count] +
                                 " is not a number ('" + trim(field) + "')");
      }
      if (!std::isfinite(values[count]))
      {
        throw InputError(path, "line " + std::to_string(lineNumber) + ": " + kAxes[count] +
                                 " is not finite ('" + trim(field) + "')");
      }
      ++count;
    }
    if (count != 4)
    {
      throw InputError(path, "line " + std::to_string(lineNumber) +
                               ": expected 4 values t,x,y,z, found " +
                               (count > 4 ? std::string("more") : std::to_string(count)));
    }
    if (!fingerPath.empty() && values[0] < fingerPath.endTime())
    {
      std::ostringstream message;
      message.precision(17);
      message << "line " << lineNumber << ": time goes backwards (" << values[0] << " after "
              << fingerPath.endTime() << ")";
      throw InputError(path, message.str());
    }
    fingerPath.append(values[0], Vec3{values[1], values[2], values[3]});
  }
  if (!haveHeader)
  {
    throw InputError(path, "empty file: expected the header 't,x,y,z' and at least one row");
  }
  if (fingerPath.empty())
  {
    throw InputError(path, "no rows after the header");
  }
  return fingerPath;
}

void writeFingerPathFile(const std::string& path, const FingerPath& fingerPath)
{
  AtomicOutputFile file(path);
  file.write("t,x,y,z\n");
  char row[128];
  for (std::size_t i = 0; i < fingerPath.size(); ++i)
  {
    const Vec3& p = fingerPath.positions[i];
    const int length = std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,%.17g\n",
                                     fingerPath.times[i], p.x, p.y, p.z);
    file.write(std::string_view(row, static_cast<std::size_t>(length)));
  }
  file.commit();
}

} // namespace proxima

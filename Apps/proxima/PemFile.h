// TLS files of `proxima serve --tls-cert/--tls-key` and `proxima remote --tls-ca`: PEM text, read
// whole and checked for a PEM block, so that a wrong file is named here rather than failing
// inside gRPC's handshake.
#pragma once

#include "IO/InputChecks/FileChecks.h"
#include "IO/InputChecks/InputError.h"

#include <string>

namespace proxima::cli
{

/// The file's text. Throws InputError naming the file when it cannot be read (readWholeFile) or
/// holds no "-----BEGIN" line; `what` says what it should hold ("certificate", "private key").
inline std::string readPemFile(const std::string& path, const std::string& what)
{
  const std::string text = detail::readWholeFile(path, what + " file");
  if (text.find("-----BEGIN ") == std::string::npos)
  {
    throw InputError(path, "not a PEM " + what + " (no -----BEGIN line)");
  }
  return text;
}

} // namespace proxima::cli

// Checks made before any reader sees a file, because VTK's readers answer a missing or empty
// file with empty output and a warning instead of an error the caller can act on.
#pragma once

#include <cstdint>
#include <string>

namespace proxima::detail
{

/// Throws InputError unless `path` names a regular file this process can open and read and
/// that holds at least one byte. Returns its size in bytes. `kind` names what was expected, for
/// the message about a directory ("is a directory, not a mesh file").
std::uintmax_t requireReadableFile(const std::string& path, const std::string& kind = "mesh file");

/// The whole file, after requireReadableFile's checks. Throws InputError naming the file when it
/// cannot be opened or read.
std::string readWholeFile(const std::string& path, const std::string& kind);

/// Up to `count` bytes from the start of the file (fewer when it is shorter).
std::string readFileHead(const std::string& path, std::size_t count);

/// The head with leading whitespace (and a UTF-8 byte order mark) removed: for magic words.
std::string trimmedHead(const std::string& head);

} // namespace proxima::detail

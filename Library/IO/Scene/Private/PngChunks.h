// A walk over a PNG file's chunks (lengths, types, CRCs, the closing IEND) before OpenImageIO
// opens it: libpng reports a truncated or damaged file by printing "libpng error: ..." on stderr
// before OpenImageIO turns it into an error, and a command line must answer with one line of its
// own. What the walk cannot see (a damaged zlib stream inside intact chunks) still reaches libpng.
#pragma once

#include <string>

namespace proxima::detail
{

/// Throws InputError when the PNG at `path` (whose signature has been checked) is truncated or
/// its chunk structure is damaged: a first chunk other than IHDR, a chunk type that is not four
/// letters, a chunk longer than the file, a CRC that does not match, or no IEND.
void checkPngChunks(const std::string& path);

} // namespace proxima::detail

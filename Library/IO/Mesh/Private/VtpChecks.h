// A check of a VTK XML poly data file before vtkXMLPolyDataReader sees it: fuzzing found that
// the reader leaks its points (vtkPoints and the array under it) when the Points DataArray does
// not have three components, e.g. with the attribute's name garbled so that it defaults to one
// (Testing/Fuzz/Findings/FuzzMeshReader-vtp). The reader then fails anyway; this refuses the
// file first, with a message, and without the leak.
#pragma once

#include <string>

namespace proxima::detail
{

/// Throws InputError naming `path` unless every <Points> element's DataArray declares
/// NumberOfComponents="3".
void checkVtpPoints(const std::string& path);

/// Throws InputError naming `path` when what the file declares cannot be in its bytes, before
/// vtkXMLPolyDataReader allocates for it: a 2 KB file declaring 900,000,000 points made it
/// allocate 21.6 GB, and a garbled compressed block header (2.5e9 blocks of 1.3 GB,
/// Testing/Fuzz/Findings/FuzzMeshReader-vtp) ran it out of memory. Bounds: the pieces' declared
/// points and cells, one byte a value at least, times the most the file's compressor can expand
/// (1 without one); each binary or appended array's header (its byte count, or its block count,
/// block size and compressed sizes) against the bytes that follow it.
void checkVtpDeclaredSizes(const std::string& path);

} // namespace proxima::detail

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

} // namespace proxima::detail

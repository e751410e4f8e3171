// A structural check of an ASCII STL file before VTK's reader sees it: fuzzing found a garbled
// ASCII STL on which vtkSTLReader ran out of memory (Testing/Fuzz/Findings/FuzzMeshReader-stl).
// VTK reads only what passes: "solid", then facets of exactly "facet normal n n n / outer loop /
// vertex x y z (three times) / endloop / endfacet", then "endsolid"; numbers that strtod reads
// whole (non-finite ones are refused later, with the point, by PolyDataToSoup).
#pragma once

#include <string>

namespace proxima::detail
{

/// The longest line accepted, in bytes: far beyond any writer's, short enough to bound a read.
inline constexpr std::size_t kMaxAsciiStlLine = 4096;

/// Throws InputError naming `path`, the line and what was expected there unless the file is a
/// well-formed ASCII STL with at least one facet (several solids one after another are fine;
/// each ends with "endsolid", which VTK requires too).
void checkAsciiStl(const std::string& path);

/// Whether VTK's reader takes the file for ASCII: vtksys::SystemTools::DetectFileType's rule,
/// fewer than 5 % of the first 256 bytes outside [0x20, 0x7E] and \n \r \t. Our checks must
/// follow the reader's choice, or a text file could reach its ASCII parser unchecked.
bool vtkReadsStlAsAscii(const std::string& head);

} // namespace proxima::detail

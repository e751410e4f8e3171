// Finger path files (DESIGN.md section 3): CSV with the header `t,x,y,z`, seconds and metres,
// one row per servo tick or sparser (played back by linear interpolation).
#pragma once

#include "IO/InputChecks/InputError.h"
#include "Runtime/FingerPath.h"

#include <string>

namespace proxima
{

/// Reads a path file. Throws InputError naming the file, the line and the defect for a missing
/// or unreadable file, a wrong header, a row without four numbers, a non-finite value, a time
/// that goes backwards, or a file with no rows.
FingerPath readFingerPathFile(const std::string& path);

/// Writes `fingerPath` with full double precision, all of it or nothing (AtomicOutputFile).
/// Throws OutputError if it cannot.
void writeFingerPathFile(const std::string& path, const FingerPath& fingerPath);

} // namespace proxima

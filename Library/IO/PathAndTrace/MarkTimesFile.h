// The marks of a scripted session (the trainee's, the inspector's markers): a CSV file with the
// header `t` and one time in seconds (on the finger path's clock) per row, never going back. The
// windows record the same times when the mark key is pressed. Every defect is one InputError naming the file and line.
#pragma once

#include <string>
#include <vector>

namespace proxima
{

/// The times of the marks file at `path`, in file order. Throws InputError naming the file and
/// line for a missing header, a time that is not a finite number, or a time that goes back.
std::vector<double> readMarkTimesFile(const std::string& path);

} // namespace proxima

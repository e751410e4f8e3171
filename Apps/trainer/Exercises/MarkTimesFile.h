// The trainee's marks in a scripted session: a CSV file with the header `t` and one time in
// seconds (on the finger path's clock) per row, never going back. The window records the same
// times when the mark key is pressed. Every defect is one InputError naming the file and line.
#pragma once

#include <string>
#include <vector>

namespace proxima::trainer
{

std::vector<double> readMarkTimesFile(const std::string& path);

} // namespace proxima::trainer

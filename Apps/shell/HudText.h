// The applications' head-up display: white text on a dark, half-transparent framed box, legible
// over a light organ and over a dark background alike, in the bottom left corner.
#pragma once

#include "Runtime/HapticState.h"
#include "Runtime/LoopStatistics.h"

#include <string>

class vtkTextActor;

namespace proxima::shell
{

void styleHud(vtkTextActor* hud);

/// The HUD's first lines: the time, what is touched (object and contacts, sticking, fading), the
/// force, and the servo's rate, p99 jitter and missed deadlines.
std::string hapticStatusText(const HapticState& state, const LoopStatistics& servo);

} // namespace proxima::shell

// The applications' head-up display: white text on a dark, half-transparent framed box, legible
// over a light organ and over a dark background alike, in the bottom left corner.
#pragma once

class vtkTextActor;

namespace proxima::shell
{

void styleHud(vtkTextActor* hud);

} // namespace proxima::shell

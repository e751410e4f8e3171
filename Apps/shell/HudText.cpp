#include "HudText.h"

#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace proxima::shell
{

void styleHud(vtkTextActor* hud)
{
  vtkTextProperty* text = hud->GetTextProperty();
  text->SetFontSize(15);
  text->SetColor(1.0, 1.0, 1.0);
  text->SetBackgroundColor(0.05, 0.05, 0.08);
  text->SetBackgroundOpacity(0.7);
  text->SetFrame(1);
  text->SetFrameColor(0.4, 0.4, 0.45);
  hud->SetPosition(10, 10);
}

} // namespace proxima::shell

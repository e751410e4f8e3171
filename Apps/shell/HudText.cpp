#include "HudText.h"

#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <cstdio>

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

std::string hapticStatusText(const HapticState& state, const LoopStatistics& servo)
{
  char touched[64] = "free";
  if (state.contactObject >= 0)
  {
    std::snprintf(touched, sizeof touched, "touching object %d, %d contact%s", state.contactObject,
                  state.numContacts, state.numContacts == 1 ? "" : "s");
  }
  char text[400];
  std::snprintf(text, sizeof text,
                "t %.3f s   %s%s%s\nforce %.3f N\nservo %.0f Hz   p99 jitter %.1f us   missed %llu",
                state.time, touched,
                state.conditions.has(TickCondition::stuck) ? "   sticking" : "",
                state.conditions.has(TickCondition::forceFading) ? "   FADING" : "",
                norm(state.force), servo.rate, servo.jitterQuantileNanoseconds(0.99) / 1000.0,
                static_cast<unsigned long long>(servo.missedDeadlines));
  return text;
}

} // namespace proxima::shell

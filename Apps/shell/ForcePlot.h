// The applications' live force plot: the force's magnitude against time over the last few
// seconds, a white curve in a dark box in the window's top right corner, scaled to the force
// clamp (so a press reads the same height on every scene), with its scale written beside it.
// Drawn with VTK's 2D actors in normalised viewport coordinates; the curve's points are kept as
// plain numbers (curve()) so that the mapping is tested without a window.
#pragma once

#include <vtkSmartPointer.h>

#include <array>
#include <deque>
#include <vector>

class vtkActor2D;
class vtkPoints;
class vtkRenderer;
class vtkTextActor;

namespace proxima::shell
{

class ForcePlot
{
public:
  /// Shows the last `seconds` of force, 0 to `maxForce` newtons from the box's bottom to its top.
  ForcePlot(double seconds, double maxForce);

  /// Adds the force magnitude at `time` (seconds, never going back; older samples than the
  /// window are dropped; a time that goes back restarts the plot, as a replayed path does).
  void add(double time, double force);
  /// Rebuilds the curve from the samples; call once a frame.
  void update();

  /// The curve's points in normalised viewport coordinates (x, y in 0..1), oldest first.
  const std::vector<std::array<double, 2>>& curve() const { return m_curve; }

  void addToRenderer(vtkRenderer* renderer);
  /// Shows or hides the box, the curve and the label.
  void setVisible(bool visible);

  /// The box, in normalised viewport coordinates (default: the top right corner).
  void place(double left, double bottom, double right, double top);

private:
  double m_seconds;
  double m_maxForce;
  double m_box[4] = {0.68, 0.74, 0.98, 0.97};
  std::deque<std::array<double, 2>> m_samples;
  std::vector<std::array<double, 2>> m_curve;
  vtkSmartPointer<vtkPoints> m_curvePoints;
  vtkSmartPointer<vtkActor2D> m_curveActor;
  vtkSmartPointer<vtkPoints> m_boxPoints;
  vtkSmartPointer<vtkActor2D> m_boxActor;
  vtkSmartPointer<vtkTextActor> m_label;
};

} // namespace proxima::shell

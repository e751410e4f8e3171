// What the probe measured, drawn over the part (the inspector's window): markers as green balls,
// a white line between consecutive markers, where the probe stopped as red balls (the proxy held
// back while the finger went on), and the narrowest gap passed through as a cyan line across it.
#pragma once

#include "Probing/ProbeMeter.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkRenderer;

namespace proxima::inspector
{

class ProbeOverlay
{
public:
  /// `markerRadius`: the balls' radius in metres.
  ProbeOverlay(vtkRenderer* renderer, double markerRadius);
  ~ProbeOverlay();
  ProbeOverlay(const ProbeOverlay&) = delete;
  ProbeOverlay& operator=(const ProbeOverlay&) = delete;

  /// Redraws when the measurements grew or changed.
  void update(const ProbeMeasurements& measurements);
  void setMarkerRadius(double radius);

private:
  vtkRenderer* m_renderer;
  double m_markerRadius;
  vtkSmartPointer<vtkActor> m_markers;
  vtkSmartPointer<vtkActor> m_distances;
  vtkSmartPointer<vtkActor> m_stops;
  vtkSmartPointer<vtkActor> m_gap;
  std::size_t m_markersDrawn = ~std::size_t{0};
  std::size_t m_stopsDrawn = ~std::size_t{0};
  double m_gapDrawn = -1.0;
};

} // namespace proxima::inspector

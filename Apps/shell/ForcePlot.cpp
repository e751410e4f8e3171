#include "ForcePlot.h"

#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCoordinate.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cstdio>

namespace proxima::shell
{
namespace
{
vtkSmartPointer<vtkActor2D> actorOf(vtkPolyData* polyData, double r, double g, double b,
                                    double width)
{
  auto coordinate = vtkSmartPointer<vtkCoordinate>::New();
  coordinate->SetCoordinateSystemToNormalizedViewport();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  mapper->SetInputData(polyData);
  mapper->SetTransformCoordinate(coordinate);
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  return actor;
}
} // namespace

ForcePlot::ForcePlot(double seconds, double maxForce)
  : m_seconds(seconds)
  , m_maxForce(maxForce)
  , m_curvePoints(vtkSmartPointer<vtkPoints>::New())
  , m_boxPoints(vtkSmartPointer<vtkPoints>::New())
  , m_label(vtkSmartPointer<vtkTextActor>::New())
{
  auto curve = vtkSmartPointer<vtkPolyData>::New();
  curve->SetPoints(m_curvePoints);
  curve->SetLines(vtkSmartPointer<vtkCellArray>::New());
  m_curveActor = actorOf(curve, 1.0, 0.85, 0.3, 2.0);

  auto box = vtkSmartPointer<vtkPolyData>::New();
  box->SetPoints(m_boxPoints);
  auto outline = vtkSmartPointer<vtkCellArray>::New();
  outline->InsertNextCell(5);
  for (vtkIdType i = 0; i < 5; ++i)
  {
    outline->InsertCellPoint(i % 4);
  }
  box->SetLines(outline);
  m_boxActor = actorOf(box, 0.6, 0.6, 0.65, 1.0);

  vtkTextProperty* text = m_label->GetTextProperty();
  text->SetFontSize(13);
  text->SetColor(1.0, 1.0, 1.0);
  text->SetBackgroundColor(0.05, 0.05, 0.08);
  text->SetBackgroundOpacity(0.7);
  m_label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  char label[96];
  std::snprintf(label, sizeof label, "force, 0 to %.3g N, last %.3g s", m_maxForce, m_seconds);
  m_label->SetInput(label);
  place(m_box[0], m_box[1], m_box[2], m_box[3]);
}

void ForcePlot::place(double left, double bottom, double right, double top)
{
  m_box[0] = left;
  m_box[1] = bottom;
  m_box[2] = right;
  m_box[3] = top;
  m_boxPoints->Reset();
  m_boxPoints->InsertNextPoint(left, bottom, 0.0);
  m_boxPoints->InsertNextPoint(right, bottom, 0.0);
  m_boxPoints->InsertNextPoint(right, top, 0.0);
  m_boxPoints->InsertNextPoint(left, top, 0.0);
  m_boxPoints->Modified();
  m_label->SetPosition(left, bottom - 0.045);
  update();
}

void ForcePlot::add(double time, double force)
{
  if (!m_samples.empty() && time < m_samples.back()[0])
  {
    m_samples.clear();
  }
  m_samples.push_back({time, force});
  while (m_samples.size() > 1 && m_samples.front()[0] < time - m_seconds)
  {
    m_samples.pop_front();
  }
}

void ForcePlot::update()
{
  m_curve.clear();
  if (!m_samples.empty())
  {
    const double end = m_samples.back()[0];
    for (const auto& [time, force] : m_samples)
    {
      const double x = m_box[0] + (m_box[2] - m_box[0]) * (1.0 - (end - time) / m_seconds);
      const double fraction = std::clamp(force / m_maxForce, 0.0, 1.0);
      m_curve.push_back({std::max(x, m_box[0]), m_box[1] + (m_box[3] - m_box[1]) * fraction});
    }
  }
  m_curvePoints->Reset();
  for (const auto& [x, y] : m_curve)
  {
    m_curvePoints->InsertNextPoint(x, y, 0.0);
  }
  m_curvePoints->Modified();
  auto* curve = vtkPolyData::SafeDownCast(m_curveActor->GetMapper()->GetInputDataObject(0, 0));
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  if (m_curve.size() > 1)
  {
    lines->InsertNextCell(static_cast<int>(m_curve.size()));
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(m_curve.size()); ++i)
    {
      lines->InsertCellPoint(i);
    }
  }
  curve->SetLines(lines);
  curve->Modified();
}

void ForcePlot::addToRenderer(vtkRenderer* renderer)
{
  renderer->AddViewProp(m_boxActor);
  renderer->AddViewProp(m_curveActor);
  renderer->AddViewProp(m_label);
}

void ForcePlot::setVisible(bool visible)
{
  m_boxActor->SetVisibility(visible);
  m_curveActor->SetVisibility(visible);
  m_label->SetVisibility(visible);
}

} // namespace proxima::shell

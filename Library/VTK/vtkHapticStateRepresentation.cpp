#include "VTK/vtkHapticStateRepresentation.h"

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkConeSource.h>
#include <vtkLineSource.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>

#include <cmath>

vtkStandardNewMacro(vtkHapticStateRepresentation);

namespace
{
template <typename Source>
vtkSmartPointer<vtkActor> actorFor(Source* source, double red, double green, double blue,
                                   double opacity = 1.0)
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(red, green, blue);
  actor->GetProperty()->SetOpacity(opacity);
  // Nothing here is pickable: picking belongs to the scene's surfaces.
  actor->PickableOff();
  actor->VisibilityOff();
  return actor;
}

// Colours of the friction cones: sticking (the finger inside the static cone) and slipping.
constexpr double kStickColor[3] = {0.2, 0.8, 0.3};
constexpr double kSlipColor[3] = {1.0, 0.55, 0.1};
} // namespace

vtkHapticStateRepresentation::vtkHapticStateRepresentation()
{
  m_proxySource = vtkSmartPointer<vtkSphereSource>::New();
  m_proxySource->SetThetaResolution(32);
  m_proxySource->SetPhiResolution(16);
  // Double precision throughout: a scene far from the origin must not make the parts jitter.
  m_proxySource->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  m_proxyActor = actorFor(m_proxySource.Get(), 0.2, 0.45, 1.0);

  m_fingerSource = vtkSmartPointer<vtkSphereSource>::New();
  m_fingerSource->SetThetaResolution(32);
  m_fingerSource->SetPhiResolution(16);
  m_fingerSource->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  m_fingerActor = actorFor(m_fingerSource.Get(), 0.9, 0.9, 0.9, this->FingerOpacity);

  m_springSource = vtkSmartPointer<vtkLineSource>::New();
  m_springSource->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  m_springActor = actorFor(m_springSource.Get(), 1.0, 0.9, 0.2);
  m_springActor->GetProperty()->SetLineWidth(3.0);
  m_springActor->GetProperty()->LightingOff();

  m_arrowSource = vtkSmartPointer<vtkArrowSource>::New();
  m_arrowSource->SetShaftResolution(16);
  m_arrowSource->SetTipResolution(24);
  m_arrowTransform = vtkSmartPointer<vtkTransform>::New();
  m_forceActor = actorFor(m_arrowSource.Get(), 0.9, 0.15, 0.15);
  m_forceActor->SetUserTransform(m_arrowTransform);

  for (int i = 0; i < kMaxContacts; ++i)
  {
    m_discSources[i] = vtkSmartPointer<vtkRegularPolygonSource>::New();
    m_discSources[i]->SetNumberOfSides(48);
    m_discSources[i]->GeneratePolygonOn();
    m_discSources[i]->GeneratePolylineOff();
    m_discSources[i]->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    m_discActors[i] = actorFor(m_discSources[i].Get(), 0.3, 0.85, 0.95, this->ContactDiscOpacity);
    m_coneSources[i] = vtkSmartPointer<vtkConeSource>::New();
    m_coneSources[i]->SetResolution(32);
    m_coneSources[i]->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    m_coneActors[i] =
      actorFor(m_coneSources[i].Get(), kSlipColor[0], kSlipColor[1], kSlipColor[2], 0.55);
    // Open cones are seen from inside as well.
    m_coneActors[i]->GetProperty()->BackfaceCullingOff();
  }
}

vtkHapticStateRepresentation::~vtkHapticStateRepresentation() = default;

vtkActor* vtkHapticStateRepresentation::GetProxyActor()
{
  return m_proxyActor;
}

vtkActor* vtkHapticStateRepresentation::GetFingerActor()
{
  return m_fingerActor;
}

vtkActor* vtkHapticStateRepresentation::GetSpringActor()
{
  return m_springActor;
}

vtkActor* vtkHapticStateRepresentation::GetForceActor()
{
  return m_forceActor;
}

vtkActor* vtkHapticStateRepresentation::GetContactDiscActor(int contact)
{
  return contact >= 0 && contact < kMaxContacts ? m_discActors[contact].Get() : nullptr;
}

vtkActor* vtkHapticStateRepresentation::GetFrictionConeActor(int contact)
{
  return contact >= 0 && contact < kMaxContacts ? m_coneActors[contact].Get() : nullptr;
}

void vtkHapticStateRepresentation::AddToRenderer(vtkRenderer* renderer)
{
  // Opaque parts first, translucent after: depth peeling or not, that order reads best.
  renderer->AddActor(m_proxyActor);
  renderer->AddActor(m_springActor);
  renderer->AddActor(m_forceActor);
  for (int i = 0; i < kMaxContacts; ++i)
  {
    renderer->AddActor(m_coneActors[i]);
    renderer->AddActor(m_discActors[i]);
  }
  renderer->AddActor(m_fingerActor);
}

void vtkHapticStateRepresentation::RemoveFromRenderer(vtkRenderer* renderer)
{
  renderer->RemoveActor(m_proxyActor);
  renderer->RemoveActor(m_springActor);
  renderer->RemoveActor(m_forceActor);
  for (int i = 0; i < kMaxContacts; ++i)
  {
    renderer->RemoveActor(m_coneActors[i]);
    renderer->RemoveActor(m_discActors[i]);
  }
  renderer->RemoveActor(m_fingerActor);
}

void vtkHapticStateRepresentation::SetState(const proxima::HapticState& state)
{
  m_state = state;
  const double radius = state.proxyRadius > 0.0 ? state.proxyRadius : 0.001;

  m_proxySource->SetCenter(state.proxy.x, state.proxy.y, state.proxy.z);
  m_proxySource->SetRadius(radius);
  m_proxyActor->VisibilityOn();

  m_fingerSource->SetCenter(state.finger.x, state.finger.y, state.finger.z);
  m_fingerSource->SetRadius(radius);
  m_fingerActor->GetProperty()->SetOpacity(this->FingerOpacity);
  m_fingerActor->VisibilityOn();

  m_springSource->SetPoint1(state.finger.x, state.finger.y, state.finger.z);
  m_springSource->SetPoint2(state.proxy.x, state.proxy.y, state.proxy.z);
  m_springActor->SetVisibility(proxima::norm(state.proxy - state.finger) > 0.0);

  this->UpdateForceArrow();
  for (int i = 0; i < kMaxContacts; ++i)
  {
    this->UpdateContact(i);
  }
  this->Modified();
}

void vtkHapticStateRepresentation::UpdateForceArrow()
{
  const proxima::Vec3& force = m_state.force;
  const double magnitude = proxima::norm(force);
  const double shaft = magnitude * this->ForceScale;
  if (!(shaft > 0.0) || !std::isfinite(shaft))
  {
    m_forceActor->VisibilityOff();
    return;
  }
  // vtkArrowSource's tip and shaft radii are fractions of the scale across the arrow.
  const double head = this->ForceArrowHeadLength;
  const double length = head > 0.0 ? shaft + head : shaft;
  const double across = head > 0.0 ? head : length;
  m_arrowSource->SetTipLength(head > 0.0 ? head / length : 0.35);
  m_arrowSource->SetTipRadius(head > 0.0 ? 0.35 : 0.1);
  m_arrowSource->SetShaftRadius(head > 0.0 ? 0.1 : 0.03);
  // vtkArrowSource points from the origin along +x with unit length: turn +x onto the force.
  const double x[3] = {1.0, 0.0, 0.0};
  const double direction[3] = {force.x / magnitude, force.y / magnitude, force.z / magnitude};
  double axis[3];
  vtkMath::Cross(x, direction, axis);
  const double sine = vtkMath::Norm(axis);
  const double cosine = vtkMath::Dot(x, direction);
  m_arrowTransform->Identity();
  m_arrowTransform->PostMultiply();
  m_arrowTransform->Scale(length, across, across);
  if (sine > 1e-12)
  {
    m_arrowTransform->RotateWXYZ(vtkMath::DegreesFromRadians(std::atan2(sine, cosine)), axis);
  }
  else if (cosine < 0.0)
  {
    m_arrowTransform->RotateZ(180.0);
  }
  m_arrowTransform->Translate(m_state.proxy.x, m_state.proxy.y, m_state.proxy.z);
  m_forceActor->VisibilityOn();
}

void vtkHapticStateRepresentation::UpdateContact(int i)
{
  if (i >= m_state.numContacts)
  {
    m_discActors[i]->VisibilityOff();
    m_coneActors[i]->VisibilityOff();
    return;
  }
  const proxima::ContactSnapshot& contact = m_state.contacts[i];
  const double radius = m_state.proxyRadius > 0.0 ? m_state.proxyRadius : 0.001;
  const proxima::Vec3& n = contact.normal;
  const proxima::Vec3& p = contact.point;

  const double discRadius = this->ContactDiscRadius > 0.0 ? this->ContactDiscRadius : 4.0 * radius;
  // Lifted off the surface by 2% of a proxy radius, so that the disc does not fight the surface
  // it lies on for the depth buffer.
  const double lift = 0.02 * radius;
  m_discSources[i]->SetCenter(p.x + lift * n.x, p.y + lift * n.y, p.z + lift * n.z);
  m_discSources[i]->SetNormal(n.x, n.y, n.z);
  m_discSources[i]->SetRadius(discRadius);
  m_discActors[i]->GetProperty()->SetOpacity(this->ContactDiscOpacity);
  m_discActors[i]->VisibilityOn();

  // The cone of forces friction can hold, apex at the contact, around the normal into free
  // space: half-angle atan(mu_s) while sticking (the finger is inside it), atan(mu_d) while
  // slipping (the finger rides its rim). The force arrow lies inside a closed (sticking) cone.
  const double mu = m_state.conditions.has(proxima::TickCondition::stuck) ? contact.staticFriction
                                                                          : contact.dynamicFriction;
  const double shown = mu > 0.0 ? mu : std::max(contact.staticFriction, contact.dynamicFriction);
  if (!(shown > 0.0))
  {
    m_coneActors[i]->VisibilityOff();
    return;
  }
  const double height = this->FrictionConeHeight > 0.0 ? this->FrictionConeHeight : 3.0 * radius;
  // vtkConeSource puts its apex at Center + Direction * Height / 2.
  m_coneSources[i]->SetHeight(height);
  m_coneSources[i]->SetRadius(height * shown);
  m_coneSources[i]->SetDirection(-n.x, -n.y, -n.z);
  m_coneSources[i]->SetCenter(p.x + 0.5 * height * n.x, p.y + 0.5 * height * n.y,
                              p.z + 0.5 * height * n.z);
  m_coneSources[i]->SetCapping(m_state.conditions.has(proxima::TickCondition::stuck) ? 1 : 0);
  const double* color =
    m_state.conditions.has(proxima::TickCondition::stuck) ? kStickColor : kSlipColor;
  m_coneActors[i]->GetProperty()->SetColor(color[0], color[1], color[2]);
  m_coneActors[i]->VisibilityOn();
}

void vtkHapticStateRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ContactDiscRadius: " << this->ContactDiscRadius << " (0: four proxy radii)\n";
  os << indent << "FrictionConeHeight: " << this->FrictionConeHeight << " (0: three proxy radii)\n";
  os << indent << "ForceScale: " << this->ForceScale << " m/N\n";
  os << indent << "ForceArrowHeadLength: " << this->ForceArrowHeadLength << " m (0: grows)\n";
  os << indent << "FingerOpacity: " << this->FingerOpacity << "\n";
  os << indent << "ContactDiscOpacity: " << this->ContactDiscOpacity << "\n";
  os << indent << "State: tick " << m_state.tick << ", " << m_state.numContacts << " contacts"
     << (m_state.conditions.has(proxima::TickCondition::stuck) ? ", stuck" : "") << "\n";
}

#include "VTK/vtkHapticMouseFinger.h"

#include "Geometry/SphereTree.h"
#include "Runtime/PointerDevice.h"

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkInteractorObserver.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cstring>

vtkStandardNewMacro(vtkHapticMouseFinger);

namespace
{
// Before the interactor style (priority 0): the wheel is taken from it.
constexpr float kObserverPriority = 1.0f;

proxima::Vec3 worldPointOfDisplay(vtkRenderer* renderer, double x, double y, double z)
{
  renderer->SetDisplayPoint(x, y, z);
  renderer->DisplayToWorld();
  double world[4];
  renderer->GetWorldPoint(world);
  const double w = world[3] != 0.0 ? world[3] : 1.0;
  return {world[0] / w, world[1] / w, world[2] / w};
}
} // namespace

vtkHapticMouseFinger::vtkHapticMouseFinger()
  : m_callback(vtkSmartPointer<vtkCallbackCommand>::New())
  , m_scratch(std::make_unique<proxima::SphereTreeScratch>())
{
  m_callback->SetClientData(this);
  m_callback->SetCallback(&vtkHapticMouseFinger::OnEvent);
}

vtkHapticMouseFinger::~vtkHapticMouseFinger()
{
  this->SetInteractor(nullptr);
}

void vtkHapticMouseFinger::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthStep: " << this->DepthStep << "\n";
  os << indent << "PressSpeed: " << this->PressSpeed << "\n";
  os << indent << "Depth: " << this->GetDepth() << "\n";
}

void vtkHapticMouseFinger::SetHapticRenderer(vtkHapticRenderer* haptics)
{
  m_haptics = haptics;
}

void vtkHapticMouseFinger::SetRenderer(vtkRenderer* renderer)
{
  m_renderer = renderer;
}

void vtkHapticMouseFinger::SetInteractor(vtkRenderWindowInteractor* interactor)
{
  if (m_interactor)
  {
    m_interactor->RemoveObserver(m_callback);
  }
  if (m_style)
  {
    m_style->RemoveObserver(m_callback);
  }
  m_interactor = interactor;
  m_style = interactor != nullptr ? interactor->GetInteractorStyle() : nullptr;
  if (m_style)
  {
    // A style grabs the interactor's focus when a drag starts, and the button's release then goes
    // to it alone: the end of its interaction says the drag is over.
    m_style->AddObserver(vtkCommand::EndInteractionEvent, m_callback);
  }
  if (m_interactor)
  {
    for (const unsigned long event :
         {vtkCommand::MouseMoveEvent, vtkCommand::MouseWheelForwardEvent,
          vtkCommand::MouseWheelBackwardEvent, vtkCommand::LeftButtonPressEvent,
          vtkCommand::LeftButtonReleaseEvent, vtkCommand::MiddleButtonPressEvent,
          vtkCommand::MiddleButtonReleaseEvent, vtkCommand::RightButtonPressEvent,
          vtkCommand::RightButtonReleaseEvent, vtkCommand::KeyPressEvent,
          vtkCommand::KeyReleaseEvent})
    {
      m_interactor->AddObserver(event, m_callback, kObserverPriority);
    }
  }
}

void vtkHapticMouseFinger::StepDepth(int notches)
{
  m_aimPlane.setDepth(m_aimPlane.depth() + notches * this->DepthStep);
  this->Aim();
}

void vtkHapticMouseFinger::AimAtDisplayPoint(int x, int y)
{
  m_cursor[0] = x;
  m_cursor[1] = y;
  m_hasCursor = true;
  this->Aim();
}

void vtkHapticMouseFinger::Update(double seconds)
{
  if (m_pressing && seconds > 0.0)
  {
    m_aimPlane.setDepth(m_aimPlane.depth() + this->PressSpeed * seconds);
  }
  this->Aim();
}

void vtkHapticMouseFinger::Aim()
{
  if (m_device == nullptr || !m_renderer || !m_haptics || !m_hasCursor || m_buttonHeld)
  {
    return;
  }
  // The cursor's ray: from its point on the near clipping plane to its point on the far one.
  const proxima::Vec3 nearPoint = worldPointOfDisplay(m_renderer, m_cursor[0], m_cursor[1], 0.0);
  const proxima::Vec3 farPoint = worldPointOfDisplay(m_renderer, m_cursor[0], m_cursor[1], 1.0);
  double projection[3];
  m_renderer->GetActiveCamera()->GetDirectionOfProjection(projection);
  const proxima::Vec3 view{projection[0], projection[1], projection[2]};

  const proxima::HapticState state = m_haptics->GetState();
  // The hover point: the proxy's sphere swept along the ray, first touch over every object. The
  // trees are read-only and shared with the haptic threads; the scratch is this thread's own.
  proxima::Vec3 hover;
  m_hovering = false;
  const std::shared_ptr<const proxima::CollisionScene> scene = m_haptics->GetCollisionScene();
  if (scene)
  {
    const proxima::SweepQuery sweep{nearPoint, farPoint, m_haptics->GetProxyRadius(), 0.0};
    double first = 1.0;
    for (const proxima::CollisionObject& object : scene->objects)
    {
      const proxima::SweepContact contact =
        object.tree.firstContact(object.mesh, sweep, *m_scratch);
      if (contact.hit && contact.t < first)
      {
        first = contact.t;
        m_hovering = true;
      }
    }
    hover = nearPoint + (farPoint - nearPoint) * first;
  }
  // A tissue under the finger gives way, and the proxy sinks with it: a press measured from the
  // proxy would move the finger deeper at every aim, pushing with a constant force until the
  // tissue tore through. While every contact is on a deforming object and the cursor's ray meets
  // the surface as the scene gave it, the press is measured from that surface at rest (the hover
  // point), so that the wheel sets how deep the finger goes, as on a rigid surface.
  bool touching = state.numContacts > 0;
  if (touching && m_hovering)
  {
    const std::vector<std::uint32_t> deforming = m_haptics->GetDeformingObjects();
    bool onTissueOnly = !deforming.empty();
    for (int k = 0; k < state.numContacts && onTissueOnly; ++k)
    {
      onTissueOnly =
        std::find(deforming.begin(), deforming.end(), state.contacts[k].object) != deforming.end();
    }
    touching = !onTissueOnly;
  }
  const proxima::Vec3 aim = m_aimPlane.aim(nearPoint, farPoint - nearPoint, view, state.proxy,
                                           touching, m_hovering ? &hover : nullptr);
  m_device->aimAt(aim);
}

void vtkHapticMouseFinger::OnEvent(vtkObject* caller, unsigned long event, void* clientData,
                                   void* /*callData*/)
{
  auto* self = static_cast<vtkHapticMouseFinger*>(clientData);
  auto* interactor = vtkRenderWindowInteractor::SafeDownCast(caller);
  if (interactor == nullptr)
  {
    // The style's end of a drag (SetInteractor).
    self->m_buttonHeld = event == vtkCommand::EndInteractionEvent ? false : self->m_buttonHeld;
    return;
  }
  switch (event)
  {
    case vtkCommand::MouseMoveEvent:
    {
      const int* position = interactor->GetEventPosition();
      if (!self->m_buttonHeld)
      {
        self->AimAtDisplayPoint(position[0], position[1]);
      }
      break;
    }
    case vtkCommand::MouseWheelForwardEvent:
    case vtkCommand::MouseWheelBackwardEvent:
      self->StepDepth(event == vtkCommand::MouseWheelForwardEvent ? 1 : -1);
      // The style would zoom on it.
      self->m_callback->SetAbortFlag(1);
      break;
    case vtkCommand::LeftButtonPressEvent:
    case vtkCommand::MiddleButtonPressEvent:
    case vtkCommand::RightButtonPressEvent: self->m_buttonHeld = true; break;
    case vtkCommand::LeftButtonReleaseEvent:
    case vtkCommand::MiddleButtonReleaseEvent:
    case vtkCommand::RightButtonReleaseEvent: self->m_buttonHeld = false; break;
    case vtkCommand::KeyPressEvent:
    case vtkCommand::KeyReleaseEvent:
    {
      const char* key = interactor->GetKeySym();
      if (key != nullptr && std::strcmp(key, "space") == 0)
      {
        self->m_pressing = event == vtkCommand::KeyPressEvent;
      }
      else if (key != nullptr && std::strcmp(key, "BackSpace") == 0 &&
               event == vtkCommand::KeyPressEvent)
      {
        self->SetDepth(0.0);
        self->Aim();
      }
      break;
    }
    default: break;
  }
}

// vtkHapticStateRepresentation: draws one HapticState (Runtime/HapticState.h): the proxy sphere,
// the finger as a translucent ghost sphere, the spring between them, a translucent disc on the
// constraint plane of each contact, the friction cone at each contact with friction (closed and
// green while the proxy sticks, open and orange while it slips) and the force on the finger as
// an arrow from the proxy's centre (from the finger it would start inside the surface, unseen). Render-thread only: feed it vtkHapticRenderer::GetState() each frame, or states
// computed in lockstep.
#pragma once

#include "Runtime/HapticState.h"

#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <array>

class vtkActor;
class vtkArrowSource;
class vtkConeSource;
class vtkLineSource;
class vtkRegularPolygonSource;
class vtkRenderer;
class vtkSphereSource;
class vtkTransform;

/// Draws one HapticState: the proxy, the finger as a ghost sphere, the spring between them, a
/// disc on each contact's constraint plane, the friction cones (green and closed while the proxy
/// sticks, orange and open while it slips) and the force as an arrow from the proxy's centre.
/// Render-thread only.
class vtkHapticStateRepresentation : public vtkObject
{
public:
  /// A new representation, every part hidden until the first SetState.
  static vtkHapticStateRepresentation* New();
  /// Prints the properties and the state's tick, contacts and whether it sticks.
  vtkTypeMacro(vtkHapticStateRepresentation, vtkObject) void PrintSelf(ostream& os,
                                                                       vtkIndent indent) override;

  /// Moves every part to `state`; parts without a subject (contacts beyond numContacts, cones of
  /// frictionless contacts, a zero force) are hidden.
  void SetState(const proxima::HapticState& state);
  /// The state last set (a default state before any).
  const proxima::HapticState& GetState() const { return m_state; }

  /// Adds every part's actor to `renderer`, opaque parts before translucent ones.
  void AddToRenderer(vtkRenderer* renderer);
  /// Removes every part's actor from `renderer`.
  void RemoveFromRenderer(vtkRenderer* renderer);

  ///@{
  /// Radius of the contact discs in metres; 0 (the default) uses four proxy radii.
  vtkSetClampMacro(ContactDiscRadius, double, 0.0, VTK_DOUBLE_MAX);
  /// Radius of the contact discs (m; 0: four proxy radii).
  vtkGetMacro(ContactDiscRadius, double);
  ///@}

  ///@{
  /// Height of the friction cones in metres; 0 (the default) uses three proxy radii.
  vtkSetClampMacro(FrictionConeHeight, double, 0.0, VTK_DOUBLE_MAX);
  /// Height of the friction cones (m; 0: three proxy radii).
  vtkGetMacro(FrictionConeHeight, double);
  ///@}

  ///@{
  /// Length of the force arrow per newton, in metres (default 0.002).
  vtkSetClampMacro(ForceScale, double, 0.0, VTK_DOUBLE_MAX);
  /// Length of the force arrow per newton (m/N).
  vtkGetMacro(ForceScale, double);
  ///@}

  ///@{
  /// Length in metres of the force arrow's head, which then keeps its size: the shaft, as thick
  /// as a fifth of the head is long, is ForceScale per newton long, and the head is drawn beyond
  /// it, so that a small force still shows as a head. 0 (the default): the whole arrow, head and
  /// thickness included, grows with the force.
  vtkSetClampMacro(ForceArrowHeadLength, double, 0.0, VTK_DOUBLE_MAX);
  /// Length of the force arrow's head (m; 0: the whole arrow grows with the force).
  vtkGetMacro(ForceArrowHeadLength, double);
  ///@}

  ///@{
  /// Opacity of the finger's ghost sphere, 0 to 1 (default 0.3), applied at the next SetState.
  vtkSetClampMacro(FingerOpacity, double, 0.0, 1.0);
  /// Opacity of the finger's ghost sphere.
  vtkGetMacro(FingerOpacity, double);
  /// Opacity of the contact discs, 0 to 1 (default 0.4), applied at the next SetState.
  vtkSetClampMacro(ContactDiscOpacity, double, 0.0, 1.0);
  /// Opacity of the contact discs.
  vtkGetMacro(ContactDiscOpacity, double);
  ///@}

  /// The parts, to restyle them (colours, visibility); SetState sets their visibility. Out of
  /// line, so that the header needs no vtkActor (VTK's Python wrapping compiles it as is).
  vtkActor* GetProxyActor();
  /// The finger's ghost sphere.
  vtkActor* GetFingerActor();
  /// The spring, a line from the finger to the proxy.
  vtkActor* GetSpringActor();
  /// The force arrow.
  vtkActor* GetForceActor();
  /// The disc of contact `contact` (0 to 2), null for another index.
  vtkActor* GetContactDiscActor(int contact);
  /// The friction cone of contact `contact` (0 to 2), null for another index.
  vtkActor* GetFrictionConeActor(int contact);

protected:
  vtkHapticStateRepresentation();
  ~vtkHapticStateRepresentation() override;

  double ContactDiscRadius = 0.0;    ///< Contact disc radius (m; 0: four proxy radii).
  double FrictionConeHeight = 0.0;   ///< Friction cone height (m; 0: three proxy radii).
  double ForceScale = 0.002;         ///< Force arrow length per newton (m/N).
  double ForceArrowHeadLength = 0.0; ///< Force arrow head length (m; 0: grows with the force).
  double FingerOpacity = 0.3;        ///< Opacity of the finger's ghost sphere.
  double ContactDiscOpacity = 0.4;   ///< Opacity of the contact discs.

private:
  vtkHapticStateRepresentation(const vtkHapticStateRepresentation&) = delete;
  void operator=(const vtkHapticStateRepresentation&) = delete;

  void UpdateForceArrow();
  void UpdateContact(int contact);

  proxima::HapticState m_state;
  vtkSmartPointer<vtkSphereSource> m_proxySource;
  vtkSmartPointer<vtkSphereSource> m_fingerSource;
  vtkSmartPointer<vtkLineSource> m_springSource;
  vtkSmartPointer<vtkArrowSource> m_arrowSource;
  vtkSmartPointer<vtkTransform> m_arrowTransform;
  vtkSmartPointer<vtkActor> m_proxyActor;
  vtkSmartPointer<vtkActor> m_fingerActor;
  vtkSmartPointer<vtkActor> m_springActor;
  vtkSmartPointer<vtkActor> m_forceActor;
  static constexpr int kMaxContacts = 3;
  std::array<vtkSmartPointer<vtkRegularPolygonSource>, kMaxContacts> m_discSources;
  std::array<vtkSmartPointer<vtkActor>, kMaxContacts> m_discActors;
  std::array<vtkSmartPointer<vtkConeSource>, kMaxContacts> m_coneSources;
  std::array<vtkSmartPointer<vtkActor>, kMaxContacts> m_coneActors;
};

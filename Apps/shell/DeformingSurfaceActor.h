// A tissue's surface drawn as it deforms (Documentation/Tissue.md): vtkHapticTissue, the
// pipeline's source of a tissue's newest step, through the scene surface's normals, colour and
// shading. A window calls update() once a frame; a lockstep run's picture calls it once, after
// the run (the lockstep run hands over its steps the same way).
#pragma once

#include "Proxy/CollisionScene.h"
#include "Tissue/TissueDynamics.h"
#include "VTK/vtkHapticTissue.h"

#include <vtkActor.h>
#include <vtkSmartPointer.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace proxima::shell
{

/// Tissue `index` of `tissue` (objects of `scene`), drawn as its newest step left it.
class DeformingSurfaceActor
{
public:
  DeformingSurfaceActor(std::shared_ptr<TissueDynamics> tissue,
                        std::shared_ptr<const CollisionScene> scene, std::size_t index);
  /// The actor to add to a renderer.
  vtkActor* actor() const { return m_actor; }
  /// Takes the newest step's surface, drawn at the next render; true when it is newer than the
  /// one drawn. The drawing thread only.
  bool update() { return m_source->TakeNewestStep(); }

private:
  vtkSmartPointer<vtkHapticTissue> m_source;
  vtkSmartPointer<vtkActor> m_actor;
};

/// One actor per tissue of `tissue` (null: none).
std::vector<DeformingSurfaceActor> makeTissueActors(
  const std::shared_ptr<TissueDynamics>& tissue,
  const std::shared_ptr<const CollisionScene>& scene);

} // namespace proxima::shell

#include "DeformingSurfaceActor.h"

#include "SceneSurfaceActor.h"

#include <utility>

namespace proxima::shell
{

DeformingSurfaceActor::DeformingSurfaceActor(std::shared_ptr<TissueDynamics> tissue,
                                             std::shared_ptr<const CollisionScene> scene,
                                             std::size_t index)
  : m_source(vtkSmartPointer<vtkHapticTissue>::New())
{
  m_source->SetTissue(std::move(tissue), std::move(scene), static_cast<int>(index));
  m_actor = makeSurfaceActor(m_source->GetOutputPort());
}

std::vector<DeformingSurfaceActor> makeTissueActors(
  const std::shared_ptr<TissueDynamics>& tissue, const std::shared_ptr<const CollisionScene>& scene)
{
  std::vector<DeformingSurfaceActor> actors;
  for (std::size_t k = 0; tissue != nullptr && k < tissue->numTissues(); ++k)
  {
    actors.emplace_back(tissue, scene, k);
  }
  return actors;
}

} // namespace proxima::shell

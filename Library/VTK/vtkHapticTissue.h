// vtkHapticTissue: a tissue's surface as it deforms, as a pipeline source (issue 35, "Seen and
// used"). The haptic threads step the scene's tissues (Tissue/TissueDynamics.h, handed to
// vtkHapticRenderer with its scene); after each step the solids' points are handed to one
// drawing thread without locks. This source's output is one tissue's surface as the newest step
// left it: the scene object's triangles over the solid's present points, in the scene's frame,
// cell data "ObjectId" as vtkHapticScene's output has it. A render loop calls TakeNewestStep()
// once a frame; it marks the source modified when a step came, and the next Update draws it.
//
// Properties follow VTK's naming (the Set/Get macros need it); members that are not properties
// use the project's m_ prefix.
#pragma once

#include "Proxy/CollisionScene.h"
#include "Tissue/TissueDynamics.h"

#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <memory>

/// One tissue's surface as the haptic threads' newest solid step left it: a source for the
/// drawing thread.
class vtkHapticTissue : public vtkPolyDataAlgorithm
{
public:
  /// A new source, with no tissue: its output is empty until SetTissue.
  static vtkHapticTissue* New();
  /// Prints the tissue drawn and the step it shows.
  vtkTypeMacro(vtkHapticTissue, vtkPolyDataAlgorithm) void PrintSelf(ostream& os,
                                                                     vtkIndent indent) override;

  /// The tissues (the ones vtkHapticRenderer::SetCollisionScene was given) and the scene they are
  /// objects of; `index` picks the tissue drawn (TissueDynamics::object(index) is its object).
  /// An index that is not a tissue's draws nothing (vtkErrorMacro).
  void SetTissue(std::shared_ptr<proxima::TissueDynamics> tissue,
                 std::shared_ptr<const proxima::CollisionScene> scene, int index = 0);

  /// For the one drawing thread: takes the newest step's surfaces from the tissues and marks this
  /// source modified when they are newer than the ones drawn; returns whether they were. Every
  /// vtkHapticTissue of the same tissues sees the newest step, whichever takes it first.
  bool TakeNewestStep();
  /// The solids' steps when the surfaces drawn were handed over (0: at rest).
  std::uint64_t GetStepDrawn() const { return m_stepDrawn; }

protected:
  /// A source without inputs.
  vtkHapticTissue();
  ~vtkHapticTissue() override;
  /// Draws the object's triangles over the points of the newest step taken (the surface at rest
  /// before any). Fails when the solid's points are not the object's.
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkHapticTissue(const vtkHapticTissue&) = delete;
  void operator=(const vtkHapticTissue&) = delete;

  std::shared_ptr<proxima::TissueDynamics> m_tissue;
  std::shared_ptr<const proxima::CollisionScene> m_scene;
  int m_index = 0;
  /// The object's triangles at rest (made once); each execution draws them over new points.
  vtkSmartPointer<vtkPolyData> m_atRest;
  std::uint64_t m_stepDrawn = 0;
};

// vtkHapticSphereTreeFilter: vtkPolyData in, the bounding-sphere tree of paper section 5 out.
// The tree (with the kernel's mesh) is kept for a haptic scene (GetCollisionObject); the output
// poly data holds the tree's spheres at one level, tessellated, for drawing.
//
// Properties follow VTK's naming (the Set/Get macros need it); members that are not properties
// use the project's m_ prefix.
#pragma once

#include "Proxy/CollisionScene.h"

#include <vtkPolyDataAlgorithm.h>

#include <memory>

class vtkHapticSphereTreeFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkHapticSphereTreeFilter* New();
  vtkTypeMacro(vtkHapticSphereTreeFilter,
               vtkPolyDataAlgorithm) void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Units of the input to metres (default 1). Changing it rebuilds the tree.
  vtkSetClampMacro(Scale, double, 1e-12, VTK_DOUBLE_MAX);
  vtkGetMacro(Scale, double);
  ///@}

  ///@{
  /// Tree depth whose spheres the output draws: 0 is the root; leaf nodes above this depth are
  /// drawn too, so every part of the surface is covered (default 4).
  vtkSetClampMacro(Level, int, 0, 127);
  vtkGetMacro(Level, int);
  ///@}

  ///@{
  /// Draw the leaf spheres (one per triangle or triangle piece) instead of a level (default off).
  vtkSetMacro(DrawLeafSpheres, vtkTypeBool);
  vtkGetMacro(DrawLeafSpheres, vtkTypeBool);
  vtkBooleanMacro(DrawLeafSpheres, vtkTypeBool);
  ///@}

  ///@{
  /// Segments around each drawn sphere (default 12; half as many from pole to pole).
  vtkSetClampMacro(SphereResolution, int, 4, 128);
  vtkGetMacro(SphereResolution, int);
  ///@}

  ///@{
  /// SphereTreeOptions::leafSizeFactor: triangles longer than this many median edge lengths are
  /// split among several leaf spheres; 0 gives one sphere per triangle (default 2).
  vtkSetClampMacro(LeafSizeFactor, double, 0.0, 1e6);
  vtkGetMacro(LeafSizeFactor, double);
  ///@}

  ///@{
  /// SphereTreeOptions::maxLeafSpheresPerNode (default 4; 1 is the paper's tree exactly).
  vtkSetClampMacro(MaxLeafSpheresPerNode, int, 1, 64);
  vtkGetMacro(MaxLeafSpheresPerNode, int);
  ///@}

  ///@{
  /// Build the tree on every hardware thread (default on; off builds it on one). The tree is the
  /// same bit for bit either way, so changing this does not rebuild it.
  vtkSetMacro(ParallelTreeBuild, vtkTypeBool);
  vtkGetMacro(ParallelTreeBuild, vtkTypeBool);
  vtkBooleanMacro(ParallelTreeBuild, vtkTypeBool);
  ///@}

  /// The mesh and tree of the last successful execution (null before one), shared so that a
  /// scene can hold it after this filter has moved on; no material (a scene gives it one).
  std::shared_ptr<const proxima::CollisionObject> GetCollisionObject() const { return m_object; }
  /// Wall time of the last tree build in milliseconds (0 when the tree was reused).
  double GetTreeBuildMilliseconds() const { return m_treeBuildMilliseconds; }

protected:
  vtkHapticSphereTreeFilter() = default;
  ~vtkHapticSphereTreeFilter() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Scale = 1.0;
  int Level = 4;
  vtkTypeBool DrawLeafSpheres = 0;
  int SphereResolution = 12;
  double LeafSizeFactor = 2.0;
  int MaxLeafSpheresPerNode = 4;
  vtkTypeBool ParallelTreeBuild = 1;

private:
  vtkHapticSphereTreeFilter(const vtkHapticSphereTreeFilter&) = delete;
  void operator=(const vtkHapticSphereTreeFilter&) = delete;

  /// True when the input or the tree's options changed since the tree was built: a new Level
  /// alone only redraws.
  bool TreeIsStale(vtkDataObject* input) const;

  std::shared_ptr<const proxima::CollisionObject> m_object;
  vtkMTimeType m_builtFromInputTime = 0;
  vtkDataObject* m_builtFromInput = nullptr;
  double m_builtScale = 0.0;
  double m_builtLeafSizeFactor = -1.0;
  int m_builtMaxLeafSpheres = 0;
  double m_treeBuildMilliseconds = 0.0;
};

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

/// vtkPolyData in, the bounding-sphere tree of paper section 5 out: keeps the tree with the
/// kernel's mesh for a haptic scene (GetCollisionObject), and outputs the tree's spheres at one
/// level (or its leaf spheres), tessellated, for drawing; the cell scalars "Radius" hold each
/// sphere's radius in metres.
class vtkHapticSphereTreeFilter : public vtkPolyDataAlgorithm
{
public:
  /// A new filter, with no tree until it executes.
  static vtkHapticSphereTreeFilter* New();
  /// Prints the properties and the tree's size.
  vtkTypeMacro(vtkHapticSphereTreeFilter,
               vtkPolyDataAlgorithm) void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Units of the input to metres (default 1). Changing it rebuilds the tree.
  vtkSetClampMacro(Scale, double, 1e-12, VTK_DOUBLE_MAX);
  /// Units of the input to metres.
  vtkGetMacro(Scale, double);
  ///@}

  ///@{
  /// Tree depth whose spheres the output draws: 0 is the root; leaf nodes above this depth are
  /// drawn too, so every part of the surface is covered (default 4).
  vtkSetClampMacro(Level, int, 0, 127);
  /// Tree depth whose spheres the output draws (0: the root).
  vtkGetMacro(Level, int);
  ///@}

  ///@{
  /// Draw the leaf spheres (one per triangle or triangle piece) instead of a level (default off).
  vtkSetMacro(DrawLeafSpheres, vtkTypeBool);
  /// Whether the output draws the leaf spheres instead of a level.
  vtkGetMacro(DrawLeafSpheres, vtkTypeBool);
  /// Draws the leaf spheres.
  vtkBooleanMacro(DrawLeafSpheres, vtkTypeBool);
  /// \fn void vtkHapticSphereTreeFilter::DrawLeafSpheresOff()
  /// Draws the spheres at Level.
  ///@}

  ///@{
  /// Segments around each drawn sphere (default 12; half as many from pole to pole).
  vtkSetClampMacro(SphereResolution, int, 4, 128);
  /// Segments around each drawn sphere.
  vtkGetMacro(SphereResolution, int);
  ///@}

  ///@{
  /// SphereTreeOptions::leafSizeFactor: triangles longer than this many median edge lengths are
  /// split among several leaf spheres; 0 gives one sphere per triangle (default 2).
  vtkSetClampMacro(LeafSizeFactor, double, 0.0, 1e6);
  /// SphereTreeOptions::leafSizeFactor of the tree.
  vtkGetMacro(LeafSizeFactor, double);
  ///@}

  ///@{
  /// SphereTreeOptions::maxLeafSpheresPerNode (default 4; 1 is the paper's tree exactly).
  vtkSetClampMacro(MaxLeafSpheresPerNode, int, 1, 64);
  /// SphereTreeOptions::maxLeafSpheresPerNode of the tree.
  vtkGetMacro(MaxLeafSpheresPerNode, int);
  ///@}

  ///@{
  /// Build the tree on every hardware thread (default on; off builds it on one). The tree is the
  /// same bit for bit either way, so changing this does not rebuild it.
  vtkSetMacro(ParallelTreeBuild, vtkTypeBool);
  /// Whether the tree is built on every hardware thread.
  vtkGetMacro(ParallelTreeBuild, vtkTypeBool);
  /// Builds the tree on every hardware thread.
  vtkBooleanMacro(ParallelTreeBuild, vtkTypeBool);
  /// \fn void vtkHapticSphereTreeFilter::ParallelTreeBuildOff()
  /// Builds the tree on one thread.
  ///@}

  /// The mesh and tree of the last successful execution (null before one), shared so that a
  /// scene can hold it after this filter has moved on; no material (a scene gives it one).
  std::shared_ptr<const proxima::CollisionObject> GetCollisionObject() const { return m_object; }
  /// Wall time of the last tree build in milliseconds (0 when the tree was reused).
  double GetTreeBuildMilliseconds() const { return m_treeBuildMilliseconds; }

protected:
  vtkHapticSphereTreeFilter() = default;
  ~vtkHapticSphereTreeFilter() override = default;

  /// Builds the tree when the input or the tree's options changed (else reuses it) and draws
  /// its spheres. Fails, keeping the previous tree, for input the kernel cannot use.
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Scale = 1.0;                ///< Units of the input to metres: SetScale.
  int Level = 4;                     ///< Tree depth drawn: SetLevel.
  vtkTypeBool DrawLeafSpheres = 0;   ///< Draw the leaf spheres instead: SetDrawLeafSpheres.
  int SphereResolution = 12;         ///< Segments around each drawn sphere: SetSphereResolution.
  double LeafSizeFactor = 2.0;       ///< The tree's leaf size factor: SetLeafSizeFactor.
  int MaxLeafSpheresPerNode = 4;     ///< Leaf spheres per leaf node: SetMaxLeafSpheresPerNode.
  vtkTypeBool ParallelTreeBuild = 1; ///< Tree on every hardware thread: SetParallelTreeBuild.

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

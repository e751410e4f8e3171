// vtkHapticScene: the haptic scene as a pipeline sink. Each input connection is one object
// (vtkPolyData) with its own scale, pose and material; executing builds the kernel's
// CollisionScene from them, an immutable snapshot that vtkHapticRenderer hands to the haptic
// threads. Editing an input's poly data, a pose transform or a material marks the scene modified,
// and the next Update rebuilds only the objects that changed and makes a new snapshot (a new
// version); the haptic threads keep running on the old one until the new one is complete.
//
// The output is the scene's surface as the proxy feels it (every object scaled and placed, one
// poly data, cell data "ObjectId"), for drawing.
#pragma once

#include "Proxy/CollisionScene.h"

#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <memory>
#include <vector>

class vtkLinearTransform;

class vtkHapticScene : public vtkPolyDataAlgorithm
{
public:
  static vtkHapticScene* New();
  vtkTypeMacro(vtkHapticScene, vtkPolyDataAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Adds an object: returns its index (the input connection's). Same as AddInputConnection.
  int AddObject(vtkAlgorithmOutput* polyData);
  /// Adds an object from a data set (wrapped in a trivial producer); editing `polyData` and
  /// calling its Modified() rebuilds the object at the next Update.
  int AddObjectData(vtkPolyData* polyData);
  int GetNumberOfObjects();

  ///@{
  /// Per object: units to metres (default 1).
  void SetObjectScale(int object, double scale);
  double GetObjectScale(int object) const;
  ///@}

  ///@{
  /// Per object: a rigid pose (rotation and translation; null for none, the default). The
  /// transform is watched: modifying it rebuilds the object at the next Update.
  void SetObjectPose(int object, vtkLinearTransform* pose);
  vtkLinearTransform* GetObjectPose(int object) const;
  ///@}

  ///@{
  /// Per object: static and dynamic friction coefficients and viscosity in N s/m (default 0:
  /// none), and force shading from the poly data's point normals, made with a 30 degree feature
  /// angle when it has none (default off).
  void SetObjectFriction(int object, double staticFriction, double dynamicFriction,
                         double viscosity);
  void SetObjectShading(int object, bool shading);
  ///@}

  ///@{
  /// Tree options for every object (SphereTreeOptions; defaults 2 and 4).
  vtkSetClampMacro(LeafSizeFactor, double, 0.0, 1e6);
  vtkGetMacro(LeafSizeFactor, double);
  vtkSetClampMacro(MaxLeafSpheresPerNode, int, 1, 64);
  vtkGetMacro(MaxLeafSpheresPerNode, int);
  ///@}

  ///@{
  /// Build the trees of several changed objects at once with vtkSMPTools, one object per task
  /// (default on; off builds one tree at a time). Two edited 1.5M-triangle objects on two cores:
  /// 955 ms from the edit to live instead of 1325-1470 ms (Documentation/VtkPipeline.md). One
  /// object's tree is one serial build either way.
  vtkSetMacro(ParallelTreeBuild, vtkTypeBool);
  vtkGetMacro(ParallelTreeBuild, vtkTypeBool);
  vtkBooleanMacro(ParallelTreeBuild, vtkTypeBool);
  ///@}

  ///@{
  /// Make the output surface (default on). Off saves a copy of every mesh per rebuild where
  /// nothing draws the scene's own output.
  vtkSetMacro(GenerateSurface, vtkTypeBool);
  vtkGetMacro(GenerateSurface, vtkTypeBool);
  vtkBooleanMacro(GenerateSurface, vtkTypeBool);
  ///@}

  /// The last snapshot built (null before the first successful Update). Immutable: the haptic
  /// threads may hold it while a newer one is built.
  std::shared_ptr<const proxima::CollisionScene> GetCollisionScene() const { return m_scene; }
  /// 1 for the first snapshot, then +1 for each rebuilt one (0 before the first).
  std::uint64_t GetSceneVersion() const { return m_sceneVersion; }
  /// Objects rebuilt by the last execution, and its wall time in milliseconds.
  int GetNumberOfObjectsRebuilt() const { return m_numRebuilt; }
  double GetLastBuildMilliseconds() const { return m_lastBuildMilliseconds; }

  /// Includes the pose transforms, so that editing one re-executes the scene.
  vtkMTimeType GetMTime() override;

protected:
  vtkHapticScene();
  ~vtkHapticScene() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double LeafSizeFactor = 2.0;
  int MaxLeafSpheresPerNode = 4;
  vtkTypeBool GenerateSurface = 1;
  vtkTypeBool ParallelTreeBuild = 1;

private:
  vtkHapticScene(const vtkHapticScene&) = delete;
  void operator=(const vtkHapticScene&) = delete;

  struct ObjectEntry
  {
    double scale = 1.0;
    vtkSmartPointer<vtkLinearTransform> pose;
    bool shading = false;
    double staticFriction = 0.0;
    double dynamicFriction = 0.0;
    double viscosity = 0.0;
    /// Bumped by every per-object setter, so that a material change rebuilds this object.
    std::uint64_t settingsVersion = 1;
    // What the cached object was built from.
    std::shared_ptr<const proxima::CollisionObject> built;
    vtkDataObject* builtFrom = nullptr;
    vtkMTimeType builtFromTime = 0;
    vtkMTimeType builtPoseTime = 0;
    std::uint64_t builtSettingsVersion = 0;
    double builtLeafSizeFactor = -1.0;
    int builtMaxLeafSpheres = 0;
  };
  ObjectEntry& Entry(int object);
  const ObjectEntry* FindEntry(int object) const;

  std::vector<ObjectEntry> m_objects;
  std::shared_ptr<const proxima::CollisionScene> m_scene;
  std::uint64_t m_sceneVersion = 0;
  int m_numRebuilt = 0;
  double m_lastBuildMilliseconds = 0.0;
};

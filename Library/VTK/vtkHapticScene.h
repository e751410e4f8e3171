// vtkHapticScene: the haptic scene as a pipeline sink. Each input connection is one object
// (vtkPolyData) with its own scale, pose and material; executing builds the kernel's
// CollisionScene from them, an immutable snapshot that vtkHapticRenderer hands to the haptic
// threads. Editing an input's poly data, a pose transform or a material marks the scene modified,
// and the next Update rebuilds only the objects that changed and makes a new snapshot (a new
// version) that shares every unchanged object with the old one; the haptic threads keep running
// on the old one until the new one is complete. With BackgroundBuild on, the trees are built on
// the scene's worker thread and Update returns as soon as the poly data is converted.
//
// The output is the scene's surface as the proxy feels it (every object scaled and placed, one
// poly data, cell data "ObjectId"), for drawing.
#pragma once

#include "Proxy/CollisionScene.h"

#include <vtkPolyDataAlgorithm.h>
#include <vtkSmartPointer.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

class vtkLinearTransform;

class vtkHapticScene : public vtkPolyDataAlgorithm
{
public:
  static vtkHapticScene* New();
  vtkTypeMacro(vtkHapticScene, vtkPolyDataAlgorithm) void PrintSelf(ostream& os,
                                                                    vtkIndent indent) override;

  /// Adds an object: returns its index (the input connection's). Same as AddInputConnection.
  int AddObject(vtkAlgorithmOutput* polyData);
  /// Adds an object from a data set (wrapped in a trivial producer); editing `polyData` and
  /// calling its Modified() rebuilds the object at the next Update. AddObject(vtkPolyData*) is
  /// the same, for callers (VTK's Python) that pass a data set where a connection also goes.
  int AddObjectData(vtkPolyData* polyData);
  int AddObject(vtkPolyData* polyData);
  int GetNumberOfObjects();

  // The per-object setters refuse (vtkErrorMacro, no change) an index that is not an object's:
  // below 0, or not yet added.

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
  /// Build each changed object's sphere tree on every hardware thread (default on; off builds
  /// it on one). The tree is the same bit for bit either way (SphereTreeOptions::numBuildThreads).
  vtkSetMacro(ParallelTreeBuild, vtkTypeBool);
  vtkGetMacro(ParallelTreeBuild, vtkTypeBool);
  vtkBooleanMacro(ParallelTreeBuild, vtkTypeBool);
  ///@}

  ///@{
  /// Build the changed objects' trees on the scene's worker thread (default off). Off, Update
  /// returns with the new snapshot made. On, Update checks and converts the changed poly data
  /// (the part that touches VTK, on the calling thread), starts the tree builds and returns; the
  /// new snapshot replaces the old one when every tree is built (GetSceneVersion rises, and
  /// vtkHapticRenderer::UpdateScene publishes it at its next call). The haptic threads run on
  /// the old scene meanwhile. One build at a time: an Update that executes the scene while a
  /// build runs waits for it first. The output surface is made from the new meshes at once.
  vtkSetMacro(BackgroundBuild, vtkTypeBool);
  vtkGetMacro(BackgroundBuild, vtkTypeBool);
  vtkBooleanMacro(BackgroundBuild, vtkTypeBool);
  ///@}

  /// True while a background build runs.
  bool IsBuilding() const;
  /// Waits for a background build to finish and takes its objects. False if it failed (an
  /// error is reported, the previous scene stays, and the next Update tries again).
  bool WaitForBuild();

  ///@{
  /// Make the output surface (default on). Off saves a copy of every mesh per rebuild where
  /// nothing draws the scene's own output.
  vtkSetMacro(GenerateSurface, vtkTypeBool);
  vtkGetMacro(GenerateSurface, vtkTypeBool);
  vtkBooleanMacro(GenerateSurface, vtkTypeBool);
  ///@}

  /// The last snapshot built (null before the first successful Update). Immutable: the haptic
  /// threads may hold it while a newer one is built. These three may be read while a background
  /// build runs.
  std::shared_ptr<const proxima::CollisionScene> GetCollisionScene() const;
  /// 1 for the first snapshot, then +1 for each rebuilt one (0 before the first).
  vtkTypeUInt64 GetSceneVersion() const;
  /// Wall time in milliseconds from the start of the execution that made the last snapshot to
  /// the snapshot complete.
  double GetLastBuildMilliseconds() const;
  /// Objects the last execution rebuilt (or, with a background build, is rebuilding).
  int GetNumberOfObjectsRebuilt() const { return m_numRebuilt; }

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
  vtkTypeBool BackgroundBuild = 0;

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
    // The object in the newest snapshot, and what it was built from.
    std::shared_ptr<const proxima::CollisionObject> built;
    vtkDataObject* builtFrom = nullptr;
    vtkMTimeType builtFromTime = 0;
    vtkMTimeType builtPoseTime = 0;
    std::uint64_t builtSettingsVersion = 0;
    double builtLeafSizeFactor = -1.0;
    int builtMaxLeafSpheres = 0;
  };
  /// The entry of an object, or null (with an error naming `setter`) for an index that is not
  /// an object's.
  ObjectEntry* Entry(int object, const char* setter);
  const ObjectEntry* FindEntry(int object) const;

  /// One execution's tree builds and the snapshot they make (defined in the .cpp).
  struct Build;
  /// Builds the trees and publishes the snapshot: on the worker thread, or inline.
  void RunBuild(Build& build);
  /// Joins the worker and takes the objects of its build into the entries; false (and an
  /// error) if the build failed.
  bool FinishBuild();

  std::vector<ObjectEntry> m_objects;
  int m_numRebuilt = 0;
  std::unique_ptr<Build> m_build;
  std::thread m_worker;
  // What the worker writes and the render thread reads.
  mutable std::mutex m_sceneMutex;
  std::shared_ptr<const proxima::CollisionScene> m_scene;
  std::uint64_t m_sceneVersion = 0;
  double m_lastBuildMilliseconds = 0.0;
};

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

/// The haptic scene as a pipeline sink: each input connection is one object with its own scale,
/// pose and material, and executing builds the kernel's CollisionScene from them, rebuilding only
/// the objects that changed. The output is the scene's surface as the proxy feels it, for drawing.
class vtkHapticScene : public vtkPolyDataAlgorithm
{
public:
  /// A new scene, with no objects.
  static vtkHapticScene* New();
  /// Prints the properties, the scene version and each object's settings.
  vtkTypeMacro(vtkHapticScene, vtkPolyDataAlgorithm) void PrintSelf(ostream& os,
                                                                    vtkIndent indent) override;

  /// Adds an object: returns its index (the input connection's). Same as AddInputConnection.
  int AddObject(vtkAlgorithmOutput* polyData);
  /// Adds an object from a data set (wrapped in a trivial producer); editing `polyData` and
  /// calling its Modified() rebuilds the object at the next Update. AddObject(vtkPolyData*) is
  /// the same, for callers (VTK's Python) that pass a data set where a connection also goes.
  int AddObjectData(vtkPolyData* polyData);
  /// Adds an object from a data set: the same as AddObjectData.
  int AddObject(vtkPolyData* polyData);
  /// The objects added (the input connections).
  int GetNumberOfObjects();

  // The per-object setters refuse (vtkErrorMacro, no change) an index that is not an object's:
  // below 0, or not yet added.

  ///@{
  /// Per object: units to metres (default 1).
  void SetObjectScale(int object, double scale);
  /// An object's scale (1 for an index that is not an object's).
  double GetObjectScale(int object) const;
  ///@}

  ///@{
  /// Per object: a rigid pose (rotation and translation; null for none, the default). The
  /// transform is watched: modifying it rebuilds the object at the next Update.
  void SetObjectPose(int object, vtkLinearTransform* pose);
  /// An object's pose (null for none, or for an index that is not an object's).
  vtkLinearTransform* GetObjectPose(int object) const;
  ///@}

  ///@{
  /// Per object: static and dynamic friction coefficients and viscosity in N s/m (default 0:
  /// none), and force shading from the poly data's point normals, made with a 30 degree feature
  /// angle when it has none (default off).
  void SetObjectFriction(int object, double staticFriction, double dynamicFriction,
                         double viscosity);
  /// Per object: force shading on or off (default off).
  void SetObjectShading(int object, bool shading);
  ///@}

  ///@{
  /// Tree option for every object: SphereTreeOptions::leafSizeFactor (default 2; 0 gives one
  /// leaf sphere per triangle). Changing it rebuilds every object at the next Update.
  vtkSetClampMacro(LeafSizeFactor, double, 0.0, 1e6);
  /// SphereTreeOptions::leafSizeFactor of every object.
  vtkGetMacro(LeafSizeFactor, double);
  /// Tree option for every object: SphereTreeOptions::maxLeafSpheresPerNode (default 4; 1 is
  /// the paper's tree exactly). Changing it rebuilds every object at the next Update.
  vtkSetClampMacro(MaxLeafSpheresPerNode, int, 1, 64);
  /// SphereTreeOptions::maxLeafSpheresPerNode of every object.
  vtkGetMacro(MaxLeafSpheresPerNode, int);
  ///@}

  ///@{
  /// Build each changed object's sphere tree on every hardware thread (default on; off builds
  /// it on one). The tree is the same bit for bit either way (SphereTreeOptions::numBuildThreads).
  vtkSetMacro(ParallelTreeBuild, vtkTypeBool);
  /// Whether the trees are built on every hardware thread.
  vtkGetMacro(ParallelTreeBuild, vtkTypeBool);
  /// Builds the trees on every hardware thread.
  vtkBooleanMacro(ParallelTreeBuild, vtkTypeBool);
  /// \fn void vtkHapticScene::ParallelTreeBuildOff()
  /// Builds each tree on one thread.
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
  /// Whether the trees are built on the scene's worker thread.
  vtkGetMacro(BackgroundBuild, vtkTypeBool);
  /// Builds the trees on the scene's worker thread.
  vtkBooleanMacro(BackgroundBuild, vtkTypeBool);
  /// \fn void vtkHapticScene::BackgroundBuildOff()
  /// Builds the trees within Update.
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
  /// Whether the output surface is made.
  vtkGetMacro(GenerateSurface, vtkTypeBool);
  /// Makes the output surface.
  vtkBooleanMacro(GenerateSurface, vtkTypeBool);
  /// \fn void vtkHapticScene::GenerateSurfaceOff()
  /// Makes no output surface.
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

  /// The one input port takes any number of vtkPolyData connections, one per object.
  int FillInputPortInformation(int port, vtkInformation* info) override;
  /// Rebuilds the changed objects and makes the new snapshot (or starts its background build)
  /// and the output surface. Fails, keeping the previous scene, for no objects or an object
  /// that cannot be built.
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double LeafSizeFactor = 2.0;       ///< The trees' leaf size factor: SetLeafSizeFactor.
  int MaxLeafSpheresPerNode = 4;     ///< Leaf spheres per leaf node: SetMaxLeafSpheresPerNode.
  vtkTypeBool GenerateSurface = 1;   ///< Make the output surface: SetGenerateSurface.
  vtkTypeBool ParallelTreeBuild = 1; ///< Trees on every hardware thread: SetParallelTreeBuild.
  vtkTypeBool BackgroundBuild = 0;   ///< Trees on the worker thread: SetBackgroundBuild.

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

// The soft block the real-time tissue tests press (threads, the VTK source, the mouse finger):
// 4 x 4 x 2 cm with its top at z = 0, 5 kPa, fixed along its base, stepping at 200 Hz. One
// definition, so the three tests press the same solid.
#pragma once

#include "Core/Vec3.h"
#include "Proxy/CollisionScene.h"
#include "Tissue/BoxTetMesh.h"
#include "Tissue/TetBoundary.h"
#include "Tissue/TissueDynamics.h"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace proxima::testing_support
{

/// The block's tetrahedra: `cellsAcross` cells along x and y, half as many along z.
inline TetMesh softBlockTets(int cellsAcross)
{
  return makeBoxTetMesh(Vec3{-0.02, -0.02, -0.02}, Vec3{0.02, 0.02, 0.0}, cellsAcross, cellsAcross,
                        cellsAcross / 2);
}

/// A scene whose one object is the block's surface (boundarySoup of softBlockTets).
inline std::shared_ptr<const CollisionScene> softBlockScene(int cellsAcross)
{
  auto scene = std::make_shared<CollisionScene>();
  TriangleMesh surface;
  MeshError error;
  if (!surface.build(boundarySoup(softBlockTets(cellsAcross)), error))
  {
    throw std::runtime_error("the soft block's surface: " + error.message);
  }
  scene->addObject(std::move(surface));
  return scene;
}

/// The block as object 0's tissue: 5 kPa, nu = 0.45, damping 20/s, a 5 ms step, its base fixed;
/// `stiffness` is the servo's kp (N/m) and `rate` its tick rate (Hz).
inline std::shared_ptr<TissueDynamics> softBlockDynamics(int cellsAcross, double stiffness,
                                                         double rate)
{
  TissueObject tissue;
  tissue.object = 0;
  tissue.tets = softBlockTets(cellsAcross);
  tissue.materials.assign(tissue.tets.tets.size(), ElasticMaterial{5000.0, 0.45});
  tissue.settings.timeStep = 0.005;
  tissue.settings.damping = 20.0;
  for (std::uint32_t v = 0; v < tissue.tets.points.size(); ++v)
  {
    if (tissue.tets.points[v].z < -0.02 + 1e-9)
    {
      tissue.fixedVertices.push_back(v);
    }
  }
  std::vector<TissueObject> tissues;
  tissues.push_back(std::move(tissue));
  return std::make_shared<TissueDynamics>(std::move(tissues), stiffness, rate);
}

} // namespace proxima::testing_support

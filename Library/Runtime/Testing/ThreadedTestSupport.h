// What the threaded runtime's tests share: a scene the runtime can keep alive, and a wait for a
// state of the real-time threads that polls rather than sleeps a guessed time.
#pragma once

#include "Geometry/TriangleSoup.h"
#include "Proxy/CollisionScene.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>
#include <thread>
#include <utility>

namespace proxima::testing_support
{

/// A one-object scene of `soup`, shared as the runtime holds scenes.
inline std::shared_ptr<const CollisionScene> makeSharedScene(TriangleSoup soup)
{
  auto scene = std::make_shared<CollisionScene>();
  TriangleMesh mesh;
  MeshError error;
  EXPECT_TRUE(mesh.build(std::move(soup), error)) << error.message;
  scene->addObject(std::move(mesh));
  return scene;
}

/// Waits up to `limit` for `condition`, polling every millisecond.
inline bool waitFor(const std::function<bool()>& condition, std::chrono::milliseconds limit)
{
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end)
  {
    if (condition())
    {
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return condition();
}

} // namespace proxima::testing_support

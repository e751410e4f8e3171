#include "IO/Mesh/MeshFileFormat.h"

#include <gtest/gtest.h>

using proxima::MeshFileFormat;
using proxima::meshFileFormatFromPath;

TEST(MeshFileFormat, ChosenByExtensionIgnoringCase)
{
  EXPECT_EQ(meshFileFormatFromPath("a/b/featuretype.STL"), MeshFileFormat::Stl);
  EXPECT_EQ(meshFileFormatFromPath("bunny.obj"), MeshFileFormat::Obj);
  EXPECT_EQ(meshFileFormatFromPath("Bunny.Obj"), MeshFileFormat::Obj);
  EXPECT_EQ(meshFileFormatFromPath("cranium.ply"), MeshFileFormat::Ply);
  EXPECT_EQ(meshFileFormatFromPath("angel.vtp"), MeshFileFormat::Vtp);
  EXPECT_EQ(meshFileFormatFromPath("liver.glb"), MeshFileFormat::Gltf);
  EXPECT_EQ(meshFileFormatFromPath("liver.GLTF"), MeshFileFormat::Gltf);
  EXPECT_EQ(meshFileFormatFromPath("fandisk.off"), MeshFileFormat::Off);
}

TEST(MeshFileFormat, UnknownOrMissingExtensionIsNothing)
{
  EXPECT_FALSE(meshFileFormatFromPath("mesh.xyz").has_value());
  EXPECT_FALSE(meshFileFormatFromPath("mesh").has_value());
  EXPECT_FALSE(meshFileFormatFromPath("dir.obj/mesh").has_value());
  EXPECT_FALSE(meshFileFormatFromPath(".obj.bak").has_value());
}

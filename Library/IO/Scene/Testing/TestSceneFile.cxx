// readSceneFile on scene files this test writes: a file using every key comes back as the
// description it spells out, omitted keys take their documented defaults, and each kind of bad
// file is refused with one line naming the scene file, the JSON location and the defect.
#include "IO/Scene/SceneFile.h"

#include "IO/Testing/ScratchFolderTest.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using proxima::SceneDescription;
using proxima::SceneShading;
using proxima::TextureChannel;
using proxima::TextureRole;

class SceneFile : public proxima::testing_support::ScratchFolderTest
{
protected:
  SceneFile()
    : ScratchFolderTest("proxima-scene-")
  {}

  /// Expects readSceneFile(path) to throw an InputError whose one-line message is
  /// "<path>: <expected>" exactly.
  static void expectRefused(const std::string& path, const std::string& expected)
  {
    std::string message;
    try
    {
      (void)proxima::readSceneFile(path);
    }
    catch (const proxima::InputError& error)
    {
      message = error.what();
      EXPECT_EQ(error.path(), path);
    }
    ASSERT_FALSE(message.empty()) << path << " was accepted";
    EXPECT_EQ(message, path + ": " + expected);
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }

  /// Like expectRefused, for messages whose tail comes from a library: the message starts with
  /// "<path>: <expectedStart>".
  static void expectRefusedStartingWith(const std::string& path, const std::string& expectedStart)
  {
    std::string message;
    try
    {
      (void)proxima::readSceneFile(path);
    }
    catch (const proxima::InputError& error)
    {
      message = error.what();
    }
    ASSERT_FALSE(message.empty()) << path << " was accepted";
    EXPECT_TRUE(message.starts_with(path + ": " + expectedStart)) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }

  /// A scene of one object `{"mesh": "m.obj", <extra>}`.
  std::string oneObject(const std::string& name, const std::string& extra) const
  {
    return write(name,
                 R"({"objects": [{"mesh": "m.obj")" + (extra.empty() ? "" : ", " + extra) + "}]}");
  }
};

TEST_F(SceneFile, EveryKeyRoundTripsIntoTheDescription)
{
  const std::string absoluteMesh = (m_dir / "elsewhere" / "b.stl").string();
  const std::string path = write("full.json", R"({
  "version": 1,
  "objects": [
    {
      "mesh": "meshes/a.obj",
      "scale": 0.001,
      "pose": {
        "translation": [0.1, -0.2, 0.3],
        "rotation": {"axis_angle_deg": [0, 0, 2, 90]}
      },
      "material": {
        "shading": "on",
        "feature_angle_deg": 45,
        "static_friction": 0.5,
        "dynamic_friction": 0.3,
        "viscosity": 2,
        "textures": [
          {"image": "textures/bumps.png", "role": "bump", "amplitude": 0.0002, "channel": "red"},
          {"image": "rough.exr", "role": "friction"},
          {"image": "sticky.tif", "role": "viscosity", "channel": "alpha"}
        ]
      }
    },
    {
      "mesh": ")" + absoluteMesh + R"(",
      "pose": {"rotation": {"quaternion": [0.7071, 0, 0.7071, 0]}},
      "material": {"shading": "auto"}
    }
  ]
})");
  const SceneDescription scene = proxima::readSceneFile(path);
  EXPECT_EQ(scene.path, path);
  EXPECT_EQ(scene.version, 1);
  ASSERT_EQ(scene.objects.size(), 2u);

  const proxima::SceneObject& a = scene.objects[0];
  EXPECT_EQ(a.mesh, (m_dir / "meshes/a.obj").string()); // relative to the scene's folder
  EXPECT_EQ(a.scale, 0.001);
  EXPECT_EQ(a.pose.translation, (proxima::Vec3{0.1, -0.2, 0.3}));
  // 90 degrees about z (the axis's length does not matter): w = cos 45, z = sin 45.
  EXPECT_NEAR(a.pose.rotation.w, std::sqrt(0.5), 2e-16);
  EXPECT_EQ(a.pose.rotation.x, 0.0);
  EXPECT_EQ(a.pose.rotation.y, 0.0);
  EXPECT_NEAR(a.pose.rotation.z, std::sqrt(0.5), 2e-16);
  EXPECT_EQ(a.material.shading, SceneShading::On);
  EXPECT_EQ(a.material.featureAngleDegrees, 45.0);
  EXPECT_EQ(a.material.staticFriction, 0.5);
  EXPECT_EQ(a.material.dynamicFriction, 0.3);
  EXPECT_EQ(a.material.viscosity, 2.0);
  ASSERT_EQ(a.material.textures.size(), 3u);
  EXPECT_EQ(a.material.textures[0].image, (m_dir / "textures/bumps.png").string());
  EXPECT_EQ(a.material.textures[0].role, TextureRole::Bump);
  EXPECT_EQ(a.material.textures[0].amplitude, 0.0002);
  EXPECT_EQ(a.material.textures[0].channel, TextureChannel::Red);
  EXPECT_EQ(a.material.textures[1].image, (m_dir / "rough.exr").string());
  EXPECT_EQ(a.material.textures[1].role, TextureRole::Friction);
  EXPECT_EQ(a.material.textures[1].amplitude, 0.0);
  EXPECT_EQ(a.material.textures[1].channel, TextureChannel::Luminance);
  EXPECT_EQ(a.material.textures[2].role, TextureRole::Viscosity);
  EXPECT_EQ(a.material.textures[2].channel, TextureChannel::Alpha);

  const proxima::SceneObject& b = scene.objects[1];
  EXPECT_EQ(b.mesh, absoluteMesh); // absolute paths stay as written
  EXPECT_EQ(b.scale, 1.0);
  EXPECT_EQ(b.pose.translation, proxima::Vec3{});
  // A rounded quaternion is normalised.
  const proxima::UnitQuaternion& q = b.pose.rotation;
  EXPECT_NEAR(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z, 1.0, 1e-15);
  EXPECT_NEAR(q.w, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(q.y, std::sqrt(0.5), 1e-15);
  EXPECT_EQ(b.material.shading, SceneShading::Auto);
  EXPECT_TRUE(b.material.textures.empty());
}

TEST_F(SceneFile, OmittedKeysTakeTheirDefaults)
{
  const SceneDescription scene =
    proxima::readSceneFile(write("minimal.json", R"({"objects": [{"mesh": "m.obj"}]})"));
  ASSERT_EQ(scene.objects.size(), 1u);
  const proxima::SceneObject& object = scene.objects[0];
  EXPECT_EQ(scene.version, 1);
  EXPECT_EQ(object.scale, 1.0);
  EXPECT_TRUE(object.pose.isIdentity());
  EXPECT_EQ(object.material.shading, SceneShading::Off);
  EXPECT_EQ(object.material.featureAngleDegrees, 30.0);
  EXPECT_EQ(object.material.staticFriction, 0.0);
  EXPECT_EQ(object.material.dynamicFriction, 0.0);
  EXPECT_EQ(object.material.viscosity, 0.0);
  EXPECT_TRUE(object.material.textures.empty());
}

TEST_F(SceneFile, AxisAngleOfWholeTurnsIsTheIdentityExactly)
{
  const SceneDescription scene = proxima::readSceneFile(write(
    "turns.json",
    R"({"objects": [{"mesh": "m.obj", "pose": {"rotation": {"axis_angle_deg": [1, 2, 3, 720]}}}]})"));
  EXPECT_TRUE(scene.objects[0].pose.isIdentity());
}

TEST_F(SceneFile, ScenePathWithoutFolderKeepsRelativeMeshPaths)
{
  // A scene named without a folder: its meshes are relative to the working directory, as it is.
  const fs::path previous = fs::current_path();
  fs::current_path(m_dir);
  write("here.json", R"({"objects": [{"mesh": "m.obj"}]})");
  const SceneDescription scene = proxima::readSceneFile("here.json");
  fs::current_path(previous);
  EXPECT_EQ(scene.objects[0].mesh, "m.obj");
}

// The file itself.

TEST_F(SceneFile, MissingFile)
{
  expectRefused((m_dir / "absent.json").string(),
                "cannot open the file (No such file or directory)");
}

TEST_F(SceneFile, Directory)
{
  expectRefused(m_dir.string(), "is a directory, not a scene file");
}

TEST_F(SceneFile, EmptyFile)
{
  expectRefused(write("empty.json", ""), "the file is empty");
}

TEST_F(SceneFile, NotJsonSaysLineAndColumn)
{
  expectRefusedStartingWith(
    write("truncated.json", "{\n  \"objects\": [\n    {\"mesh\": \"m.obj\"},\n"),
    "not valid JSON: line 4, column 1: syntax error");
}

TEST_F(SceneFile, AMeshFileIsNotJson)
{
  expectRefusedStartingWith(write("mesh.json", "v 0 0 0\nv 1 0 0\n"),
                            "not valid JSON: line 1, column 1: syntax error");
}

TEST_F(SceneFile, NumberTooLargeForADouble)
{
  expectRefusedStartingWith(oneObject("huge.json", R"("scale": 1e400)"),
                            "not valid JSON: number overflow");
}

// The top level.

TEST_F(SceneFile, TopLevelNotAnObject)
{
  expectRefused(write("array.json", R"([{"mesh": "m.obj"}])"),
                R"(top level: must be a JSON object {...}, got [{"mesh":"m.obj"}])");
}

TEST_F(SceneFile, MissingObjects)
{
  expectRefused(write("none.json", R"({"version": 1})"),
                R"(top level: missing the required key "objects")");
}

TEST_F(SceneFile, EmptyObjects)
{
  expectRefused(write("zero.json", R"({"objects": []})"),
                "objects: must be an array of at least one object, got []");
}

TEST_F(SceneFile, UnknownTopLevelKeySuggestsTheNearOne)
{
  expectRefused(write("typo.json", R"({"object": [{"mesh": "m.obj"}]})"),
                R"(object: unknown key (did you mean "objects"?))");
}

TEST_F(SceneFile, UnsupportedVersion)
{
  // Reported before the unknown key a newer version might bring.
  expectRefused(write("v4.json", R"({"version": 4, "lights": [], "objects": [{"mesh": "m.obj"}]})"),
                "version: must be 1, 2 or 3 (the scene file versions this program reads), got 4");
  expectRefused(write("v2.5.json", R"({"version": 2.5, "objects": [{"mesh": "m.obj"}]})"),
                "version: must be 1, 2 or 3 (the scene file versions this program reads), got 2.5");
}

/// A version 3 scene of one object `{"mesh": "m.obj", "tissue": <tissue>}`.
static std::string tissueScene(const std::string& tissue, int version = 3)
{
  return R"({"version": )" + std::to_string(version) +
         R"(, "objects": [{"mesh": "m.obj", "tissue": )" + tissue + "}]}";
}

TEST_F(SceneFile, TissueComesBackAsWritten)
{
  const std::string path = write(
    "tissue.json", tissueScene(R"({"youngs_modulus": 4000, "poisson_ratio": 0.4, "density": 1060,
                    "damping": 15, "tet_size": 0.006,
                    "fixed": {"box": [[-1, -1, -1], [1, 1, -0.05]]},
                    "inclusions": [{"center": [0.07, 0.3, 0.0], "radius": 0.01,
                                    "youngs_modulus": 40000}]})"));
  const SceneDescription scene = proxima::readSceneFile(path);
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.version, 3);
  EXPECT_TRUE(scene.hasTissue());
  EXPECT_FALSE(scene.hasBodies());
  const proxima::SceneTissue& tissue = scene.objects[0].tissue;
  EXPECT_EQ(tissue.youngsModulus, 4000.0);
  EXPECT_EQ(tissue.poissonRatio, 0.4);
  EXPECT_EQ(tissue.density, 1060.0);
  EXPECT_EQ(tissue.damping, 15.0);
  EXPECT_EQ(tissue.tetSize, 0.006);
  EXPECT_TRUE(tissue.tets.empty());
  EXPECT_EQ(tissue.fixedLow, (proxima::Vec3{-1.0, -1.0, -1.0}));
  EXPECT_EQ(tissue.fixedHigh, (proxima::Vec3{1.0, 1.0, -0.05}));
  ASSERT_EQ(tissue.inclusions.size(), 1u);
  EXPECT_EQ(tissue.inclusions[0].center, (proxima::Vec3{0.07, 0.3, 0.0}));
  EXPECT_EQ(tissue.inclusions[0].radius, 0.01);
  EXPECT_EQ(tissue.inclusions[0].youngsModulus, 40000.0);

  // The defaults, and a .vtu file resolved against the scene's folder.
  const SceneDescription plain = proxima::readSceneFile(
    write("plain.json", tissueScene(R"({"youngs_modulus": 3000, "tets": "t.vtu",
                                        "fixed": {"box": [[0, 0, 0], [1, 1, 1]]}})")));
  const proxima::SceneTissue& defaults = plain.objects[0].tissue;
  EXPECT_EQ(defaults.poissonRatio, 0.45);
  EXPECT_EQ(defaults.density, 1000.0);
  EXPECT_EQ(defaults.damping, 1.0);
  EXPECT_EQ(fs::path(defaults.tets).filename(), "t.vtu");
  EXPECT_TRUE(fs::path(defaults.tets).is_absolute() ||
              defaults.tets.find(fs::path(path).parent_path().string()) == 0);
  EXPECT_TRUE(defaults.inclusions.empty());
}

TEST_F(SceneFile, BadTissueIsRefusedWhereItIs)
{
  const std::string fixed = R"("fixed": {"box": [[0, 0, 0], [1, 1, 1]]})";
  expectRefused(
    write("v2.json",
          tissueScene(R"({"youngs_modulus": 3000, "tet_size": 0.005, )" + fixed + "}", 2)),
    "objects[0].tissue: tissue needs \"version\": 3 at the top level (this file "
    "reads as version 2)");
  expectRefused(write("both.json",
                      R"({"version": 3, "objects": [{"mesh": "m.obj",
                          "body": {"joint": {"type": "free"}, "density": 1000},
                          "tissue": {"youngs_modulus": 3000, "tet_size": 0.005, )" +
                        fixed + "}}]}"),
                "objects[0].tissue: an object is either a rigid body or tissue, not both");
  // Nor a body and tissue on two objects: no runner steps both (a lever beside a kidney stood
  // still under the finger's press).
  expectRefused(write("bodies-and-tissue.json",
                      R"({"version": 3, "objects": [{"mesh": "m.obj",
                          "body": {"joint": {"type": "free"}, "density": 1000}},
                          {"mesh": "m.obj", "tissue": {"youngs_modulus": 3000,
                          "tet_size": 0.005, )" +
                        fixed + "}}]}"),
                "objects[1].tissue: a scene has bodies or tissue, not both yet (this one has "
                "bodies too): no runner steps rigid bodies and elastic solids together");
  expectRefused(write("shaded.json",
                      R"({"version": 3, "objects": [{"mesh": "m.obj",
                          "material": {"shading": "on"},
                          "tissue": {"youngs_modulus": 3000, "tet_size": 0.005, )" +
                        fixed + "}}]}"),
                "objects[0].material.shading: tissue is not shaded (its surface is remade from "
                "the tetrahedra)");
  expectRefused(write("no-size.json", tissueScene(R"({"youngs_modulus": 3000, )" + fixed + "}")),
                "objects[0].tissue: needs one of \"tet_size\" (m: the mesh is wrapped and "
                "filled) and \"tets\" (a .vtu file of tetrahedra)");
  expectRefused(
    write("two-sizes.json",
          tissueScene(R"({"youngs_modulus": 3000, "tet_size": 0.005, "tets": "t.vtu", )" + fixed +
                      "}")),
    "objects[0].tissue: takes only one of \"tet_size\" (m: the mesh is wrapped and filled) and "
    "\"tets\" (a .vtu file of tetrahedra)");
  expectRefused(
    write("no-fixed.json", tissueScene(R"({"youngs_modulus": 3000, "tet_size": 0.005})")),
    "objects[0].tissue: missing the required key \"fixed\"");
  expectRefused(write("flat-box.json", tissueScene(R"({"youngs_modulus": 3000, "tet_size": 0.005,
                                      "fixed": {"box": [[0, 0, 1], [1, 1, 0]]}})")),
                "objects[0].tissue.fixed.box: the first corner must be below the second on every "
                "axis, got [[0,0,1],[1,1,0]]");
  expectRefused(write("nu.json", tissueScene(R"({"youngs_modulus": 3000, "poisson_ratio": 0.5,
                                                 "tet_size": 0.005, )" +
                                             fixed + "}")),
                "objects[0].tissue.poisson_ratio: must be a number from 0 to 0.499, got 0.5");
  expectRefused(
    write("e.json", tissueScene(R"({"youngs_modulus": -5, "tet_size": 0.005, )" + fixed + "}")),
    "objects[0].tissue.youngs_modulus: must be a number above 0 and at most 1e+09 Pa, got -5");
  expectRefused(write("inclusion.json",
                      tissueScene(R"({"youngs_modulus": 3000, "tet_size": 0.005, )" + fixed +
                                  R"(, "inclusions": [{"center": [0, 0, 0], "radius": 0.01}]})")),
                "objects[0].tissue.inclusions[0]: missing the required key \"youngs_modulus\"");
  expectRefused(write("typo.json", tissueScene(R"({"youngs_modulus": 3000, "tet_size": 0.005,
                                                   "dampin": 3, )" +
                                               fixed + "}")),
                "objects[0].tissue.dampin: unknown key (did you mean \"damping\"?)");
}

/// A version 2 scene of one object `{"mesh": "m.obj", "body": <body>}`.
static std::string bodyScene(const std::string& body)
{
  return R"({"version": 2, "objects": [{"mesh": "m.obj", "body": )" + body + "}]}";
}

TEST_F(SceneFile, BodyKeysRoundTripIntoTheDescription)
{
  const proxima::SceneDescription scene = proxima::readSceneFile(
    write("lever.json", R"({"version": 2, "gravity": [0, 0, -9.81], "objects": [)"
                        R"({"mesh": "m.obj"}, {"mesh": "m.obj", "body": {"joint": )"
                        R"({"type": "hinge", "axis": [1, 0, 0], "anchor": [0, -0.1, 0.5], )"
                        R"("range": [-0.5, 0.25], "stiffness": 2, "damping": 0.1}, )"
                        R"("density": 1000}}]})"));
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_FALSE(scene.objects[0].hasBody);
  EXPECT_TRUE(scene.hasBodies());
  EXPECT_EQ(scene.gravity.z, -9.81);
  const proxima::SceneBody& body = scene.objects[1].body;
  EXPECT_EQ(body.joint, proxima::SceneJoint::Hinge);
  EXPECT_EQ(body.axis.x, 1.0);
  EXPECT_EQ(body.anchor.y, -0.1);
  EXPECT_EQ(body.anchor.z, 0.5);
  EXPECT_TRUE(body.limited);
  EXPECT_EQ(body.range[0], -0.5);
  EXPECT_EQ(body.range[1], 0.25);
  EXPECT_EQ(body.stiffness, 2.0);
  EXPECT_EQ(body.damping, 0.1);
  EXPECT_EQ(body.density, 1000.0);
  EXPECT_EQ(body.mass, 0.0);
  const proxima::SceneDescription free = proxima::readSceneFile(
    write("free.json", bodyScene(R"({"joint": {"type": "free"}, "mass": 0.3})")));
  EXPECT_EQ(free.objects[0].body.joint, proxima::SceneJoint::Free);
  EXPECT_EQ(free.objects[0].body.mass, 0.3);
}

// An axis is a direction of any length but zero: one whose squared norm overflows or underflows
// is read as its unit direction, for a joint and for a rotation, rather than as no direction
// (which gave a hinge that never moved, or a rotation refused as about no axis).
TEST_F(SceneFile, AxesOfAnyLengthAreTheirDirections)
{
  const auto jointAxis = [&](const std::string& name, const std::string& axis) {
    return proxima::readSceneFile(write(name, bodyScene(R"({"joint": {"type": "hinge", "axis": )" +
                                                        axis + R"(}, "mass": 1})")))
      .objects[0]
      .body.axis;
  };
  const proxima::Vec3 huge = jointAxis("huge.json", "[1e300, 1e300, 0]");
  EXPECT_DOUBLE_EQ(huge.x, std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(huge.y, std::sqrt(0.5));
  EXPECT_EQ(huge.z, 0.0);
  const proxima::Vec3 tiny = jointAxis("tiny.json", "[0, 0, -1e-300]");
  EXPECT_EQ(tiny.x, 0.0);
  EXPECT_EQ(tiny.y, 0.0);
  EXPECT_EQ(tiny.z, -1.0);
  const proxima::Vec3 plain = jointAxis("plain.json", "[0, 3, 4]");
  EXPECT_DOUBLE_EQ(plain.y, 0.6);
  EXPECT_DOUBLE_EQ(plain.z, 0.8);
  for (const char* axis : {"1e300, 1e300, 0", "1e-300, 1e-300, 0"})
  {
    const SceneDescription scene = proxima::readSceneFile(
      write("turned.json", std::string(R"({"objects": [{"mesh": "m.obj", "pose": {"rotation": )"
                                       R"({"axis_angle_deg": [)") +
                             axis + R"(, 90]}}}]})"));
    const proxima::UnitQuaternion& rotation = scene.objects[0].pose.rotation;
    EXPECT_DOUBLE_EQ(rotation.w, std::sqrt(0.5)) << axis;
    EXPECT_DOUBLE_EQ(rotation.x, 0.5) << axis;
    EXPECT_DOUBLE_EQ(rotation.y, 0.5) << axis;
    EXPECT_EQ(rotation.z, 0.0) << axis;
  }
}

TEST_F(SceneFile, BodyRefusals)
{
  expectRefused(write("v1.json", R"({"objects": [{"mesh": "m.obj", "body": {}}]})"),
                "objects[0].body: bodies need \"version\": 2 at the top level (this file reads "
                "as version 1)");
  expectRefused(write("g1.json", R"({"gravity": [0, 0, -9.81], "objects": [{"mesh": "m.obj"}]})"),
                "gravity: bodies need \"version\": 2 at the top level (this file reads as "
                "version 1)");
  expectRefused(
    write("type.json", bodyScene(R"({"joint": {"type": "pivot"}, "mass": 1})")),
    R"(objects[0].body.joint.type: must be "hinge", "slide", "ball" or "free", got "pivot")");
  expectRefused(write("axis.json", bodyScene(R"({"joint": {"type": "hinge"}, "mass": 1})")),
                R"(objects[0].body.joint: missing the required key "axis")");
  expectRefused(
    write("zero.json", bodyScene(R"({"joint": {"type": "slide", "axis": [0, 0, 0]}, "mass": 1})")),
    "objects[0].body.joint.axis: must not be zero");
  expectRefused(
    write("ballaxis.json",
          bodyScene(R"({"joint": {"type": "ball", "axis": [0, 0, 1]}, "mass": 1})")),
    "objects[0].body.joint.axis: a ball joint takes no axis (only hinge and slide joints have an "
    "axis)");
  expectRefused(write("freeanchor.json",
                      bodyScene(R"({"joint": {"type": "free", "anchor": [0, 0, 0]}, "mass": 1})")),
                "objects[0].body.joint.anchor: a free joint takes no anchor (a free body turns "
                "about its centre of mass)");
  expectRefused(write("range.json", bodyScene(R"({"joint": {"type": "hinge", "axis": [1, 0, 0], )"
                                              R"("range": [1, -1]}, "mass": 1})")),
                "objects[0].body.joint.range: must be [low, high] with low below high, got [1,-1]");
  expectRefused(write("both.json", bodyScene(R"({"joint": {"type": "free"}, "mass": 1, )"
                                             R"("density": 1000})")),
                R"(objects[0].body: takes only one of "density" (kg/m^3) and "mass" (kg))");
  expectRefused(write("neither.json", bodyScene(R"({"joint": {"type": "free"}})")),
                R"(objects[0].body: needs one of "density" (kg/m^3) and "mass" (kg))");
  expectRefusedStartingWith(write("light.json", bodyScene(R"({"joint": {"type": "free"}, )"
                                                          R"("mass": -1})")),
                            "objects[0].body.mass: must be a number above 0");
}

TEST_F(SceneFile, MjcfBodiesAreBoundByName)
{
  const proxima::SceneDescription scene = proxima::readSceneFile(
    write("crank.json", R"({"version": 2, "mjcf": "crank.xml", "objects": [)"
                        R"({"mesh": "m.obj", "body": {"name": "arm"}}, {"mesh": "m.obj"}]})"));
  EXPECT_EQ(scene.mjcf, (m_dir / "crank.xml").string());
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_TRUE(scene.objects[0].hasBody);
  EXPECT_EQ(scene.objects[0].body.mjcfBody, "arm");
  EXPECT_FALSE(scene.objects[1].hasBody);
}

TEST_F(SceneFile, MjcfRefusals)
{
  expectRefused(write("mjcf1.json", R"({"mjcf": "c.xml", "objects": [{"mesh": "m.obj"}]})"),
                "mjcf: bodies need \"version\": 2 at the top level (this file reads as version 1)");
  expectRefused(
    write("unbound.json", R"({"version": 2, "mjcf": "c.xml", "objects": [{"mesh": "m.obj"}]})"),
    R"(mjcf: no object binds a body of it (give an object "body": {"name": ...}))");
  expectRefused(write("joint.json",
                      R"({"version": 2, "mjcf": "c.xml", "objects": [{"mesh": )"
                      R"("m.obj", "body": {"joint": {"type": "free"}, "mass": 1}}]})"),
                R"(objects[0].body.joint: the scene's "mjcf" file gives the joints and masses: )"
                R"(bind the object to one of its bodies by "name" alone)");
  expectRefused(write("noname.json", bodyScene(R"({"name": "arm"})")),
                R"(objects[0].body.name: binds a body of an MJCF file, and the scene names none )"
                R"((give "mjcf" at the top level, or declare the body's "joint" here))");
  expectRefused(write("gravity.json", R"({"version": 2, "mjcf": "c.xml", "gravity": [0, 0, -1], )"
                                      R"("objects": [{"mesh": "m.obj", "body": {"name": "a"}}]})"),
                R"(gravity: a scene with an "mjcf" file takes gravity from the file's <option>)");
  expectRefused(write("emptyname.json", R"({"version": 2, "mjcf": "c.xml", "objects": [{"mesh": )"
                                        R"("m.obj", "body": {"name": ""}}]})"),
                R"(objects[0].body.name: must name a body of the scene's "mjcf" file, got "")");
}

TEST_F(SceneFile, RepeatedKey)
{
  expectRefused(write("twice.json", R"({"objects": [{"mesh": "a.obj"},)"
                                    R"({"mesh": "b.obj", "scale": 2, "mesh": "c.obj"}]})"),
                "objects[1].mesh: the key appears twice in the same object");
}

TEST_F(SceneFile, RepeatedKeyDeepInside)
{
  expectRefused(write("twice-deep.json",
                      R"({"objects": [{"mesh": "a.obj", "material": {"textures": [)"
                      R"({"image": "x.png", "role": "bump", "amplitude": 1},)"
                      R"({"image": "y.png", "image": "z.png"}]}}]})"),
                "objects[0].material.textures[1].image: the key appears twice in the same object");
}

// Objects.

TEST_F(SceneFile, ObjectNotAnObject)
{
  expectRefused(write("string.json", R"({"objects": [{"mesh": "m.obj"}, "m2.obj"]})"),
                R"(objects[1]: must be a JSON object {...}, got "m2.obj")");
}

TEST_F(SceneFile, MissingMesh)
{
  expectRefused(write("nomesh.json", R"({"objects": [{"scale": 2}]})"),
                R"(objects[0]: missing the required key "mesh")");
}

TEST_F(SceneFile, MeshNotAPath)
{
  expectRefused(write("mesh3.json", R"({"objects": [{"mesh": 3}]})"),
                "objects[0].mesh: must be a file path (a non-empty string), got 3");
  expectRefused(write("mesh-empty.json", R"({"objects": [{"mesh": ""}]})"),
                R"(objects[0].mesh: must be a file path (a non-empty string), got "")");
}

TEST_F(SceneFile, UnknownObjectKeyListsTheKnownOnes)
{
  expectRefused(
    oneObject("colour.json", R"("colour": "red")"),
    "objects[0].colour: unknown key (the keys here are mesh, scale, pose, material, body, tissue)");
}

TEST_F(SceneFile, ScaleNotPositive)
{
  expectRefused(oneObject("scale0.json", R"("scale": 0)"),
                "objects[0].scale: must be a number above 0 and at most 1e+06, got 0");
  expectRefused(oneObject("scale-string.json", R"("scale": "mm")"),
                R"(objects[0].scale: must be a number above 0 and at most 1e+06, got "mm")");
}

// Poses.

TEST_F(SceneFile, TranslationOfTwoNumbers)
{
  expectRefused(oneObject("t2.json", R"("pose": {"translation": [1, 2]})"),
                "objects[0].pose.translation: must be an array of 3 numbers [x, y, z] in metres, "
                "got [1,2]");
}

TEST_F(SceneFile, TranslationWithAString)
{
  expectRefused(oneObject("tz.json", R"("pose": {"translation": [1, 2, "z"]})"),
                R"(objects[0].pose.translation[2]: must be a number, got "z")");
}

TEST_F(SceneFile, RotationWithBothForms)
{
  expectRefused(
    oneObject(
      "both.json",
      R"("pose": {"rotation": {"axis_angle_deg": [0, 0, 1, 90], "quaternion": [1, 0, 0, 0]}})"),
    R"(objects[0].pose.rotation: takes only one of "axis_angle_deg" and "quaternion")");
}

TEST_F(SceneFile, RotationWithNeitherForm)
{
  expectRefused(oneObject("neither.json", R"("pose": {"rotation": {}})"),
                R"(objects[0].pose.rotation: needs one of "axis_angle_deg" and "quaternion")");
}

TEST_F(SceneFile, RotationAboutAZeroAxis)
{
  expectRefused(
    oneObject("axis0.json", R"("pose": {"rotation": {"axis_angle_deg": [0, 0, 0, 90]}})"),
    "objects[0].pose.rotation.axis_angle_deg: the axis (the first three numbers) must "
    "not be zero");
}

TEST_F(SceneFile, AxisAngleOfThreeNumbers)
{
  expectRefused(oneObject("axis3.json", R"("pose": {"rotation": {"axis_angle_deg": [0, 0, 90]}})"),
                "objects[0].pose.rotation.axis_angle_deg: must be an array of 4 numbers "
                "[ax, ay, az, degrees], got [0,0,90]");
}

TEST_F(SceneFile, QuaternionNotUnit)
{
  expectRefused(oneObject("q2.json", R"("pose": {"rotation": {"quaternion": [1, 1, 1, 1]}})"),
                "objects[0].pose.rotation.quaternion: must be a unit quaternion [w, x, y, z] "
                "(norm within 0.001 of 1), got norm 2");
}

TEST_F(SceneFile, UnknownPoseKey)
{
  expectRefused(oneObject("position.json", R"("pose": {"position": [0, 0, 0]})"),
                "objects[0].pose.position: unknown key (the keys here are translation, rotation)");
}

// Materials.

TEST_F(SceneFile, MaterialNotAnObject)
{
  expectRefused(oneObject("shiny.json", R"("material": "shiny")"),
                R"(objects[0].material: must be a JSON object {...}, got "shiny")");
}

TEST_F(SceneFile, FrictionNotANumber)
{
  // The brief's example: the second object's static friction given as a word.
  expectRefused(
    write("high.json", R"({"objects": [{"mesh": "a.obj"},
    {"mesh": "b.obj", "material": {"static_friction": "high"}}]})"),
    R"(objects[1].material.static_friction: must be a number from 0 to 10, got "high")");
}

TEST_F(SceneFile, NegativeViscosity)
{
  expectRefused(oneObject("b.json", R"("material": {"viscosity": -1})"),
                "objects[0].material.viscosity: must be a number from 0 to 10000 N s/m, got -1");
}

TEST_F(SceneFile, StiffnessAndStiffnessRegionsAreRead)
{
  const proxima::SceneDescription scene = proxima::readSceneFile(
    oneObject("nodule.json", R"("material": {"stiffness": 0.4, "stiffness_regions": [
      {"center": [0.01, -0.02, 0.03], "radius": 0.008, "scale": 5}]})"));
  const proxima::SceneMaterial& material = scene.objects[0].material;
  EXPECT_EQ(material.stiffness, 0.4);
  ASSERT_EQ(material.stiffnessRegions.size(), 1u);
  EXPECT_EQ(material.stiffnessRegions[0].center, (proxima::Vec3{0.01, -0.02, 0.03}));
  EXPECT_EQ(material.stiffnessRegions[0].radius, 0.008);
  EXPECT_EQ(material.stiffnessRegions[0].scale, 5.0);
}

TEST_F(SceneFile, StiffnessRegionDefects)
{
  expectRefused(oneObject("k.json", R"("material": {"stiffness": 0})"),
                "objects[0].material.stiffness: must be a number from 0.001 to 1000, got 0");
  expectRefused(oneObject("r.json", R"("material": {"stiffness_regions": {"radius": 1}})"),
                "objects[0].material.stiffness_regions: must be an array of regions "
                R"([{"center": [x, y, z], "radius": r, "scale": s}], got {"radius":1})");
  expectRefused(
    oneObject("c.json", R"("material": {"stiffness_regions": [{"radius": 0.01, "scale": 2}]})"),
    R"(objects[0].material.stiffness_regions[0]: missing the required key "center")");
  expectRefused(oneObject("z.json", R"("material": {"stiffness_regions": [
                             {"center": [0, 0, 0], "radius": 0, "scale": 2}]})"),
                "objects[0].material.stiffness_regions[0].radius: must be a number above 0 and "
                "at most 1000 m, got 0");
  expectRefused(oneObject("s.json", R"("material": {"stiffness_regions": [
                             {"center": [0, 0], "radius": 0.01, "scale": 2}]})"),
                "objects[0].material.stiffness_regions[0].center: must be an array of 3 numbers "
                "[x, y, z] in metres, got [0,0]");
}

TEST_F(SceneFile, BooleanIsNotANumber)
{
  expectRefused(oneObject("bool.json", R"("material": {"dynamic_friction": true})"),
                "objects[0].material.dynamic_friction: must be a number from 0 to 10, got true");
}

TEST_F(SceneFile, FeatureAngleOutOfRange)
{
  expectRefused(
    oneObject("angle.json", R"("material": {"feature_angle_deg": 200})"),
    "objects[0].material.feature_angle_deg: must be a number from 0 to 180 degrees, got 200");
}

TEST_F(SceneFile, ShadingNotAMode)
{
  expectRefused(oneObject("yes.json", R"("material": {"shading": true})"),
                R"(objects[0].material.shading: must be "off", "on" or "auto", got true)");
}

TEST_F(SceneFile, MisspeltMaterialKey)
{
  expectRefused(
    oneObject("fricton.json", R"("material": {"static_fricton": 0.5})"),
    R"(objects[0].material.static_fricton: unknown key (did you mean "static_friction"?))");
}

// Textures.

TEST_F(SceneFile, TexturesNotAnArray)
{
  expectRefused(oneObject("tex.json", R"("material": {"textures": {"image": "a.png"}})"),
                R"(objects[0].material.textures: must be an array of texture maps [{...}], )"
                R"(got {"image":"a.png"})");
}

TEST_F(SceneFile, TextureWithoutRole)
{
  expectRefused(oneObject("norole.json", R"("material": {"textures": [{"image": "a.png"}]})"),
                R"(objects[0].material.textures[0]: missing the required key "role")");
}

TEST_F(SceneFile, TextureRoleNotKnown)
{
  expectRefused(oneObject("colour-role.json",
                          R"("material": {"textures": [{"image": "a.png", "role": "colour"}]})"),
                R"(objects[0].material.textures[0].role: must be "bump", "friction", )"
                R"("viscosity" or "stiffness", got "colour")");
}

TEST_F(SceneFile, BumpWithoutAmplitude)
{
  expectRefused(
    oneObject("noamp.json", R"("material": {"textures": [{"image": "a.png", "role": "bump"}]})"),
    R"(objects[0].material.textures[0]: missing the required key "amplitude" )"
    R"((metres of height per unit of image value, for a bump map))");
}

TEST_F(SceneFile, BumpOfZeroAmplitude)
{
  expectRefused(
    oneObject("amp0.json",
              R"("material": {"textures": [{"image": "a.png", "role": "bump", "amplitude": 0}]})"),
    "objects[0].material.textures[0].amplitude: must be a number other than 0 (metres), got 0");
}

TEST_F(SceneFile, AmplitudeOnAFrictionMap)
{
  expectRefused(
    oneObject("famp.json", R"("material": {"static_friction": 0.5, "textures": [)"
                           R"({"image": "a.png", "role": "friction", "amplitude": 0.1}]})"),
    "objects[0].material.textures[0].amplitude: is for bump maps only: a friction map scales the "
    "material's coefficient by the image value");
}

TEST_F(SceneFile, FrictionMapWithoutFriction)
{
  expectRefused(
    oneObject("fmap.json", R"("material": {"textures": [{"image": "a.png", "role": "friction"}]})"),
    "objects[0].material.textures[0].role: a friction map scales static_friction and "
    "dynamic_friction, but the material sets neither above 0");
}

TEST_F(SceneFile, ViscosityMapWithoutViscosity)
{
  expectRefused(
    oneObject("vmap.json", R"("material": {"dynamic_friction": 0.3, "textures": [)"
                           R"({"image": "a.png", "role": "viscosity"}]})"),
    "objects[0].material.textures[0].role: a viscosity map scales viscosity, but the material "
    "does not set it above 0");
}

TEST_F(SceneFile, TextureChannelNotKnown)
{
  expectRefused(
    oneObject("purple.json",
              R"("material": {"textures": [)"
              R"({"image": "a.png", "role": "bump", "amplitude": 1e-4, "channel": "purple"}]})"),
    R"(objects[0].material.textures[0].channel: must be "luminance", "red", "green", "blue" )"
    R"(or "alpha", got "purple")");
}

TEST_F(SceneFile, TextureImageNotAPath)
{
  expectRefused(
    oneObject("image0.json",
              R"("material": {"textures": [{"image": null, "role": "bump", "amplitude": 1}]})"),
    "objects[0].material.textures[0].image: must be a file path (a non-empty string), "
    "got null");
}

TEST_F(SceneFile, LongValuesAreCutShortInTheMessage)
{
  expectRefused(
    oneObject("long.json",
              R"("scale": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17])"),
    "objects[0].scale: must be a number above 0 and at most 1e+06, got "
    "[1,2,3,4,5,6,7,8,9,10,11,12,13,14,15 ...");
}

TEST_F(SceneFile, DeeplyNestedValuesAreQuotedWithoutRecursingThroughThem)
{
  // The parser takes any depth; the message about the value must not recurse through it either.
  const std::size_t depth = 100000;
  expectRefused(
    oneObject("deep.json", R"("scale": )" + std::string(depth, '[') + std::string(depth, ']')),
    "objects[0].scale: must be a number above 0 and at most 1e+06, got [[[[[[[[...]]]]]]]]");
  std::string wide = "[1";
  for (int i = 0; i < 100000; ++i)
  {
    wide += ",1";
  }
  expectRefused(oneObject("wide.json", R"("scale": )" + wide + "]"),
                "objects[0].scale: must be a number above 0 and at most 1e+06, got "
                "[1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1 ...");
}

TEST_F(SceneFile, LongTokensAreCutShortInJsonErrors)
{
  // nlohmann quotes the token it could not take: here 100,000 digits.
  const std::string path = oneObject("digits.json", R"("scale": )" + std::string(100000, '9'));
  std::string message;
  try
  {
    (void)proxima::readSceneFile(path);
  }
  catch (const proxima::InputError& error)
  {
    message = error.defect();
  }
  EXPECT_TRUE(message.starts_with("not valid JSON: number overflow parsing '999")) << message;
  EXPECT_TRUE(message.ends_with("99 ...")) << message;
  EXPECT_EQ(message.size(), std::string("not valid JSON: ").size() + 160) << message;
}

TEST_F(SceneFile, LongKeysAreCutShortInTheLocation)
{
  const std::string key(1000, 'k');
  expectRefused(
    oneObject("key.json", "\"" + key + "\": 1"),
    "objects[0]." + std::string(36, 'k') +
      " ...: unknown key (the keys here are mesh, scale, pose, material, body, tissue)");
  expectRefused(oneObject("key2.json", "\"" + key + "\": 1, \"" + key + "\": 2"),
                "objects[0]." + std::string(36, 'k') +
                  " ...: the key appears twice in the same object");
}

TEST_F(SceneFile, QuotedValuesAreNotCutInsideACharacter)
{
  // The quote and 34 ASCII bytes, then 2-byte characters, one across the cut at byte 36.
  const std::string mesh = std::string(34, 'a') + "\u00e9\u00e9\u00e9";
  expectRefused(oneObject("utf8.json", R"("scale": ")" + mesh + R"(")"),
                "objects[0].scale: must be a number above 0 and at most 1e+06, got \"" +
                  std::string(34, 'a') + " ...");
}

} // namespace

// Exercise files read and refused as scene files are (JsonChecker): every key of the format read
// into the description, and each kind of defect one message naming the file and the place.
#include "Exercises/ExerciseFile.h"

#include "IO/InputChecks/InputError.h"
#include "IO/Testing/ScratchFolderTest.h"

#include <gtest/gtest.h>

namespace
{
using namespace proxima;
using namespace proxima::trainer;

class ExerciseFile : public testing_support::ScratchFolderTest
{
protected:
  ExerciseFile()
    : ScratchFolderTest("proxima-exercise-")
  {}

  // An exercise file whose tasks are `tasks` (JSON text).
  std::string withTasks(const std::string& name, const std::string& tasks) const
  {
    return write(name, R"({"format": "proxima-exercise", "version": 1, "name": "x",
                           "scene": "s.json", "tasks": )" +
                         tasks + "}");
  }

  void expectRefused(const std::string& path, const std::string& defect) const
  {
    try
    {
      readExerciseFile(path);
      FAIL() << "no refusal of " << path;
    }
    catch (const InputError& error)
    {
      EXPECT_EQ(std::string(error.what()), path + ": " + defect);
    }
  }
};

TEST_F(ExerciseFile, EveryKeyIsRead)
{
  const Exercise exercise = readExerciseFile(write("all.json", R"({
    "format": "proxima-exercise", "version": 1, "name": "All", "instructions": "Do it.",
    "scene": "../Scenes/s.json",
    "proxy": {"radius": 0.003, "stiffness": 400, "rate": 2000, "max_force": 8},
    "tissues": [{"object": 1, "name": "bone", "force_limit": 9}],
    "tasks": [
      {"type": "palpation", "object": 1, "region": 2, "pass_distance": 0.01},
      {"type": "targets", "targets": [{"name": "A", "center": [1, 2, 3], "radius": 0.004}],
       "force": [0.5, 2], "hold": 0.25},
      {"type": "trace", "line": [[0, 0, 0], [0.1, 0, 0]], "tolerance": 0.002,
       "min_coverage": 0.8, "max_off_line": 0.2}]})"));
  EXPECT_EQ(exercise.name, "All");
  EXPECT_EQ(exercise.instructions, "Do it.");
  EXPECT_EQ(exercise.scene, (m_dir / "../Scenes/s.json").string());
  EXPECT_EQ(exercise.radius, 0.003);
  EXPECT_EQ(exercise.stiffness, 400.0);
  EXPECT_EQ(exercise.rate, 2000.0);
  EXPECT_EQ(exercise.maxForce, 8.0);
  ASSERT_EQ(exercise.tissues.size(), 1u);
  EXPECT_EQ(exercise.tissues[0].object, 1u);
  EXPECT_EQ(exercise.tissues[0].name, "bone");
  EXPECT_EQ(exercise.tissues[0].forceLimit, 9.0);
  ASSERT_EQ(exercise.tasks.size(), 3u);
  EXPECT_EQ(exercise.tasks[0].kind, TaskKind::Palpation);
  EXPECT_EQ(exercise.tasks[0].palpation.region, 2u);
  EXPECT_EQ(exercise.tasks[1].targets.targets[0].center, (Vec3{1.0, 2.0, 3.0}));
  EXPECT_EQ(exercise.tasks[1].targets.minForce, 0.5);
  EXPECT_EQ(exercise.tasks[1].targets.maxForce, 2.0);
  EXPECT_EQ(exercise.tasks[1].targets.holdSeconds, 0.25);
  EXPECT_EQ(exercise.tasks[2].trace.line.size(), 2u);
  EXPECT_EQ(exercise.tasks[2].trace.minCoverage, 0.8);
  EXPECT_EQ(exercise.tasks[2].trace.maxOffLine, 0.2);
}

TEST_F(ExerciseFile, Defects)
{
  expectRefused(write("scene.json", R"({"version": 1, "objects": []})"),
                "top level: missing the required key \"format\"");
  expectRefused(write("v2.json", R"({"format": "proxima-exercise", "version": 2})"),
                "version: must be 1 (the exercise file version this program reads), got 2");
  expectRefused(withTasks("none.json", "[]"),
                "tasks: must be an array of at least one task, got []");
  expectRefused(withTasks("kind.json", R"([{"type": "suture"}])"),
                R"(tasks[0].type: must be "palpation", "targets" or "trace", got "suture")");
  expectRefused(withTasks("typo.json", R"([{"type": "palpation", "objet": 0}])"),
                R"(tasks[0].objet: unknown key (did you mean "object"?))");
  expectRefused(
    withTasks("band.json", R"([{"type": "targets", "targets": [{"name": "A",
                 "center": [0, 0, 0], "radius": 0.01}], "force": [2, 1]}])"),
    "tasks[0].force: must be [least, most] newtons with 0 <= least < most <= 1000, got [2,1]");
  expectRefused(withTasks("radius.json", R"([{"type": "targets", "targets": [{"name": "A",
                 "center": [0, 0, 0], "radius": 0}], "force": [1, 2]}])"),
                "tasks[0].targets[0].radius: must be a number above 0 and at most 1 m, got 0");
  expectRefused(withTasks("line.json", R"([{"type": "trace", "line": [[0, 0, 0]],
                                             "tolerance": 0.01}])"),
                "tasks[0].line: must be an array of at least two points [x, y, z], got [[0,0,0]]");
  // A line of no length, however many points it repeats, is no line to trace.
  expectRefused(withTasks("point.json", R"([{"type": "trace", "line": [[0, 0, 0], [0, 0, 0]],
                "tolerance": 0.002}])"),
                "tasks[0].line: has no length (all its points are one point): give a line to "
                "trace, got [[0,0,0],[0,0,0]]");
  expectRefused(withTasks("points.json", R"([{"type": "trace", "line": [[1, 2, 3], [1, 2, 3],
                [1, 2, 3]], "tolerance": 0.002}])"),
                "tasks[0].line: has no length (all its points are one point): give a line to "
                "trace, got [[1,2,3],[1,2,3],[1,2,3]]");
  expectRefused(withTasks("index.json", R"([{"type": "palpation", "object": 0.5, "region": 0,
                                              "pass_distance": 0.01}])"),
                "tasks[0].object: must be an index (a whole number from 0), got 0.5");
  expectRefused(write("twice.json", R"({"format": "proxima-exercise", "format": "x"})"),
                "format: the key appears twice in the same object");
  // A palpation's inclusion is a stiffness region or a tissue inclusion, never both or neither.
  const std::string either = R"(one of "region" (a stiffness region of the object's material) )"
                             R"(and "inclusion" (an inclusion of the object's tissue))";
  expectRefused(withTasks("both.json", R"([{"type": "palpation", "object": 0, "region": 0,
                                             "inclusion": 0, "pass_distance": 0.01}])"),
                "tasks[0]: takes only " + either);
  expectRefused(withTasks("neither.json", R"([{"type": "palpation", "object": 0,
                                                "pass_distance": 0.01}])"),
                "tasks[0]: needs " + either);
}

TEST_F(ExerciseFile, APalpationMayFindATissueInclusion)
{
  const Exercise exercise = readExerciseFile(withTasks(
    "soft.json", R"([{"type": "palpation", "object": 0, "inclusion": 1, "pass_distance": 0.01}])"));
  ASSERT_EQ(exercise.tasks.size(), 1u);
  EXPECT_TRUE(exercise.tasks[0].palpation.tissueInclusion);
  EXPECT_EQ(exercise.tasks[0].palpation.region, 1u);
}

} // namespace

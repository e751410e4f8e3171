// How every program words a usage error (CommandLine/UsageErrors.h): an unknown option or command
// named as typed with the nearest valid one, a repeated option said plainly, in one line.
#include "UsageErrors.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace proxima::cli
{
namespace
{
TEST(UsageErrors, EditDistanceCountsASwapAsOneEdit)
{
  EXPECT_EQ(editDistance("raduis", "radius"), 1u);
  EXPECT_EQ(editDistance("rnu", "run"), 1u);
  EXPECT_EQ(editDistance("radius", "radius"), 0u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("stifness", "stiffness"), 1u);
}

TEST(UsageErrors, NearestWordOnlyWhenNear)
{
  const std::vector<std::string> commands{"run", "view", "path", "tree", "inspect", "generate"};
  EXPECT_EQ(nearestWord("rnu", commands), "run");
  EXPECT_EQ(nearestWord("veiw", commands), "view");
  EXPECT_EQ(nearestWord("insp", commands), "inspect");
  EXPECT_EQ(nearestWord("frobnicate", commands), "");
  EXPECT_EQ(nearestWord("x", commands), "");
}

// `arguments` parsed by a small proxima-like app; the failure message, as the program prints it.
std::string failure(std::vector<std::string> arguments)
{
  CLI::App app{"test", "proxima"};
  app.require_subcommand(1);
  configureUsageErrors(app, "proxima");
  CLI::App* run = app.add_subcommand("run", "Run");
  CLI::App* view = app.add_subcommand("view", "View");
  double radius = 0.0;
  double stiffness = 0.0;
  run->add_option("--radius", radius);
  run->add_option("--stiffness", stiffness);
  view->add_option("--radius", radius);
  std::vector<const char*> argv{"proxima"};
  for (const std::string& argument : arguments)
  {
    argv.push_back(argument.c_str());
  }
  try
  {
    app.parse(static_cast<int>(argv.size()), const_cast<char**>(argv.data()));
  }
  catch (const CLI::ParseError& error)
  {
    testing::internal::CaptureStderr();
    app.exit(error);
    return testing::internal::GetCapturedStderr();
  }
  return "parsed";
}

TEST(UsageErrors, UnknownOptionNamedWithTheNearest)
{
  EXPECT_EQ(failure({"run", "--raduis", "0.002"}),
            "proxima: unknown option '--raduis'; did you mean '--radius'? (see proxima --help)\n");
  EXPECT_EQ(failure({"run", "--raduis=0.002"}),
            "proxima: unknown option '--raduis'; did you mean '--radius'? (see proxima --help)\n");
  EXPECT_EQ(failure({"run", "--radius", "0.001", "--stifnes", "5"}),
            "proxima: unknown option '--stifnes'; did you mean '--stiffness'? (see proxima "
            "--help)\n");
  EXPECT_EQ(failure({"run", "--frobnicate"}),
            "proxima: unknown option '--frobnicate' (see proxima --help)\n");
  EXPECT_EQ(failure({"run", "--radius", "0.001", "extra"}),
            "proxima: unexpected argument 'extra' (no option takes it here) (see proxima "
            "--help)\n");
}

TEST(UsageErrors, UnknownCommandNamedWithTheNearest)
{
  EXPECT_EQ(failure({"rnu"}),
            "proxima: unknown command 'rnu'; did you mean 'run'? (see proxima --help)\n");
  EXPECT_EQ(failure({"rnu", "--radius", "0.001"}),
            "proxima: unknown command 'rnu'; did you mean 'run'? (see proxima --help)\n");
  EXPECT_EQ(failure({"zzz"}), "proxima: unknown command 'zzz' (see proxima --help)\n");
  EXPECT_EQ(failure({}), "proxima: A subcommand is required (see proxima --help)\n");
}

TEST(UsageErrors, RepeatedOptionSaidPlainly)
{
  EXPECT_EQ(failure({"run", "--radius", "0.001", "--radius", "0.002"}),
            "proxima: --radius: given 2 times; give it once (see proxima --help)\n");
  EXPECT_EQ(failure({"view", "--radius", "1", "--radius", "2", "--radius", "3"}),
            "proxima: --radius: given 3 times; give it once (see proxima --help)\n");
}
} // namespace
} // namespace proxima::cli

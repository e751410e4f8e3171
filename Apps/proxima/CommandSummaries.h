// The name and one-line description of every subcommand, in the order `proxima --help` lists
// them. Shared by the front (main.cpp), which lists the subcommands without linking them, and by
// each subcommand's own program, which registers its options under the same words.
#pragma once

namespace proxima::cli
{

struct CommandSummary
{
  const char* name;
  const char* description;
};

inline constexpr CommandSummary kRunSummary{
  "run", "Play a finger path through a mesh or a scene in lockstep mode; write the trace and a "
         "summary"};
inline constexpr CommandSummary kViewSummary{
  "view", "Replay a finger path through a mesh or a scene in the threaded runtime and draw it "
          "(proxy, finger, spring, contact planes, friction cones, force)"};
inline constexpr CommandSummary kPathSummary{
  "path", "Write a scripted finger path (slide, press-stroke, circle, jab, wander, or a seeded "
          "person-like probe session) for a mesh or a scene"};
inline constexpr CommandSummary kTreeSummary{
  "tree", "Read a mesh, build its sphere tree and print sizes and timings as JSON."};
inline constexpr CommandSummary kInspectSummary{
  "inspect", "Report a mesh's defects as JSON: holes, non-manifold and misoriented edges, "
             "degenerate, duplicate and self-intersecting triangles, pieces"};
inline constexpr CommandSummary kTissueSummary{
  "tissue", "Wrap an organ's surface into a closed one, fill it with tetrahedra of a given size "
            "and write them as a .vtu file, with a report as JSON"};
inline constexpr CommandSummary kGenerateSummary{
  "generate", "Write a procedural mesh (sizes in metres) to a file."};
inline constexpr CommandSummary kDevicesSummary{
  "devices", "List the haptic devices connected now, by the name proxima run --device takes"};

inline constexpr CommandSummary kServeSummary{
  "serve", "Serve remote runs over gRPC: play clients' finger paths in lockstep and stream the "
           "ticks back"};
inline constexpr CommandSummary kRemoteSummary{
  "remote", "Run a command on a proxima serve elsewhere: remote --server HOST:PORT run ..."};

// PROXIMA_HAS_NET: whether this build made the Net layer's commands (Apps/proxima/CMakeLists.txt).
inline constexpr CommandSummary kCommandSummaries[] = {
  kRunSummary,     kViewSummary,   kPathSummary,     kTreeSummary,
  kInspectSummary, kTissueSummary, kGenerateSummary, kDevicesSummary,
#if PROXIMA_HAS_NET
  kServeSummary,   kRemoteSummary,
#endif
};

} // namespace proxima::cli

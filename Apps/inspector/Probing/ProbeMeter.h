// Clearance by touch (Documentation/CadInspector.md): what a probing session measured,
// tick by tick, with the proxy at the tool's radius as the probe. The proxy never enters the part,
// so it answers by itself whether a point is reachable; the meter records
//   - markers: the touched surface point (the contact nearest the proxy's centre) when asked;
//   - the distances between consecutive markers, straight and across (along the first marker's
//     normal: the clearance between two facing surfaces, whatever the markers' offset along them);
//   - the narrowest gap the probe passed through: at each tick, the nearest surface to the proxy's
//     centre, and the surface met going the other way along the line from it through the centre;
//     the gap is the sum of the two distances (exact between parallel walls);
//   - stops: the runs of ticks where the finger went deeper than a depth beyond the proxy, the
//     proxy held where the tool could go no further; each names its deepest tick.
// The headless session (`proxima-inspector --path`) and the window feed it the same ticks.
#pragma once

#include "Proxy/CollisionScene.h"
#include "Runtime/HapticState.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace proxima
{
struct SphereTreeScratch;
}

namespace proxima::inspector
{

struct ProbeMarker
{
  double time = 0.0;
  /// The touched point on the surface, and the surface's normal there (into free space).
  Vec3 point;
  Vec3 normal;
  std::uint32_t object = 0;
  std::uint32_t triangle = 0;
};

struct MarkerDistance
{
  std::size_t from = 0;
  std::size_t to = 0;
  double distance = 0.0;
  /// |(to - from) . normal of from|.
  double across = 0.0;
};

struct ProbeGap
{
  double width = 0.0;
  double time = 0.0;
  Vec3 proxy;
  /// The nearest surface point, and the point met across the gap.
  Vec3 wall;
  Vec3 across;
};

struct ProbeStop
{
  double startTime = 0.0;
  double endTime = 0.0;
  /// At the deepest tick of the run.
  Vec3 proxy;
  Vec3 finger;
  double depth = 0.0;
};

struct ProbeMeasurements
{
  std::size_t ticks = 0;
  std::vector<ProbeMarker> markers;
  /// Marks asked for while the proxy touched nothing: not markers.
  std::size_t marksMissed = 0;
  std::vector<MarkerDistance> distances;
  std::optional<ProbeGap> narrowestGap;
  std::size_t stopCount = 0;
  /// The first ProbeMeterSettings::stopsKept stops.
  std::vector<ProbeStop> stops;
  /// The deepest the finger went beyond the proxy in the whole session.
  double deepestPress = 0.0;
};

struct ProbeMeterSettings
{
  /// Finger beyond the proxy by more than this is a stop (metres).
  double stopDepth = 0.0005;
  /// Gaps wider than this are not measured (metres).
  double widestGap = 0.02;
  std::size_t stopsKept = 100;
};

class ProbeMeter
{
public:
  /// `scene` must outlive the meter.
  ProbeMeter(const CollisionScene& scene, const ProbeMeterSettings& settings);
  ~ProbeMeter();

  void addTick(const HapticState& state);
  /// Marks the last tick's touched point; false when it touched nothing (or no tick came yet).
  bool mark();
  const ProbeMeasurements& measurements() const { return m_measurements; }

private:
  void measureGap(const HapticState& state);

  const CollisionScene& m_scene;
  ProbeMeterSettings m_settings;
  std::unique_ptr<SphereTreeScratch> m_scratch;
  ProbeMeasurements m_measurements;
  std::optional<HapticState> m_last;
  bool m_inStop = false;
};

} // namespace proxima::inspector

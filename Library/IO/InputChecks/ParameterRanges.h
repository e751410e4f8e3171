// The documented range of every number a user gives Proxima, on the command line or in a scene
// file (Documentation/CommandLine.md, "Numbers"). One table, so that `--scale` and a scene's
// "scale" refuse the same values with the same words. A range is wide enough for any real
// session (a 0.1 mm probe on a 10 m model, a 100 kHz replay) and narrow enough that a typo or
// NaN is refused before it runs: a scale of 1e200 froze the proxy, a rate of 1e9 filled the disk.
#pragma once

#include "IO/InputChecks/InputError.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace proxima
{

/// A closed or half-open interval of accepted values, with the unit for messages.
struct ParameterRange
{
  /// Lower bound; accepted itself unless `lowExcluded`.
  double low = 0.0;
  /// True: `low` itself is refused (the value must be above it).
  bool lowExcluded = false;
  /// Upper bound, always accepted itself.
  double high = 0.0;
  /// " m", " Hz", "" for a pure number.
  const char* unit = "";

  /// True if `value` lies in the range; false for NaN.
  bool contains(double value) const
  {
    // NaN fails both comparisons and so every range.
    return (lowExcluded ? value > low : value >= low) && value <= high;
  }
};

/// `value` as a short number for messages: 1e+06, 0.001, 10000 (never 309 digits).
inline std::string shortNumber(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

/// The range in words: "from 0 to 10", "above 0 and at most 1 m".
inline std::string describeRange(const ParameterRange& range)
{
  const std::string high = shortNumber(range.high) + range.unit;
  return range.lowExcluded ? "above " + shortNumber(range.low) + " and at most " + high
                           : "from " + shortNumber(range.low) + " to " + high;
}

// Geometry.
/// The proxy sphere's radius: above 0 (a point proxy is radius 0 by its own option) up to 1 m.
inline constexpr ParameterRange kProxyRadiusRange{0.0, true, 1.0, " m"};
/// The contact skin: 0 (the scene's own, from its size) up to 10 cm.
inline constexpr ParameterRange kSkinRange{0.0, false, 0.1, " m"};
/// File units to metres: a micrometre-unit file to a kilometre-unit one, with margin.
inline constexpr ParameterRange kMeshScaleRange{0.0, true, 1e6, ""};
/// The feature angle of point normals: dihedral angles above it are creases.
inline constexpr ParameterRange kFeatureAngleRange{0.0, false, 180.0, " degrees"};

/// Generated shapes (proxima generate): a micrometre to a kilometre across, placed within a
/// thousand kilometres of the origin.
inline constexpr ParameterRange kGeneratedSizeRange{0.0, true, 1000.0, " m"};
/// Where a generated shape is placed: each coordinate within a thousand kilometres.
inline constexpr ParameterRange kGeneratedPlaceRange{-1e6, false, 1e6, " m"};
/// An icosphere's subdivision levels: level 9 is 5.2 million triangles, level 10 would be 21 million.
inline constexpr ParameterRange kIcosphereSubdivisionsRange{0.0, false, 9.0, ""};
/// A generated grid's cells along a side: 4096 is 33.6 million triangles.
inline constexpr ParameterRange kGridCellsRange{1.0, false, 4096.0, ""};
/// A generated prism's sides: fewer than three is no prism.
inline constexpr ParameterRange kPrismSidesRange{3.0, false, 100000.0, ""};

/// The sphere tree's leaf rule (proxima tree): a triangle longer than this many median edges is
/// split; 0 splits none.
inline constexpr ParameterRange kLeafSizeFactorRange{0.0, false, 1e6, ""};
/// Leaf spheres grouped under one leaf node of the sphere tree (1 is the paper's tree).
inline constexpr ParameterRange kLeafSpheresPerNodeRange{1.0, false, 1024.0, ""};
/// The most pieces the leaf rule may split one triangle into.
inline constexpr ParameterRange kPiecesPerTriangleRange{1.0, false, 1e6, ""};

/// A tissue's tetrahedra's edge size (proxima tissue): above 0, at most 10 m.
inline constexpr ParameterRange kTetSizeRange{0.0, true, 10.0, " m"};

/// A tissue's Young's modulus: above 0, at most 1 GPa (soft tissue is a few kPa, cartilage MPa).
inline constexpr ParameterRange kYoungsModulusRange{0.0, true, 1e9, " Pa"};
/// A tissue's Poisson's ratio: from 0 to 0.499 (0.5, incompressible, locks linear tetrahedra).
inline constexpr ParameterRange kPoissonRatioRange{0.0, false, 0.499, ""};
/// A tissue's density: above 0, at most 1e5 kg/m^3.
inline constexpr ParameterRange kTissueDensityRange{0.0, true, 1e5, " kg/m^3"};
/// A tissue's mass-proportional damping: from 0 to 1e4 per second.
inline constexpr ParameterRange kTissueDampingRange{0.0, false, 1e4, " 1/s"};

/// Mesh inspection (proxima inspect): places listed per kind of defect, the angle under which a
/// triangle is a sliver (no triangle has all angles above 60), and the welding distance.
inline constexpr ParameterRange kDefectLocationsRange{0.0, false, 100000.0, ""};
/// The angle under which a triangle is a sliver.
inline constexpr ParameterRange kSliverAngleRange{0.0, false, 60.0, " degrees"};
/// The distance within which inspection welds corners into one vertex.
inline constexpr ParameterRange kWeldDistanceRange{0.0, true, 1e6, " m"};

/// The proxy's work: move/update iterations allowed per tick.
inline constexpr ParameterRange kMaxIterationsRange{1.0, false, 1000.0, ""};

// The spring and the device.
/// The spring between proxy and finger (kp).
inline constexpr ParameterRange kStiffnessRange{0.0, true, 1e6, " N/m"};
/// The largest force the servo renders; the device's own limit may be lower.
inline constexpr ParameterRange kMaxForceRange{0.0, true, 1000.0, " N"};

// Surface effects (paper section 4).
/// A friction coefficient (mu_s or mu_d).
inline constexpr ParameterRange kFrictionRange{0.0, false, 10.0, ""};
/// A surface's viscous friction (paper section 4.2).
inline constexpr ParameterRange kViscosityRange{0.0, false, 1e4, " N s/m"};
/// A bump map's metres of height per unit of image value (0 is refused apart: no bump at all).
inline constexpr ParameterRange kTextureAmplitudeRange{-1.0, false, 1.0, " m"};
/// A surface's factor on kp, and a stiffness region's at its centre: from a thousandth (a fluid
/// against bone) to a thousand times the scene's spring.
inline constexpr ParameterRange kStiffnessScaleRange{0.001, false, 1000.0, ""};
/// A stiffness region's radius.
inline constexpr ParameterRange kStiffnessRegionRadiusRange{0.0, true, 1e3, " m"};

// Bodies (paper section 6; Documentation/Dynamics.md): from a MEMS test mass to a crank handle.
/// A body's density.
inline constexpr ParameterRange kBodyDensityRange{0.0, true, 1e5, " kg/m^3"};
/// A body's mass, when given instead of its density.
inline constexpr ParameterRange kBodyMassRange{0.0, true, 1e4, " kg"};
/// A joint's spring toward its rest coordinate (N m/rad for a hinge, N/m for a slide).
inline constexpr ParameterRange kJointStiffnessRange{0.0, false, 1e6, ""};
/// A joint's damping (N m s/rad for a hinge, N s/m for a slide).
inline constexpr ParameterRange kJointDampingRange{0.0, false, 1e6, ""};
/// Each component of a scene's gravity.
inline constexpr ParameterRange kGravityRange{-100.0, false, 100.0, " m/s^2"};

/// Empty when mu_s and mu_d go together; else why not. Sliding never holds harder than sticking
/// (Coulomb; paper section 4.1), so with a static phase (mu_s > 0) mu_d must not be above mu_s.
/// mu_s = 0 is the documented surface with no static phase that drags at mu_d
/// (Documentation/Friction.md). `staticName` is the key or option that gives mu_s.
inline std::string frictionPairError(double staticFriction, double dynamicFriction,
                                     const std::string& staticName)
{
  if (staticFriction > 0.0 && dynamicFriction > staticFriction)
  {
    return "mu_d " + shortNumber(dynamicFriction) + " is above " + staticName + " mu_s " +
           shortNumber(staticFriction) + ": give mu_d <= mu_s (or mu_s 0 for no static phase)";
  }
  return {};
}

// The applications' windows and pictures (proxima view, proxima-inspector, proxima-trainer).
/// A window's or picture's width or height.
inline constexpr ParameterRange kWindowSizeRange{64.0, false, 8192.0, " pixels"};
/// A screenshot's time into its path.
inline constexpr ParameterRange kScreenshotTimeRange{0.0, false, 1e9, " s"};

// The CAD inspector's probe (Documentation/CadInspector.md): the finger this far beyond the proxy
// is a stop; gaps wider than the widest are not measured.
/// The probe's stop: the finger this far beyond the proxy.
inline constexpr ParameterRange kStopDepthRange{0.0, false, 1.0, " m"};
/// The widest gap the probe measures.
inline constexpr ParameterRange kWidestGapRange{1e-6, false, 10.0, " m"};

// Time.
/// A scripted run or path's sample rate. The real-time servo has its own, narrower rule
/// (Runtime/ServoRate.h).
inline constexpr ParameterRange kScriptedRateRange{10.0, false, 100000.0, " Hz"};
/// The real-time servo loop's rate, the rule of Runtime/ServoRate.h (a static_assert in
/// Apps/proxima/SceneOptions.cpp keeps the two equal): proxima view, run --realtime, the
/// applications' windows.
inline constexpr ParameterRange kRealtimeRateRange{1000.0, false, 10000.0, " Hz"};
/// The length of a generated path.
inline constexpr ParameterRange kPathDurationRange{0.0, false, 3600.0, " s"};
/// Ticks of a run, or rows of a generated path, taken without --max-ticks: about 40 minutes at
/// 4 kHz, a trace of a few GB. A path row at t = 1e9 s would otherwise write until the disk is
/// full.
inline constexpr double kDefaultMaxTicks = 1e7;

/// Refuses a run or path of more than `maxTicks` ticks before it writes anything, in words
/// that say how long it would be and how to go past the limit.
inline void checkTickCount(double ticks, double rate, double maxTicks, const std::string& what)
{
  if (ticks > maxTicks)
  {
    throw InputError("--max-ticks", what + " is " + shortNumber(ticks) + " ticks at " +
                                      shortNumber(rate) + " Hz, more than the limit of " +
                                      shortNumber(maxTicks) + " (give --max-ticks to go past it)");
  }
}

} // namespace proxima

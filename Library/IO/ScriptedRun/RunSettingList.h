// The knobs of a scripted run, declared once. Each row below becomes:
// - a member of ScriptedRunSettings (ScriptedRunSettings.h), with its default;
// - a row of the settings table (RunSettingTable.h) that checks its value and that the command
//   line registers its option from (`--max-force`), the Python module its keyword from
//   (`max_force`), and the remote-run client and server copy it by;
// - a field of the remote runs' RunSettings message, generated into proxima_run_settings.proto
//   at build time (Library/Net/RunSettingsProto.cpp) under the row's field number.
// So a new setting is one row here. A field number is part of the wire format: a new row takes a
// new number, and no row ever changes its number or reuses a removed row's.
//
// A row is X(member, option, type, kind, default, range, choices, scope, field, help):
// - member: the C++ name; option: the command line's spelling without "--" (Python and the
//   .proto spell it with '_' for '-');
// - type: double, int or std::string; kind: how its value is read and checked (RunSettingKind);
// - range: the ParameterRange of a number (IO/InputChecks/ParameterRanges.h), else nullptr;
// - choices: the accepted words of a Choice, separated by '|', else nullptr;
// - scope: Proxy (the proxy and the spring), Servo (the loop and the force), Surface (a --mesh
//   run's one object: a scene file gives these per object, and --scene excludes them) or Budget;
// - help: the command line's help text and the Python documentation's.
#pragma once

#define PROXIMA_RUN_SETTINGS(X)                                                                    \
  X(radius, "radius", double, Number, 0.001, &kProxyRadiusRange, nullptr, Proxy, 2,                \
    "Proxy radius in metres (default 0.001)")                                                      \
  X(stiffness, "stiffness", double, Number, 1000.0, &kStiffnessRange, nullptr, Proxy, 3,           \
    "Spring stiffness kp in N/m (default 1000)")                                                   \
  X(rate, "rate", double, Number, 1000.0, &kScriptedRateRange, nullptr, Servo, 4,                  \
    "Servo rate in Hz (default 1000)")                                                             \
  X(maxForce, "max-force", double, Number, 10.0, &kMaxForceRange, nullptr, Servo, 5,               \
    "Force clamp in newtons (default 10)")                                                         \
  X(maxIterations, "max-iterations", int, WholeNumber, 256, &kMaxIterationsRange, nullptr, Servo,  \
    6, "Move/update iterations per tick (default 256)")                                            \
  X(skin, "skin", double, Number, 0.0, &kSkinRange, nullptr, Servo, 7,                             \
    "Contact skin in metres (default: from the scene, see Documentation/Epsilons.md)")             \
  X(scale, "scale", double, Number, 1.0, &kMeshScaleRange, nullptr, Surface, 1,                    \
    "File units to metres (default 1)")                                                            \
  X(shading, "shading", std::string, Choice, "off", nullptr, "off|on|auto", Surface, 8,            \
    "Force shading from the mesh's point normals: off, on or auto (default off)")                  \
  X(featureAngle, "feature-angle", double, Number, 30.0, &kFeatureAngleRange, nullptr, Surface, 9, \
    "With --shading on and a mesh without normals: edges sharper than this many degrees stay "     \
    "sharp (default 30)")                                                                          \
  X(staticFriction, "static-friction", double, Number, 0.0, &kFrictionRange, nullptr, Surface, 10, \
    "Static friction coefficient mu_s (default 0: none)")                                          \
  X(dynamicFriction, "dynamic-friction", double, Number, 0.0, &kFrictionRange, nullptr, Surface,   \
    11, "Dynamic friction coefficient mu_d, at most mu_s (default 0: none)")                       \
  X(viscosity, "viscosity", double, Number, 0.0, &kViscosityRange, nullptr, Surface, 12,           \
    "Viscous friction b in N s/m (default 0: none)")                                               \
  X(texture, "texture", std::string, File, "", nullptr, nullptr, Surface, 0,                       \
    "Texture image (PNG, JPEG, TIFF, OpenEXR) mapped by the mesh's texture coordinates; needs "    \
    "--texture-role")                                                                              \
  X(textureRole, "texture-role", std::string, Choice, "", nullptr,                                 \
    "bump|friction|viscosity|stiffness", Surface, 13,                                              \
    "What --texture modulates: bump (height), friction or viscosity (scales those "                \
    "coefficients)")                                                                               \
  X(textureAmplitude, "texture-amplitude", double, NonZeroNumber, 0.0, &kTextureAmplitudeRange,    \
    nullptr, Surface, 14,                                                                          \
    "Bump maps: metres of height per unit of image value (required for bump, not 0)")              \
  X(textureChannel, "texture-channel", std::string, Choice, "luminance", nullptr,                  \
    "luminance|red|green|blue|alpha", Surface, 15,                                                 \
    "Which value of each pixel --texture takes: luminance, red, green, blue or alpha (default "    \
    "luminance)")                                                                                  \
  X(tickBudget, "tick-budget", std::string, TickBudget, "", nullptr, nullptr, Budget, 16,          \
    "Work budget of one proxy tick: <N>us of wall time, <N>it move/update iterations, both "       \
    "(50us,40it), default (the real-time default, an iteration budget: deterministic, with a "     \
    "wall-time safety cap in real time only) or none. A tick that reaches it stops with the "      \
    "proxy where it is (always feasible) and the next tick goes on from there.")

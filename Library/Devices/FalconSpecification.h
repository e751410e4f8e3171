// The Novint Falcon's numbers, each with where it comes from, in one place so that the
// kinematics, the driver and the emulator cannot disagree. The linkage dimensions, the encoder
// and the capstan are the measurements libnifalcon publishes in its FalconGeometry.h (the
// letters of R. E. Stamper's delta-robot diagram that file follows are given in brackets); the
// motor command scale and its sign are those of libnifalcon's FalconKinematicStamper.cpp.
// What no public source gives is marked so (Documentation/Devices.md has the table).
#pragma once

#include <numbers>

namespace proxima::falcon
{

// The linkage, in metres (libnifalcon FalconGeometry.h).
/// [a] Hip (motor axis) to knee: the upper arm.
constexpr double kUpperArm = 0.060;
/// [b] Length of the sides of the shin parallelogram: the lower arm.
constexpr double kLowerArm = 0.1025;
/// [e] Knee to shin connection joint, and [d] shin to effector connection joint: short links
/// at both ends of the parallelogram. In libnifalcon's equations they lie in the arm's plane,
/// along the shin's lean in it, so only their sum matters.
constexpr double kKneeLink = 0.01125;
/// [d] Shin to effector connection joint (see kKneeLink).
constexpr double kEffectorLink = 0.01125;
/// [c], [f] The effector's joint relative to the grip centre, along the arm's radial (u) and
/// motor-axis (v) directions.
constexpr double kEffectorRadial = 0.01443;
/// [f] The effector's joint along the motor axis (v), relative to the grip centre.
constexpr double kEffectorAlongAxis = -0.025;
/// [r], [s] The hip relative to the base centre, along u and v.
constexpr double kHipRadial = 0.0400;
/// [s] The hip along the motor axis (v), relative to the base centre.
constexpr double kHipAlongAxis = -0.02309;
/// [phy] Direction of each arm's u axis about the base axis: 90, -30 and -150 degrees, each
/// turned by the 15 degrees the whole mechanism is rotated from the desk plane.
constexpr double kArmOffsetAngle = std::numbers::pi / 12.0;
/// Each arm's u direction about the base axis (rad), in the order of the encoders.
constexpr double kArmAngles[3] = {std::numbers::pi / 2.0 + kArmOffsetAngle,
                                  -std::numbers::pi / 6.0 + kArmOffsetAngle,
                                  -5.0 * std::numbers::pi / 6.0 + kArmOffsetAngle};

// Encoders to arm angles (libnifalcon FalconGeometry.h and FalconKinematic.h).
/// Transparent slots on the motor's encoder wheel; quadrature gives four counts per slot.
constexpr double kEncoderSlots = 320.0;
/// Encoder counts per turn of the motor shaft.
constexpr double kCountsPerMotorTurn = 4.0 * kEncoderSlots;
/// The motor shaft drives the arm at the rim of the arm's 110 mm sector (libnifalcon's "small
/// diameter of the arm"), equal arc lengths: arm angle = shaft angle x shaft / sector diameter.
constexpr double kShaftDiameter = 0.01425;
/// Diameter of the arm's sector the shaft drives (m).
constexpr double kArmSectorDiameter = 0.110;
/// 1280 x 110 / 14.25 / (2 pi) = 1572.6 counts per radian of arm angle.
constexpr double kCountsPerArmRadian =
  kCountsPerMotorTurn * (kArmSectorDiameter / kShaftDiameter) / (2.0 * std::numbers::pi);
/// The arm angle at zero counts: 35 degrees, "approx" in libnifalcon's own words.
constexpr double kThetaAtZeroCounts = 35.0 * std::numbers::pi / 180.0;

// Torques to motor commands (libnifalcon FalconKinematicStamper.cpp, getForces).
/// The command is -10000 per N m of torque toward a larger arm angle: a positive command turns
/// the arm toward fewer counts. libnifalcon calls the value a motor voltage; its link to
/// current and torque is not published, so this scale is what libnifalcon sends, not a
/// calibration.
constexpr double kCommandsPerNewtonMetre = -10000.0;

} // namespace proxima::falcon

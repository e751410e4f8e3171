// The 3Dconnexion SpaceMouse's USB HID reports (SpaceNavigator, SpaceMouse Pro, Wireless,
// Compact, ...), as plain byte codecs. Input report 1 holds the translation (x, y, z) as signed
// 16-bit little-endian values; older models send the rotation (rx, ry, rz) in report 2, newer ones
// append it to report 1 (six axes, 12 bytes); report 3 holds the buttons as a bit mask. Output
// report 4 switches the LED. Which layout a device uses is read from its report descriptor.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace proxima
{

// The vendor IDs of 3Dconnexion devices: the Logitech era and 3Dconnexion's own.
/// Logitech's vendor ID, under which the older 3Dconnexion devices are sold.
constexpr std::uint16_t kSpaceMouseVendorLogitech = 0x046d;
/// 3Dconnexion's own vendor ID: every device under it is a SpaceMouse.
constexpr std::uint16_t kSpaceMouseVendor3Dconnexion = 0x256f;

constexpr std::uint8_t kSpaceMouseTranslationReport = 1; ///< Input: translation (or six axes).
constexpr std::uint8_t kSpaceMouseRotationReport = 2;    ///< Input: rotation (split layout).
constexpr std::uint8_t kSpaceMouseButtonReport = 3;      ///< Input: the buttons as a bit mask.
constexpr std::uint8_t kSpaceMouseLedReport = 4;         ///< Output: the LED on or off.

/// Which input reports carry the rotation axes.
enum class SpaceMouseLayout
{
  /// Translation in report 1, rotation in report 2 (SpaceNavigator, SpaceMouse Pro and older).
  SplitReports,
  /// All six axes in report 1 (SpaceMouse Wireless, Compact and newer).
  SixAxisReport
};

/// Raw axis counts as the device reports them, and the buttons.
struct SpaceMouseState
{
  /// Cap translation counts along the device's x, y, z (signed 16-bit values).
  std::array<int, 3> translation{0, 0, 0};
  /// Cap rotation counts about the device's x, y, z (signed 16-bit values).
  std::array<int, 3> rotation{0, 0, 0};
  /// Button states, bit i for button i.
  std::uint32_t buttons = 0;
};

/// What one input report changed; `error` says why a report was refused.
struct SpaceMouseReportResult
{
  /// True if the report was applied; false if it was refused and `state` is unchanged.
  bool accepted = false;
  /// The report set the translation counts.
  bool translation = false;
  /// The report set the rotation counts.
  bool rotation = false;
  /// The report set the buttons.
  bool buttons = false;
  /// Why the report was refused; empty if it was accepted.
  std::string error;
};

/// Applies one input report (report ID first) to `state`. A report that is too short for its ID,
/// or has an unknown ID, is refused and leaves `state` unchanged.
SpaceMouseReportResult applySpaceMouseReport(std::span<const std::uint8_t> report,
                                             SpaceMouseLayout layout, SpaceMouseState& state);

/// The LED output report: report ID 4, then 1 for on, 0 for off.
std::array<std::uint8_t, 2> spaceMouseLedReport(bool on);

/// Input report sizes in bytes (without the ID byte), by report ID, from a HID report descriptor.
/// Refuses (nullopt, `error` set) a descriptor whose items run past its end.
std::optional<std::vector<std::pair<std::uint8_t, std::size_t>>> inputReportSizes(
  std::span<const std::uint8_t> descriptor, std::string& error);

/// The layout a report descriptor describes: six axes (12 bytes) in report 1, or three (6 bytes)
/// with report 2 beside it. Refuses a descriptor without a translation report of either size.
std::optional<SpaceMouseLayout> spaceMouseLayoutFromDescriptor(
  std::span<const std::uint8_t> descriptor, std::string& error);

} // namespace proxima

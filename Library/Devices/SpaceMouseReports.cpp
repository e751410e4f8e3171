#include "Devices/SpaceMouseReports.h"

#include <algorithm>

namespace proxima
{
namespace
{
int int16At(std::span<const std::uint8_t> bytes, std::size_t offset)
{
  const auto value = static_cast<std::uint16_t>(bytes[offset] | (bytes[offset + 1] << 8));
  return static_cast<std::int16_t>(value);
}

void readAxes(std::span<const std::uint8_t> report, std::size_t offset, std::array<int, 3>& axes)
{
  for (std::size_t i = 0; i < 3; ++i)
  {
    axes[i] = int16At(report, offset + 2 * i);
  }
}

SpaceMouseReportResult refuse(std::string error)
{
  SpaceMouseReportResult result;
  result.error = std::move(error);
  return result;
}
} // namespace

SpaceMouseReportResult applySpaceMouseReport(std::span<const std::uint8_t> report,
                                             SpaceMouseLayout layout, SpaceMouseState& state)
{
  if (report.empty())
  {
    return refuse("empty report");
  }
  const std::uint8_t id = report[0];
  const std::size_t payload = report.size() - 1;
  SpaceMouseReportResult result;
  switch (id)
  {
    case kSpaceMouseTranslationReport:
    {
      const std::size_t needed = layout == SpaceMouseLayout::SixAxisReport ? 12 : 6;
      if (payload < needed)
      {
        return refuse("report 1 has " + std::to_string(payload) + " bytes, the layout needs " +
                      std::to_string(needed));
      }
      readAxes(report, 1, state.translation);
      result.translation = true;
      if (layout == SpaceMouseLayout::SixAxisReport)
      {
        readAxes(report, 7, state.rotation);
        result.rotation = true;
      }
      break;
    }
    case kSpaceMouseRotationReport:
      if (payload < 6)
      {
        return refuse("report 2 has " + std::to_string(payload) + " bytes, needs 6");
      }
      readAxes(report, 1, state.rotation);
      result.rotation = true;
      break;
    case kSpaceMouseButtonReport:
    {
      if (payload < 1)
      {
        return refuse("report 3 has no button bytes");
      }
      std::uint32_t buttons = 0;
      for (std::size_t i = 0; i < std::min<std::size_t>(payload, 4); ++i)
      {
        buttons |= static_cast<std::uint32_t>(report[1 + i]) << (8 * i);
      }
      state.buttons = buttons;
      result.buttons = true;
      break;
    }
    default: return refuse("unknown report ID " + std::to_string(id));
  }
  result.accepted = true;
  return result;
}

std::array<std::uint8_t, 2> spaceMouseLedReport(bool on)
{
  return {kSpaceMouseLedReport, static_cast<std::uint8_t>(on ? 1 : 0)};
}

std::optional<std::vector<std::pair<std::uint8_t, std::size_t>>> inputReportSizes(
  std::span<const std::uint8_t> descriptor, std::string& error)
{
  // Walks the short items of the descriptor (HID 1.11 section 6.2.2.2), keeping the global Report
  // ID, Report Size and Report Count, and adds size x count bits to the current report for every
  // Input main item.
  std::vector<std::pair<std::uint8_t, std::size_t>> bits;
  std::uint8_t reportId = 0;
  std::uint32_t reportSize = 0;
  std::uint32_t reportCount = 0;
  std::size_t at = 0;
  while (at < descriptor.size())
  {
    const std::uint8_t prefix = descriptor[at];
    if (prefix == 0xfe)
    {
      // A long item: its data size follows the prefix.
      if (at + 1 >= descriptor.size())
      {
        error = "long item at byte " + std::to_string(at) + " runs past the end";
        return std::nullopt;
      }
      at += 3 + descriptor[at + 1];
      continue;
    }
    const std::size_t dataSize = (prefix & 3) == 3 ? 4 : (prefix & 3);
    if (at + 1 + dataSize > descriptor.size())
    {
      error = "item at byte " + std::to_string(at) + " runs past the end of the descriptor (" +
              std::to_string(descriptor.size()) + " bytes)";
      return std::nullopt;
    }
    std::uint32_t data = 0;
    for (std::size_t i = 0; i < dataSize; ++i)
    {
      data |= static_cast<std::uint32_t>(descriptor[at + 1 + i]) << (8 * i);
    }
    switch (prefix & 0xfc)
    {
      case 0x84: // Report ID
        reportId = static_cast<std::uint8_t>(data);
        break;
      case 0x74: // Report Size
        reportSize = data;
        break;
      case 0x94: // Report Count
        reportCount = data;
        break;
      case 0x80: // Input
      {
        auto entry = std::find_if(bits.begin(), bits.end(),
                                  [&](const auto& pair) { return pair.first == reportId; });
        if (entry == bits.end())
        {
          bits.emplace_back(reportId, 0);
          entry = bits.end() - 1;
        }
        entry->second += static_cast<std::size_t>(reportSize) * reportCount;
        break;
      }
      default: break;
    }
    at += 1 + dataSize;
  }
  for (auto& entry : bits)
  {
    entry.second = (entry.second + 7) / 8;
  }
  return bits;
}

std::optional<SpaceMouseLayout> spaceMouseLayoutFromDescriptor(
  std::span<const std::uint8_t> descriptor, std::string& error)
{
  const auto sizes = inputReportSizes(descriptor, error);
  if (!sizes)
  {
    return std::nullopt;
  }
  for (const auto& [id, size] : *sizes)
  {
    if (id == kSpaceMouseTranslationReport && size >= 12)
    {
      return SpaceMouseLayout::SixAxisReport;
    }
    if (id == kSpaceMouseTranslationReport && size >= 6)
    {
      return SpaceMouseLayout::SplitReports;
    }
  }
  error = "the report descriptor has no input report 1 of 6 or 12 bytes (not a SpaceMouse?)";
  return std::nullopt;
}

} // namespace proxima

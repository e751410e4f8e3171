#include "Devices/HidapiTransport.h"

#include <hidapi.h>

#include <cwchar>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace proxima
{
namespace
{
std::string narrow(const wchar_t* text)
{
  std::string result;
  for (; text != nullptr && *text != 0; ++text)
  {
    result.push_back(*text < 128 ? static_cast<char>(*text) : '?');
  }
  return result;
}

class HidapiTransport final : public ReportTransport
{
public:
  explicit HidapiTransport(hid_device* device)
    : m_device(device)
  {}
  ~HidapiTransport() override { hid_close(m_device); }
  HidapiTransport(const HidapiTransport&) = delete;
  HidapiTransport& operator=(const HidapiTransport&) = delete;

  TransportResult readReport(std::span<std::uint8_t> buffer, int timeoutMilliseconds) override
  {
    if (m_gone)
    {
      return {TransportStatus::Disconnected, 0};
    }
    const int count = hid_read_timeout(m_device, buffer.data(), buffer.size(), timeoutMilliseconds);
    if (count < 0)
    {
      // hidapi 0.13 reports a vanished hidraw node (poll error, read error) as -1 and nothing
      // finer; a read error on hidraw is a disconnect in practice.
      m_gone = true;
      return {TransportStatus::Disconnected, 0};
    }
    if (count == 0)
    {
      return {TransportStatus::NoData, 0};
    }
    return {TransportStatus::Ok, static_cast<std::size_t>(count)};
  }

  TransportResult writeReport(std::span<const std::uint8_t> report) override
  {
    if (m_gone)
    {
      return {TransportStatus::Disconnected, 0};
    }
    const int count = hid_write(m_device, report.data(), report.size());
    if (count < 0 || static_cast<std::size_t>(count) != report.size())
    {
      return {TransportStatus::Failed, 0};
    }
    return {TransportStatus::Ok, report.size()};
  }

private:
  hid_device* m_device;
  bool m_gone = false;
};
} // namespace

std::vector<HidDeviceInfo> enumerateHidDevices(std::uint16_t vendorId)
{
  std::vector<HidDeviceInfo> devices;
  hid_device_info* list = hid_enumerate(vendorId, 0);
  for (hid_device_info* info = list; info != nullptr; info = info->next)
  {
    HidDeviceInfo device;
    device.path = info->path != nullptr ? info->path : "";
    device.vendorId = info->vendor_id;
    device.productId = info->product_id;
    device.manufacturer = narrow(info->manufacturer_string);
    device.product = narrow(info->product_string);
    device.interfaceNumber = info->interface_number;
    devices.push_back(std::move(device));
  }
  hid_free_enumeration(list);
  return devices;
}

std::unique_ptr<ReportTransport> openHidapiTransport(const std::string& path, std::string& error)
{
  hid_device* device = hid_open_path(path.c_str());
  if (device == nullptr)
  {
    error = path + ": cannot open the HID device (" + narrow(hid_error(nullptr)) +
            "); see the udev rule in Documentation/Devices.md";
    return nullptr;
  }
  return std::make_unique<HidapiTransport>(device);
}

std::optional<std::vector<std::uint8_t>> readHidReportDescriptor(const std::string& path,
                                                                 std::string& error)
{
  const std::size_t slash = path.rfind('/');
  const std::string node = slash == std::string::npos ? path : path.substr(slash + 1);
  // The hidraw node's "device" link leads to its HID device, which holds the descriptor; where
  // that link is missing, the HID device is the node's grandparent in the sysfs tree
  // (.../0003:VVVV:PPPP.NNNN/hidraw/hidrawN).
  const std::string classNode = "/sys/class/hidraw/" + node;
  std::string sysfs = classNode + "/device/report_descriptor";
  std::ifstream file(sysfs, std::ios::binary);
  if (!file)
  {
    std::error_code code;
    const std::filesystem::path real = std::filesystem::canonical(classNode, code);
    if (!code)
    {
      sysfs = (real.parent_path().parent_path() / "report_descriptor").string();
      file.open(sysfs, std::ios::binary);
    }
  }
  if (!file)
  {
    error = classNode + ": cannot open the HID report descriptor in sysfs";
    return std::nullopt;
  }
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                  std::istreambuf_iterator<char>());
  if (bytes.empty())
  {
    error = sysfs + ": the report descriptor is empty";
    return std::nullopt;
  }
  return bytes;
}

} // namespace proxima

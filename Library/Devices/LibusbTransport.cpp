#include "Devices/LibusbTransport.h"

#include "Devices/FtdiRequests.h"

#include <libusb.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace proxima
{
namespace
{
constexpr unsigned char kEndpointIn = 0x81;
constexpr unsigned char kEndpointOut = 0x02;
// bmRequestType of an FTDI request: vendor, to the device, host to device.
constexpr std::uint8_t kVendorOut = 0x40;
// The FT232's one port: FTDI requests carry it in wIndex.
constexpr std::uint16_t kPort = 1;
constexpr unsigned kControlTimeoutMilliseconds = 500;
constexpr unsigned kWriteTimeoutMilliseconds = 100;

TransportStatus statusOf(int code)
{
  if (code == LIBUSB_ERROR_NO_DEVICE || code == LIBUSB_ERROR_IO)
  {
    return TransportStatus::Disconnected;
  }
  return code == LIBUSB_ERROR_TIMEOUT ? TransportStatus::NoData : TransportStatus::Failed;
}

class LibusbTransport final : public BulkTransport
{
public:
  LibusbTransport(libusb_context* context, libusb_device_handle* handle)
    : m_context(context)
    , m_handle(handle)
  {}
  ~LibusbTransport() override
  {
    libusb_release_interface(m_handle, 0);
    libusb_close(m_handle);
    libusb_exit(m_context);
  }
  LibusbTransport(const LibusbTransport&) = delete;
  LibusbTransport& operator=(const LibusbTransport&) = delete;

  TransportResult control(std::uint8_t request, std::uint16_t value, std::uint16_t index) override
  {
    if (m_gone)
    {
      return {TransportStatus::Disconnected, 0};
    }
    const int code = libusb_control_transfer(m_handle, kVendorOut, request, value,
                                             static_cast<std::uint16_t>(index | kPort), nullptr, 0,
                                             kControlTimeoutMilliseconds);
    return finish(code, 0);
  }

  TransportResult write(std::span<const std::uint8_t> bytes) override
  {
    if (m_gone)
    {
      return {TransportStatus::Disconnected, 0};
    }
    int transferred = 0;
    // libusb takes a non-const buffer for both directions; an OUT transfer only reads it.
    const int code =
      libusb_bulk_transfer(m_handle, kEndpointOut, const_cast<unsigned char*>(bytes.data()),
                           static_cast<int>(bytes.size()), &transferred, kWriteTimeoutMilliseconds);
    if (code == 0 && static_cast<std::size_t>(transferred) != bytes.size())
    {
      return {TransportStatus::Failed, static_cast<std::size_t>(transferred)};
    }
    return finish(code, bytes.size());
  }

  TransportResult read(std::span<std::uint8_t> buffer, int timeoutMilliseconds) override
  {
    if (m_gone)
    {
      return {TransportStatus::Disconnected, 0};
    }
    // Room for the payload plus the status bytes of every packet it may span.
    const std::size_t payloadPerPacket = ftdi::kPacketSize - ftdi::kStatusBytes;
    const std::size_t packets =
      std::max<std::size_t>(1, (buffer.size() + payloadPerPacket - 1) / payloadPerPacket);
    const std::size_t rawSize = std::min(packets * ftdi::kPacketSize, m_raw.size());
    int transferred = 0;
    // libusb waits forever on a timeout of 0; "do not wait" is the shortest wait it has.
    const int code =
      libusb_bulk_transfer(m_handle, kEndpointIn, m_raw.data(), static_cast<int>(rawSize),
                           &transferred, static_cast<unsigned>(std::max(1, timeoutMilliseconds)));
    if (code != 0)
    {
      return finish(code, 0);
    }
    // Every packet starts with two modem-status bytes; a packet shorter than that is malformed.
    std::size_t size = 0;
    for (std::size_t at = 0; at < static_cast<std::size_t>(transferred); at += ftdi::kPacketSize)
    {
      const std::size_t packet =
        std::min(ftdi::kPacketSize, static_cast<std::size_t>(transferred) - at);
      if (packet < ftdi::kStatusBytes)
      {
        return {TransportStatus::Failed, 0};
      }
      const std::size_t payload = std::min(packet - ftdi::kStatusBytes, buffer.size() - size);
      std::memcpy(buffer.data() + size, m_raw.data() + at + ftdi::kStatusBytes, payload);
      size += payload;
    }
    return {size == 0 ? TransportStatus::NoData : TransportStatus::Ok, size};
  }

private:
  TransportResult finish(int code, std::size_t size)
  {
    if (code >= 0)
    {
      return {TransportStatus::Ok, size};
    }
    const TransportStatus status = statusOf(code);
    m_gone = status == TransportStatus::Disconnected;
    return {status, 0};
  }

  libusb_context* m_context;
  libusb_device_handle* m_handle;
  std::array<unsigned char, 16 * ftdi::kPacketSize> m_raw{};
  bool m_gone = false;
};
} // namespace

std::vector<UsbDeviceInfo> enumerateUsbDevices(std::uint16_t vendorId, std::uint16_t productId)
{
  std::vector<UsbDeviceInfo> devices;
  libusb_context* context = nullptr;
  if (libusb_init(&context) != 0)
  {
    return devices;
  }
  libusb_device** list = nullptr;
  const ssize_t count = libusb_get_device_list(context, &list);
  for (ssize_t i = 0; i < count; ++i)
  {
    libusb_device_descriptor descriptor{};
    if (libusb_get_device_descriptor(list[i], &descriptor) != 0)
    {
      continue;
    }
    if ((vendorId != 0 && descriptor.idVendor != vendorId) ||
        (productId != 0 && descriptor.idProduct != productId))
    {
      continue;
    }
    devices.push_back(UsbDeviceInfo{descriptor.idVendor, descriptor.idProduct,
                                    libusb_get_bus_number(list[i]),
                                    libusb_get_device_address(list[i])});
  }
  if (count >= 0)
  {
    libusb_free_device_list(list, 1);
  }
  libusb_exit(context);
  return devices;
}

std::unique_ptr<BulkTransport> openFtdiTransport(std::uint16_t vendorId, std::uint16_t productId,
                                                 std::string& error)
{
  libusb_context* context = nullptr;
  if (const int code = libusb_init(&context); code != 0)
  {
    error = std::string("libusb cannot start: ") + libusb_error_name(code);
    return nullptr;
  }
  libusb_device_handle* handle = libusb_open_device_with_vid_pid(context, vendorId, productId);
  if (handle == nullptr)
  {
    char ids[32];
    std::snprintf(ids, sizeof ids, "%04x:%04x", vendorId, productId);
    error = std::string("no USB device ") + ids +
            " can be opened (not connected, or no permission: see the udev rule in "
            "Documentation/Devices.md)";
    libusb_exit(context);
    return nullptr;
  }
  if (libusb_kernel_driver_active(handle, 0) == 1)
  {
    libusb_detach_kernel_driver(handle, 0);
  }
  if (const int code = libusb_claim_interface(handle, 0); code != 0)
  {
    error = std::string("cannot claim the USB interface: ") + libusb_error_name(code);
    libusb_close(handle);
    libusb_exit(context);
    return nullptr;
  }
  return std::make_unique<LibusbTransport>(context, handle);
}

} // namespace proxima

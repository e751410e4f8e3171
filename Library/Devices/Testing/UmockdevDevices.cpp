#include "UmockdevDevices.h"

#include <umockdev.h>

#include <linux/hidraw.h>
#include <linux/ioctl.h>
#include <linux/usbdevice_fs.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <deque>
#include <mutex>
#include <stdexcept>

namespace proxima::testing
{
namespace
{
constexpr const char* kHidrawNode = "/dev/hidraw0";
constexpr const char* kUsbNode = "/dev/bus/usb/001/002";

std::string takeString(gchar* text)
{
  std::string result = text != nullptr ? text : "";
  g_free(text);
  return result;
}

// The ioctl argument's memory resolved into this process, released on scope exit.
struct Resolved
{
  UMockdevIoctlData* data = nullptr;
  Resolved(UMockdevIoctlData* parent, gsize offset, gsize size)
    : data(umockdev_ioctl_data_resolve(parent, offset, size, nullptr))
  {}
  ~Resolved()
  {
    if (data != nullptr)
    {
      g_object_unref(data);
    }
  }
  Resolved(const Resolved&) = delete;
  Resolved& operator=(const Resolved&) = delete;
};

struct HidrawState
{
  SpaceMouseEmulator* emulator = nullptr;
  std::string sysfsPath;
  // Set by the test's thread, read by umockdev's handler thread.
  std::atomic<bool> unplugged{false};
};

gboolean hidrawIoctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user)
{
  auto* state = static_cast<HidrawState*>(user);
  if (state->unplugged)
  {
    umockdev_ioctl_client_complete(client, -1, ENODEV);
    return TRUE;
  }
  const unsigned long request = umockdev_ioctl_client_get_request(client);
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  const std::vector<std::uint8_t>& descriptor = state->emulator->reportDescriptor();
  if (request == HIDIOCGRDESCSIZE)
  {
    Resolved size(arg, 0, sizeof(int));
    const int value = static_cast<int>(descriptor.size());
    std::memcpy(size.data->data, &value, sizeof value);
    umockdev_ioctl_client_complete(client, 0, 0);
    return TRUE;
  }
  if (request == HIDIOCGRDESC)
  {
    Resolved out(arg, 0, sizeof(hidraw_report_descriptor));
    auto* target = reinterpret_cast<hidraw_report_descriptor*>(out.data->data);
    target->size = static_cast<__u32>(descriptor.size());
    std::memcpy(target->value, descriptor.data(), descriptor.size());
    umockdev_ioctl_client_complete(client, 0, 0);
    return TRUE;
  }
  umockdev_ioctl_client_complete(client, -1, ENOTTY);
  return TRUE;
}

gboolean hidrawRead(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user)
{
  auto* state = static_cast<HidrawState*>(user);
  if (state->unplugged)
  {
    // What the kernel's hidraw read gives once the device is gone.
    umockdev_ioctl_client_complete(client, -1, EIO);
    return TRUE;
  }
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  const std::vector<std::uint8_t> report = state->emulator->nextInputReport();
  if (report.empty())
  {
    umockdev_ioctl_client_complete(client, -1, EAGAIN);
    return TRUE;
  }
  const std::size_t size = std::min<std::size_t>(report.size(), arg->data_len);
  std::memcpy(arg->data, report.data(), size);
  umockdev_ioctl_client_complete(client, static_cast<glong>(size), 0);
  return TRUE;
}

gboolean hidrawWrite(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user)
{
  auto* state = static_cast<HidrawState*>(user);
  if (state->unplugged)
  {
    umockdev_ioctl_client_complete(client, -1, ENODEV);
    return TRUE;
  }
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  state->emulator->onOutputReport(std::vector<std::uint8_t>(arg->data, arg->data + arg->data_len));
  umockdev_ioctl_client_complete(client, static_cast<glong>(arg->data_len), 0);
  return TRUE;
}

struct UsbState
{
  FalconEmulator* emulator = nullptr;
  std::string sysfsPath;
  bool unplugged = false;
  std::mutex mutex;
  // Submitted URBs, completed when reaped, in order.
  std::deque<UMockdevIoctlData*> submitted;
};

// Completes one URB against the emulator: control requests, bulk OUT bytes, and bulk IN packets
// of two FTDI modem-status bytes followed by up to 62 payload bytes each.
void completeUrb(UsbState& state, UMockdevIoctlData* urbData)
{
  auto* urb = reinterpret_cast<usbdevfs_urb*>(urbData->data);
  Resolved buffer(urbData, G_STRUCT_OFFSET(usbdevfs_urb, buffer),
                  static_cast<gsize>(std::max(0, urb->buffer_length)));
  std::uint8_t* bytes = buffer.data->data;
  urb->status = 0;
  if (urb->type == USBDEVFS_URB_TYPE_CONTROL && urb->buffer_length >= 8)
  {
    const auto value = static_cast<std::uint16_t>(bytes[2] | (bytes[3] << 8));
    const auto index = static_cast<std::uint16_t>(bytes[4] | (bytes[5] << 8));
    if (bytes[0] == 0x40)
    {
      state.emulator->control(bytes[1], value, index);
    }
    urb->actual_length = 0;
  }
  else if (urb->type == USBDEVFS_URB_TYPE_BULK && (urb->endpoint & 0x80) == 0)
  {
    state.emulator->receive(bytes, static_cast<std::size_t>(urb->buffer_length));
    urb->actual_length = urb->buffer_length;
  }
  else if (urb->type == USBDEVFS_URB_TYPE_BULK)
  {
    int at = 0;
    while (at + 2 <= urb->buffer_length)
    {
      const std::size_t room = std::min(62, urb->buffer_length - at - 2);
      const std::vector<std::uint8_t> payload = state.emulator->transmit(room);
      bytes[at] = 0x31;
      bytes[at + 1] = 0x60;
      std::memcpy(bytes + at + 2, payload.data(), payload.size());
      at += 2 + static_cast<int>(payload.size());
      if (payload.size() < 62)
      {
        break; // a short packet ends the transfer
      }
    }
    urb->actual_length = at;
  }
  else
  {
    urb->status = -EPIPE;
  }
}

gboolean usbIoctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer user)
{
  auto* state = static_cast<UsbState*>(user);
  const unsigned long request = umockdev_ioctl_client_get_request(client);
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  std::lock_guard lock(state->mutex);
  switch (request)
  {
    case USBDEVFS_GET_CAPABILITIES:
    {
      Resolved caps(arg, 0, sizeof(guint32));
      const guint32 value = USBDEVFS_CAP_BULK_CONTINUATION | USBDEVFS_CAP_NO_PACKET_SIZE_LIM |
                            USBDEVFS_CAP_REAP_AFTER_DISCONNECT;
      std::memcpy(caps.data->data, &value, sizeof value);
      umockdev_ioctl_client_complete(client, 0, 0);
      return TRUE;
    }
    case USBDEVFS_GETDRIVER:
      // No kernel driver holds the interface.
      umockdev_ioctl_client_complete(client, -1, ENODATA);
      return TRUE;
    case USBDEVFS_CLAIMINTERFACE:
    case USBDEVFS_RELEASEINTERFACE:
    case USBDEVFS_SETINTERFACE:
    case USBDEVFS_SETCONFIGURATION:
    case USBDEVFS_CLEAR_HALT:
    case USBDEVFS_RESET:
      umockdev_ioctl_client_complete(client, state->unplugged ? -1 : 0,
                                     state->unplugged ? ENODEV : 0);
      return TRUE;
    case USBDEVFS_SUBMITURB:
    {
      if (state->unplugged)
      {
        umockdev_ioctl_client_complete(client, -1, ENODEV);
        return TRUE;
      }
      // Kept (a reference) until reaped; umockdev syncs our changes back to the client then.
      UMockdevIoctlData* urb = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_urb), nullptr);
      state->submitted.push_back(urb);
      umockdev_ioctl_client_complete(client, 0, 0);
      return TRUE;
    }
    case USBDEVFS_REAPURB:
    case USBDEVFS_REAPURBNDELAY:
    {
      if (state->submitted.empty())
      {
        umockdev_ioctl_client_complete(client, -1, state->unplugged ? ENODEV : EAGAIN);
        return TRUE;
      }
      UMockdevIoctlData* urb = state->submitted.front();
      state->submitted.pop_front();
      completeUrb(*state, urb);
      Resolved pointer(arg, 0, sizeof(gpointer));
      umockdev_ioctl_data_set_ptr(pointer.data, 0, urb);
      umockdev_ioctl_client_complete(client, 0, 0);
      g_object_unref(urb);
      return TRUE;
    }
    case USBDEVFS_DISCARDURB:
      // Every URB completes at its reap, so none is left to cancel.
      umockdev_ioctl_client_complete(client, -1, EINVAL);
      return TRUE;
    default: umockdev_ioctl_client_complete(client, -1, ENOTTY); return TRUE;
  }
}
} // namespace

struct UmockdevBed::Impl
{
  UMockdevTestbed* testbed = nullptr;
  UMockdevIoctlBase* hidHandler = nullptr;
  UMockdevIoctlBase* usbHandler = nullptr;
  HidrawState hid;
  UsbState usb;
};

UmockdevBed::UmockdevBed()
  : m_impl(std::make_unique<Impl>())
{
  m_impl->testbed = umockdev_testbed_new();
}

UmockdevBed::~UmockdevBed()
{
  if (m_impl->hidHandler != nullptr)
  {
    g_object_unref(m_impl->hidHandler);
  }
  if (m_impl->usbHandler != nullptr)
  {
    g_object_unref(m_impl->usbHandler);
  }
  {
    std::lock_guard lock(m_impl->usb.mutex);
    for (UMockdevIoctlData* urb : m_impl->usb.submitted)
    {
      g_object_unref(urb);
    }
    m_impl->usb.submitted.clear();
  }
  g_object_unref(m_impl->testbed);
}

bool UmockdevBed::active() const
{
  // The testbed's root has a fresh sys/ folder; under the preload, /sys is that folder.
  const std::string root = takeString(umockdev_testbed_get_root_dir(m_impl->testbed));
  struct stat real
  {};
  struct stat seen
  {};
  return stat((root + "/sys").c_str(), &real) == 0 && stat("/sys", &seen) == 0 &&
         real.st_ino == seen.st_ino && real.st_dev == seen.st_dev;
}

void UmockdevBed::addHidraw(SpaceMouseEmulator& emulator, std::uint16_t vendorId,
                            std::uint16_t productId, const std::string& product)
{
  UMockdevTestbed* bed = m_impl->testbed;
  m_impl->hid.emulator = &emulator;
  m_impl->hidHandler = umockdev_ioctl_base_new();
  g_signal_connect(m_impl->hidHandler, "handle-ioctl", G_CALLBACK(hidrawIoctl), &m_impl->hid);
  g_signal_connect(m_impl->hidHandler, "handle-read", G_CALLBACK(hidrawRead), &m_impl->hid);
  g_signal_connect(m_impl->hidHandler, "handle-write", G_CALLBACK(hidrawWrite), &m_impl->hid);
  GError* error = nullptr;
  if (!umockdev_testbed_attach_ioctl(bed, kHidrawNode, m_impl->hidHandler, &error))
  {
    const std::string message = error->message;
    g_error_free(error);
    throw std::runtime_error("umockdev cannot attach to " + std::string(kHidrawNode) + ": " +
                             message);
  }
  char vendor[8];
  char productText[8];
  char hidName[32];
  char hidId[40];
  std::snprintf(vendor, sizeof vendor, "%04x", vendorId);
  std::snprintf(productText, sizeof productText, "%04x", productId);
  std::snprintf(hidName, sizeof hidName, "0003:%04X:%04X.0001", vendorId, productId);
  std::snprintf(hidId, sizeof hidId, "0003:%08X:%08X", vendorId, productId);
  // The sysfs chain hidapi walks: usb_device > usb_interface > hid > hidraw.
  const std::string usb = takeString(umockdev_testbed_add_device(
    bed, "usb", "usb1/1-1", nullptr, "idVendor", vendor, "idProduct", productText, "manufacturer",
    "3Dconnexion", "product", product.c_str(), "busnum", "1", "devnum", "3", nullptr, "DEVTYPE",
    "usb_device", nullptr));
  const std::string interface =
    takeString(umockdev_testbed_add_device(bed, "usb", "1-1:1.0", usb.c_str(), "bInterfaceNumber",
                                           "00", nullptr, "DEVTYPE", "usb_interface", nullptr));
  const std::string hid = takeString(
    umockdev_testbed_add_device(bed, "hid", hidName, interface.c_str(), nullptr, "HID_ID", hidId,
                                "HID_NAME", product.c_str(), "HID_UNIQ", "", nullptr));
  std::vector<std::uint8_t> descriptor = emulator.reportDescriptor();
  umockdev_testbed_set_attribute_binary(bed, hid.c_str(), "report_descriptor", descriptor.data(),
                                        static_cast<gint>(descriptor.size()));
  // add_from_string (not add_device) so that the /dev node exists for the handler.
  const std::string record =
    "P: " + hid.substr(4) +
    "/hidraw/hidraw0\nN: hidraw0\nE: SUBSYSTEM=hidraw\nE: DEVNAME=" + kHidrawNode + "\n";
  if (!umockdev_testbed_add_from_string(bed, record.c_str(), &error))
  {
    const std::string message = error->message;
    g_error_free(error);
    throw std::runtime_error("umockdev cannot add the hidraw node: " + message);
  }
  m_impl->hid.sysfsPath = hid + "/hidraw/hidraw0";
  // The node is a pty whose reads the handler answers; a byte waiting on its other end makes
  // poll() report it readable, as a real hidraw node is when a report is pending. Reads then
  // reach hidrawRead, which says EAGAIN when the emulator has nothing.
  const int fd = umockdev_testbed_get_dev_fd(bed, kHidrawNode);
  if (fd >= 0)
  {
    const char byte = 0;
    if (::write(fd, &byte, 1) != 1)
    {
      throw std::runtime_error("umockdev: cannot prime the hidraw node's poll");
    }
  }
}

void UmockdevBed::addFalcon(FalconEmulator& emulator)
{
  UMockdevTestbed* bed = m_impl->testbed;
  m_impl->usb.emulator = &emulator;
  m_impl->usbHandler = umockdev_ioctl_base_new();
  g_signal_connect(m_impl->usbHandler, "handle-ioctl", G_CALLBACK(usbIoctl), &m_impl->usb);
  GError* error = nullptr;
  if (!umockdev_testbed_attach_ioctl(bed, kUsbNode, m_impl->usbHandler, &error))
  {
    const std::string message = error->message;
    g_error_free(error);
    throw std::runtime_error("umockdev cannot attach to " + std::string(kUsbNode) + ": " + message);
  }
  // Device descriptor 0403:cb48 (bcdUSB 2.0, class per interface, 8-byte EP0), one
  // configuration with one vendor-class interface and bulk endpoints 0x81 IN and 0x02 OUT of 64
  // bytes: the FT232 layout.
  const char* record =
    "P: /devices/pci0000:00/usb1/1-2\nN: bus/usb/001/002\nE: SUBSYSTEM=usb\nE: DRIVER=usb\n"
    "E: BUSNUM=001\nE: DEVNUM=002\nE: DEVNAME=/dev/bus/usb/001/002\nE: DEVTYPE=usb_device\n"
    "A: bConfigurationValue=1\\n\nA: busnum=1\\n\nA: devnum=2\\n\nA: speed=12\\n\n"
    "A: idVendor=0403\\n\nA: idProduct=cb48\\n\nA: manufacturer=NOVINT\\n\n"
    "A: product=FALCON HAPTIC\\n\n"
    "H: descriptors=120100020000000803044"
    "8cb000601020301"
    "09022000010100802d"
    "0904000002ffffff02"
    "07058102400000"
    "07050202400000\n";
  if (!umockdev_testbed_add_from_string(bed, record, &error))
  {
    const std::string message = error->message;
    g_error_free(error);
    throw std::runtime_error("umockdev cannot add the Falcon: " + message);
  }
  m_impl->usb.sysfsPath = "/sys/devices/pci0000:00/usb1/1-2";
}

void UmockdevBed::unplugHidraw()
{
  m_impl->hid.emulator->unplug();
  m_impl->hid.unplugged = true;
  umockdev_testbed_uevent(m_impl->testbed, m_impl->hid.sysfsPath.c_str(), "remove");
  umockdev_testbed_remove_device(m_impl->testbed, m_impl->hid.sysfsPath.c_str());
}

void UmockdevBed::unplugFalcon()
{
  m_impl->usb.emulator->unplug();
  {
    std::lock_guard lock(m_impl->usb.mutex);
    m_impl->usb.unplugged = true;
  }
  umockdev_testbed_uevent(m_impl->testbed, m_impl->usb.sysfsPath.c_str(), "remove");
}

} // namespace proxima::testing

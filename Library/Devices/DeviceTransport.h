// The two byte pipes a driver talks through, so that one driver runs against the real hidapi or
// libusb and against an in-memory emulator alike. Errors are values: a transport never throws,
// and a vanished device is a status, not a crash.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace proxima
{

/// How a transport call ended.
enum class TransportStatus
{
  /// The call did what it was asked; `size` bytes moved.
  Ok,
  /// Nothing arrived within the timeout (no report pending): not an error.
  NoData,
  /// The device is gone (unplugged, closed): every later call says so too.
  Disconnected,
  /// The call failed for another reason (a malformed transfer, a refused request).
  Failed
};

/// The outcome of one transport call: its status and how many bytes it moved.
struct TransportResult
{
  /// How the call ended; Failed until the transport says otherwise.
  TransportStatus status = TransportStatus::Failed;
  /// Bytes the call moved (read into the buffer, or written); 0 for NoData and Disconnected,
  /// and a failed short write gives the part it did move.
  std::size_t size = 0;

  /// True if the call did what it was asked (`status` is Ok).
  bool ok() const { return status == TransportStatus::Ok; }
};

/// HID reports (hidraw through hidapi, or an emulator): one report per call, its first byte the
/// report ID.
class ReportTransport
{
public:
  virtual ~ReportTransport() = default;
  /// Reads one input report into `buffer`; waits at most `timeoutMilliseconds` (0: do not wait).
  virtual TransportResult readReport(std::span<std::uint8_t> buffer, int timeoutMilliseconds) = 0;
  /// Sends one output report (first byte the report ID).
  virtual TransportResult writeReport(std::span<const std::uint8_t> report) = 0;
};

/// A serial byte stream behind an FTDI USB bridge (libusb bulk endpoints and FTDI vendor
/// requests, or an emulator). Reads return payload only: the FTDI modem-status bytes that lead
/// every USB packet are stripped by the transport.
class BulkTransport
{
public:
  virtual ~BulkTransport() = default;
  /// One FTDI vendor request (SIO_* in FtdiRequests.h) with its value and index.
  virtual TransportResult control(std::uint8_t request, std::uint16_t value,
                                  std::uint16_t index) = 0;
  /// Writes all of `bytes` (bulk OUT).
  virtual TransportResult write(std::span<const std::uint8_t> bytes) = 0;
  /// Reads up to buffer.size() payload bytes (bulk IN); waits at most `timeoutMilliseconds`.
  virtual TransportResult read(std::span<std::uint8_t> buffer, int timeoutMilliseconds) = 0;
};

} // namespace proxima

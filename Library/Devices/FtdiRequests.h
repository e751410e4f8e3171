// The FTDI serial-bridge vendor requests the Falcon driver uses (bRequest values of the FT232's
// SIO interface, as libftdi and the Linux ftdi_sio driver name them), and the values it sends.
#pragma once

#include <cstdint>

namespace proxima::ftdi
{

/// Resets the chip or purges one of its buffers.
constexpr std::uint8_t kRequestReset = 0x00;
/// Sets the DTR and RTS lines.
constexpr std::uint8_t kRequestModemControl = 0x01;
/// Sets the flow control (the driver uses none).
constexpr std::uint8_t kRequestFlowControl = 0x02;
/// Sets the baud rate divisor.
constexpr std::uint8_t kRequestBaudRate = 0x03;
/// Sets data bits, parity and stop bits.
constexpr std::uint8_t kRequestLineProperties = 0x04;
/// Sets how long the chip waits before it sends a part-filled packet.
constexpr std::uint8_t kRequestLatencyTimer = 0x09;

/// kRequestReset values.
constexpr std::uint16_t kResetPurgeReceive = 1;
/// kRequestReset value: purge the transmit buffer.
constexpr std::uint16_t kResetPurgeTransmit = 2;
/// kRequestModemControl values: the high byte says which line the low byte sets.
constexpr std::uint16_t kDtrHigh = 0x0101;
/// kRequestModemControl value: DTR low.
constexpr std::uint16_t kDtrLow = 0x0100;
/// kRequestModemControl value: RTS low.
constexpr std::uint16_t kRtsLow = 0x0200;
/// kRequestLineProperties value for 8 data bits, no parity, one stop bit.
constexpr std::uint16_t kLine8N1 = 0x0008;
/// kRequestBaudRate divisors: 9600 baud on the FT232's 3 MHz clock (312.5), and the two
/// divisors libnifalcon's documentation gives for firmware upload (0x15) and normal I/O (0x02).
constexpr std::uint16_t kBaud9600 = 0x4138;
/// kRequestBaudRate divisor for the firmware upload.
constexpr std::uint16_t kBaudFirmwareUpload = 0x0015;
/// kRequestBaudRate divisor for normal I/O with the firmware running.
constexpr std::uint16_t kBaudNormal = 0x0002;

/// Size of one USB packet on the bulk IN endpoint, and the modem-status bytes leading it.
constexpr std::size_t kPacketSize = 64;
/// The modem-status bytes that lead every packet read from the bulk IN endpoint.
constexpr std::size_t kStatusBytes = 2;

} // namespace proxima::ftdi

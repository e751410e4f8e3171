// The FTDI serial-bridge vendor requests the Falcon driver uses (bRequest values of the FT232's
// SIO interface, as libftdi and the Linux ftdi_sio driver name them), and the values it sends.
#pragma once

#include <cstdint>

namespace proxima::ftdi
{

constexpr std::uint8_t kRequestReset = 0x00;
constexpr std::uint8_t kRequestModemControl = 0x01;
constexpr std::uint8_t kRequestFlowControl = 0x02;
constexpr std::uint8_t kRequestBaudRate = 0x03;
constexpr std::uint8_t kRequestLineProperties = 0x04;
constexpr std::uint8_t kRequestLatencyTimer = 0x09;

/// kRequestReset values.
constexpr std::uint16_t kResetPurgeReceive = 1;
constexpr std::uint16_t kResetPurgeTransmit = 2;
/// kRequestModemControl values: the high byte says which line the low byte sets.
constexpr std::uint16_t kDtrHigh = 0x0101;
constexpr std::uint16_t kDtrLow = 0x0100;
constexpr std::uint16_t kRtsLow = 0x0200;
/// kRequestLineProperties value for 8 data bits, no parity, one stop bit.
constexpr std::uint16_t kLine8N1 = 0x0008;
/// kRequestBaudRate divisors: 9600 baud on the FT232's 3 MHz clock (312.5), and the two
/// divisors libnifalcon's documentation gives for firmware upload (0x15) and normal I/O (0x02).
constexpr std::uint16_t kBaud9600 = 0x4138;
constexpr std::uint16_t kBaudFirmwareUpload = 0x0015;
constexpr std::uint16_t kBaudNormal = 0x0002;

/// Size of one USB packet on the bulk IN endpoint, and the modem-status bytes leading it.
constexpr std::size_t kPacketSize = 64;
constexpr std::size_t kStatusBytes = 2;

} // namespace proxima::ftdi

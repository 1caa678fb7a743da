#pragma once
// The station's Modbus register map (issue 22, docs/station.md "Modbus TCP"): what a PLC reads
// is computed from StationStatus here, and what it writes (the coils) is parsed here, so the
// server (modbus_server.hpp) only moves frames and calls the Station. Addresses are zero-based
// protocol addresses (a PLC that counts from 1 adds one: coil 0 is 00001).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "marker/station/station.hpp"

namespace mark {

// Coils (read/write bits).
inline constexpr int kCoilStart = 0;  // write 1: one mark, async; reads 1 while marking
inline constexpr int kCoilAbort = 1;  // write 1: laser off now; reads 0
inline constexpr int kCoilReset = 2;  // write 1: leave error; reads 0
inline constexpr int kCoilCount = 3;
// Discrete inputs (read-only bits).
inline constexpr int kInputReady = 0;  // idle: a start would mark
inline constexpr int kInputBusy = 1;   // marking
inline constexpr int kInputDone = 2;   // not marking, and the last part ended done
inline constexpr int kInputError = 3;  // error: needs a reset
inline constexpr int kInputCount = 4;
// Input registers (read-only words); 32-bit values low word first.
inline constexpr int kRegisterMarksDone = 0;      // 0–1: parts that ended done since start
inline constexpr int kRegisterSerial = 2;         // 2–3: the last part's first serial value
inline constexpr int kRegisterOutcome = 4;        // 4: the last part's outcome (ModbusOutcome)
inline constexpr int kRegisterRefusedStarts = 5;  // 5–6: start writes refused since start
inline constexpr int kRegisterCount = 7;

enum class ModbusOutcome : std::uint16_t { none = 0, done = 1, aborted = 2, failed = 3, rejected = 4 };

// Modbus exception codes the station answers with (the protocol's own numbers).
inline constexpr std::uint8_t kExceptionIllegalFunction = 0x01;
inline constexpr std::uint8_t kExceptionIllegalAddress = 0x02;
inline constexpr std::uint8_t kExceptionIllegalValue = 0x03;
inline constexpr std::uint8_t kExceptionBusy = 0x06;  // "slave device busy": a refused start or reset

struct ModbusImage {
  std::array<std::uint8_t, kCoilCount> coils{};
  std::array<std::uint8_t, kInputCount> inputs{};
  std::array<std::uint16_t, kRegisterCount> registers{};
};

// What the PLC reads now. `refused_starts` is the server's count of refused start writes.
ModbusImage modbus_image(const StationStatus& status, std::uint32_t refused_starts);

// The last part's serial value for registers 2–3: the first of its counters by name (a job with
// one counter: its value); 0 with none, or one outside 0 to 4294967295 (a register pair cannot
// hold it, and a wrapped number would be a wrong serial).
std::uint32_t modbus_serial_value(const PartResult& part);

// A whole Modbus TCP request as modbus_receive gives it (MBAP header first): its protocol id is
// 0 (Modbus) and its length field counts its bytes from the unit id on. libmodbus 3.1.6 reads a
// frame by its function code and checks neither, and echoes a write's header as it came: a
// frame that fails this is not Modbus or the stream lost its place, so the connection closes.
bool modbus_tcp_frame_sound(const std::uint8_t* adu, std::size_t size);

// A request's PDU (function code first, no MBAP header) as far as the station acts on it.
struct CoilRequest {
  enum Kind { other, write, invalid } kind = other;  // other: not a coil write; libmodbus answers
  std::uint8_t exception = 0;                        // invalid: the exception to answer with
  int first = 0;                                     // write: the first coil written
  std::vector<bool> values;                          // write: one value per coil, in address order
};
// Write Single Coil (0x05: value 0xFF00 on, 0x0000 off) and Write Multiple Coils (0x0F) inside
// coils 0–2 are writes; a malformed one or one beyond coil 2 is invalid (nothing is acted on).
CoilRequest parse_coil_request(const std::uint8_t* pdu, std::size_t size);

}  // namespace mark

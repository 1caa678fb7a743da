#include "marker/station/modbus_map.hpp"

#include <limits>

namespace mark {

namespace {

void put32(std::array<std::uint16_t, kRegisterCount>& r, int at, std::uint32_t value) {
  r[static_cast<std::size_t>(at)] = static_cast<std::uint16_t>(value & 0xFFFFu);  // low word first
  r[static_cast<std::size_t>(at) + 1] = static_cast<std::uint16_t>(value >> 16);
}

ModbusOutcome outcome_of(const PartResult& part) {
  if (part.outcome == JobOutcome::done) return part.rejected ? ModbusOutcome::rejected : ModbusOutcome::done;
  if (part.outcome == JobOutcome::aborted) return ModbusOutcome::aborted;
  return ModbusOutcome::failed;
}

std::uint32_t saturated(std::uint64_t n) {
  return n > std::numeric_limits<std::uint32_t>::max() ? std::numeric_limits<std::uint32_t>::max()
                                                       : static_cast<std::uint32_t>(n);
}

}  // namespace

std::uint32_t modbus_serial_value(const PartResult& part) {
  if (part.serials.empty()) return 0;
  const std::int64_t v = part.serials.begin()->second;
  if (v < 0 || v > static_cast<std::int64_t>(std::numeric_limits<std::uint32_t>::max())) return 0;
  return static_cast<std::uint32_t>(v);
}

ModbusImage modbus_image(const StationStatus& status, std::uint32_t refused_starts) {
  ModbusImage m;
  const bool marking = status.state == StationState::marking;
  m.coils[kCoilStart] = marking ? 1 : 0;  // abort and reset are actions: they read 0
  const StationLights lights = station_lights(status.state, status.last);  // the board's outputs too
  m.inputs[kInputReady] = lights.ready ? 1 : 0;
  m.inputs[kInputBusy] = lights.busy ? 1 : 0;
  m.inputs[kInputDone] = lights.done ? 1 : 0;
  m.inputs[kInputError] = lights.error ? 1 : 0;
  const auto done = status.outcomes.find("done");
  put32(m.registers, kRegisterMarksDone, saturated(done == status.outcomes.end() ? 0 : done->second));
  put32(m.registers, kRegisterSerial, status.last ? modbus_serial_value(*status.last) : 0);
  m.registers[kRegisterOutcome] =
      static_cast<std::uint16_t>(status.last ? outcome_of(*status.last) : ModbusOutcome::none);
  put32(m.registers, kRegisterRefusedStarts, refused_starts);
  return m;
}

bool modbus_tcp_frame_sound(const std::uint8_t* adu, std::size_t size) {
  if (size < 8) return false;
  const std::size_t length = static_cast<std::size_t>(adu[4]) << 8 | adu[5];
  return adu[2] == 0 && adu[3] == 0 && length == size - 6;
}

CoilRequest parse_coil_request(const std::uint8_t* pdu, std::size_t size) {
  CoilRequest r;
  if (size < 1) return r;
  const auto word = [pdu](std::size_t at) { return static_cast<int>(pdu[at]) << 8 | pdu[at + 1]; };
  const auto invalid = [&r](std::uint8_t exception) {
    r.kind = CoilRequest::invalid;
    r.exception = exception;
    return r;
  };
  if (pdu[0] == 0x05) {  // address, value
    if (size != 5) return invalid(kExceptionIllegalValue);
    const int address = word(1), value = word(3);
    if (value != 0xFF00 && value != 0x0000) return invalid(kExceptionIllegalValue);
    if (address >= kCoilCount) return invalid(kExceptionIllegalAddress);
    r.kind = CoilRequest::write;
    r.first = address;
    r.values = {value == 0xFF00};
    return r;
  }
  if (pdu[0] == 0x0F) {  // address, quantity, byte count, the bits (LSB first)
    if (size < 6) return invalid(kExceptionIllegalValue);
    const int address = word(1), quantity = word(3);
    const std::size_t bytes = pdu[5];
    // The protocol's limit is 1968 coils (0x7B0); a byte count that disagrees is malformed.
    if (quantity < 1 || quantity > 0x7B0 || bytes != static_cast<std::size_t>((quantity + 7) / 8) || size != 6 + bytes)
      return invalid(kExceptionIllegalValue);
    if (address + quantity > kCoilCount) return invalid(kExceptionIllegalAddress);
    r.kind = CoilRequest::write;
    r.first = address;
    for (int i = 0; i < quantity; ++i) r.values.push_back((pdu[6 + i / 8] >> (i % 8)) & 1);
    return r;
  }
  return r;
}

}  // namespace mark

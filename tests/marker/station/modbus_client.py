#!/usr/bin/python3
"""An independent Modbus TCP client for `marker serve --modbus` (pymodbus, not libmodbus).

For each of MARKS parts: write coil 0 (start), poll discrete input 1 (busy) until it clears,
then read discrete inputs 0-3 and input registers 0-6. Prints one JSON object: every part's
figures (serial and marks done decoded from the register pairs, low word first) and the start
-> busy-clear round trip in seconds (median, p99). Exits 2 when the station does not answer.

usage: modbus_client.py PORT MARKS [HOST] [POLL_MS]

POLL_MS: the pause between two polls of busy (default 0: back to back), as a PLC's scan cycle.
"""
import json
import sys
import time

from pymodbus.client import ModbusTcpClient


def u32(registers, at):
    return registers[at] | registers[at + 1] << 16  # low word first


def main():
    port, marks = int(sys.argv[1]), int(sys.argv[2])
    host = sys.argv[3] if len(sys.argv) > 3 else "127.0.0.1"
    poll_s = float(sys.argv[4]) / 1000 if len(sys.argv) > 4 else 0.0
    client = ModbusTcpClient(host, port=port, timeout=10)
    if not client.connect():
        print(json.dumps({"error": "cannot connect"}))
        return 2
    parts, trips = [], []
    for _ in range(marks):
        started = time.perf_counter()
        reply = client.write_coil(0, True)
        if reply.isError():
            print(json.dumps({"error": "start refused: " + str(reply)}))
            return 2
        while True:
            busy = client.read_discrete_inputs(1, 1)
            if busy.isError():
                print(json.dumps({"error": str(busy)}))
                return 2
            if not busy.bits[0]:
                break
            if poll_s:
                time.sleep(poll_s)
        trips.append(time.perf_counter() - started)
        inputs = client.read_discrete_inputs(0, 4).bits[:4]
        registers = client.read_input_registers(0, 7).registers
        coil = client.read_coils(0, 3).bits[:3]
        parts.append({
            "ready": inputs[0], "busy": inputs[1], "done": inputs[2], "error": inputs[3],
            "marks_done": u32(registers, 0), "serial": u32(registers, 2),
            "outcome": registers[4], "refused_starts": u32(registers, 5),
            "start_coil": coil[0],
        })
    client.close()
    trips.sort()
    figures = {
        "parts": parts,
        # The quantiles as bench/prog_station_tcp.cpp takes them: sorted[q * (n - 1)].
        "round_trip_median_s": trips[int(0.5 * (len(trips) - 1))] if trips else None,
        "round_trip_p99_s": trips[int(0.99 * (len(trips) - 1))] if trips else None,
    }
    print(json.dumps(figures))
    return 0


if __name__ == "__main__":
    sys.exit(main())

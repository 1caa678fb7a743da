#!/usr/bin/python3
"""The Modbus start coil as a PLC writes it, for bench/prog_station_modbus.cpp (pymodbus: a client
independent of the station's libmodbus).

For each of MARKS parts: take time.monotonic_ns(), write coil 0 (start) at once, poll discrete
input 1 (busy) until it clears, read the last part's first serial value (input registers 2-3,
low word first). Prints one line per part: "<monotonic ns before the write> <serial>", then
"end". time.monotonic_ns() is CLOCK_MONOTONIC, the clock std::chrono::steady_clock reads on
Linux, so the bench subtracts it from the drain's first block directly. Exits 2 when the station
does not answer or refuses a start.

usage: station_modbus_trigger.py PORT MARKS
"""
import sys
import time

from pymodbus.client import ModbusTcpClient


def main():
    port, marks = int(sys.argv[1]), int(sys.argv[2])
    client = ModbusTcpClient("127.0.0.1", port=port, timeout=10)
    if not client.connect():
        print("error cannot connect", flush=True)
        return 2
    for _ in range(marks):
        sent_ns = time.monotonic_ns()
        reply = client.write_coil(0, True)
        if reply.isError():
            print("error start refused: " + str(reply), flush=True)
            return 2
        while True:
            busy = client.read_discrete_inputs(1, 1)
            if busy.isError():
                print("error " + str(busy), flush=True)
                return 2
            if not busy.bits[0]:
                break
        registers = client.read_input_registers(2, 2).registers
        print(sent_ns, registers[0] | registers[1] << 16, flush=True)
    client.close()
    print("end", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

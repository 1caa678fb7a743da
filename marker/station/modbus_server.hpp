#pragma once
// The station's Modbus TCP interface (docs/station.md "Modbus TCP"), libmodbus as the server:
// one thread polls the listening socket and every client; a readable client's request is read
// with modbus_receive, its coil writes become Station calls (modbus_map.hpp parses them), the
// register map is refreshed from Station::status() and modbus_reply answers. Modbus has no
// authentication: a peer the allow-list refuses is closed right after accept, before a
// register is read or written. libmodbus is included only by modbus_server.cpp.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "marker/station/peer_allow.hpp"
#include "marker/station/station.hpp"
#include "marker/station/tcp_server.hpp"

namespace mark {

// Throws InputError when `address` is not loopback and `allow` is empty (Modbus has no
// authentication); the server's constructor checks it too, serve checks it before the store.
void check_modbus_access(const ListenAddress& address, const std::vector<AllowedNet>& allow);

class ModbusServer {
 public:
  // Binds now (throws InputError naming --modbus and the address when it cannot, or when the
  // address is not loopback and `allow` is empty) and serves on its own thread until stop().
  ModbusServer(Station& station, const ListenAddress& address, std::vector<AllowedNet> allow, int max_connections,
               std::function<void(const std::string&)> log = {});
  ~ModbusServer();  // stop()
  ModbusServer(const ModbusServer&) = delete;
  ModbusServer& operator=(const ModbusServer&) = delete;

  int port() const { return port_; }
  // Ends the thread and closes every socket (a start it took stays the station's: abort the
  // station to end that part).
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int port_ = 0;
};

}  // namespace mark

#include "marker/station/modbus_server.hpp"

#include <arpa/inet.h>
#include <modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "base/error.hpp"
#include "marker/station/modbus_map.hpp"

namespace mark {

struct ModbusServer::Impl {
  Station& station;
  std::vector<AllowedNet> allow;
  int max_connections;
  std::function<void(const std::string&)> log;
  modbus_t* ctx = nullptr;
  modbus_mapping_t* mapping = nullptr;
  int listen_fd = -1;
  // stop() signals it: the poll wakes at once, so SIGTERM's abort is not held back by a poll
  // timeout (serve stops this server before it aborts the part).
  int wake_fd = -1;
  std::vector<int> clients;
  std::uint32_t refused_starts = 0;  // only the server thread touches it
  std::atomic<bool> stopping{false};
  std::thread thread;

  Impl(Station& s, std::vector<AllowedNet> a, int max, std::function<void(const std::string&)> l)
      : station(s), allow(std::move(a)), max_connections(max), log(std::move(l)) {}

  void say(const std::string& line) const {
    if (log) log("modbus: " + line);
  }
  void loop();
  void accept_one();
  bool serve_one(int fd);  // false: the connection ended
  std::uint8_t act(const CoilRequest& request);
  void refresh();
  void close_all();
};

void check_modbus_access(const ListenAddress& address, const std::vector<AllowedNet>& allow) {
  in_addr host{};
  ::inet_pton(AF_INET, address.host.c_str(), &host);
  if ((ntohl(host.s_addr) >> 24) != 127 && allow.empty())
    throw InputError("--modbus " + address.host + ":" + std::to_string(address.port) +
                     ": Modbus has no authentication; listening beyond loopback needs --modbus-allow ADDR[/BITS] "
                     "naming the PLC's address or network");
}

ModbusServer::ModbusServer(Station& station, const ListenAddress& address, std::vector<AllowedNet> allow,
                           int max_connections, std::function<void(const std::string&)> log)
    : impl_(std::make_unique<Impl>(station, std::move(allow), max_connections, std::move(log))) {
  check_modbus_access(address, impl_->allow);
  const std::string where = address.host + ":" + std::to_string(address.port);
  Impl& m = *impl_;
  m.ctx = modbus_new_tcp(address.host.c_str(), address.port);
  if (!m.ctx) throw InputError("--modbus " + where + ": " + modbus_strerror(errno));
  // A client that stops mid-frame holds the one server thread for at most this per byte: then
  // modbus_receive fails and the connection is closed.
  modbus_set_byte_timeout(m.ctx, 0, 100'000);
  // A server uses the response timeout only to sleep before it flushes after a bad request
  // (libmodbus 3.1.6 response_exception with to_flush): the default 0.5 s would let any client
  // hold the one server thread half a second per unknown function code. 1 ms still drops the
  // rest of a garbled frame that is already on its way.
  modbus_set_response_timeout(m.ctx, 0, 1'000);
  m.listen_fd = modbus_tcp_listen(m.ctx, 16);
  if (m.listen_fd < 0) {
    const std::string why = modbus_strerror(errno);
    modbus_free(m.ctx);
    throw InputError("--modbus " + where + ": cannot listen there: " + why);
  }
  sockaddr_in sa{};
  socklen_t len = sizeof sa;
  ::getsockname(m.listen_fd, reinterpret_cast<sockaddr*>(&sa), &len);
  port_ = ntohs(sa.sin_port);
  m.mapping = modbus_mapping_new_start_address(0, kCoilCount, 0, kInputCount, 0, 0, 0, kRegisterCount);
  if (!m.mapping) {
    ::close(m.listen_fd);
    modbus_free(m.ctx);
    throw std::bad_alloc();
  }
  m.wake_fd = ::eventfd(0, EFD_CLOEXEC);
  if (m.wake_fd < 0) {
    const std::string why = std::strerror(errno);
    modbus_mapping_free(m.mapping);
    ::close(m.listen_fd);
    modbus_free(m.ctx);
    throw InputError("--modbus " + where + ": " + why);
  }
  m.thread = std::thread([&m] { m.loop(); });
}

ModbusServer::~ModbusServer() { stop(); }

void ModbusServer::stop() {
  Impl& m = *impl_;
  if (m.stopping.exchange(true)) return;
  const std::uint64_t one = 1;
  [[maybe_unused]] const ssize_t n = ::write(m.wake_fd, &one, sizeof one);
  if (m.thread.joinable()) m.thread.join();
  const std::size_t open = m.clients.size();
  m.close_all();
  ::close(m.wake_fd);
  m.say("stopped (" + std::to_string(open) + " connections closed)");
  modbus_mapping_free(m.mapping);
  modbus_free(m.ctx);  // frees only: every socket is closed above
}

void ModbusServer::Impl::close_all() {
  for (const int fd : clients) ::close(fd);
  clients.clear();
  if (listen_fd >= 0) ::close(listen_fd);
  listen_fd = -1;
}

// poll, not select: a descriptor above FD_SETSIZE must not corrupt the stack.
void ModbusServer::Impl::loop() {
  std::vector<pollfd> fds;
  while (!stopping.load()) {
    fds.assign({pollfd{listen_fd, POLLIN, 0}, pollfd{wake_fd, POLLIN, 0}});
    for (const int fd : clients) fds.push_back(pollfd{fd, POLLIN, 0});
    const int r = ::poll(fds.data(), fds.size(), -1);
    if (r <= 0 || stopping.load()) continue;
    std::vector<int> ended;
    for (std::size_t i = 2; i < fds.size(); ++i)
      if (fds[i].revents & (POLLIN | POLLHUP | POLLERR))
        if (!serve_one(fds[i].fd)) ended.push_back(fds[i].fd);
    for (const int fd : ended) {
      ::close(fd);
      clients.erase(std::find(clients.begin(), clients.end(), fd));
      say("connection closed (" + std::to_string(clients.size()) + " open)");
    }
    if (fds[0].revents & POLLIN) accept_one();
  }
}

void ModbusServer::Impl::accept_one() {
  sockaddr_in peer{};
  socklen_t len = sizeof peer;
  const int fd = ::accept4(listen_fd, reinterpret_cast<sockaddr*>(&peer), &len, SOCK_CLOEXEC);
  if (fd < 0) return;
  // getpeername, as the brief of the allow-list says: the address the kernel holds for the
  // connection, before one byte of it is read.
  len = sizeof peer;
  if (::getpeername(fd, reinterpret_cast<sockaddr*>(&peer), &len) != 0 || peer.sin_family != AF_INET) {
    ::close(fd);
    say("connection refused: no IPv4 peer address");
    return;
  }
  const std::uint32_t from = ntohl(peer.sin_addr.s_addr);
  if (!peer_allowed(allow, from)) {
    ::close(fd);
    say("connection refused from " + dotted(from) + ": not in --modbus-allow");
    return;
  }
  if (static_cast<int>(clients.size()) >= max_connections) {
    ::close(fd);
    say("connection refused from " + dotted(from) + ": " + std::to_string(max_connections) + " open already");
    return;
  }
  clients.push_back(fd);
  say("connection opened from " + dotted(from) + " (" + std::to_string(clients.size()) + " open)");
}

bool ModbusServer::Impl::serve_one(int fd) {
  std::uint8_t query[MODBUS_TCP_MAX_ADU_LENGTH];
  modbus_set_socket(ctx, fd);
  const int length = modbus_receive(ctx, query);
  if (length < 0) return false;  // closed, timed out mid-frame or a bad frame
  if (length == 0) return true;  // not for this unit: nothing to answer
  if (!modbus_tcp_frame_sound(query, static_cast<std::size_t>(length))) {
    say("not a Modbus TCP frame (protocol id or length field): closing the connection");
    return false;
  }
  const int header = modbus_get_header_length(ctx);
  const CoilRequest request = parse_coil_request(query + header, static_cast<std::size_t>(length - header));
  std::uint8_t exception = 0;
  if (request.kind == CoilRequest::invalid)
    exception = request.exception;
  else if (request.kind == CoilRequest::write)
    exception = act(request);
  if (exception != 0) return modbus_reply_exception(ctx, query, exception) >= 0;
  refresh();  // the reply reads the station as it is now, the write's effect included
  return modbus_reply(ctx, query, length, mapping) >= 0;
}

// The coils written with 1, in address order, as Station calls; 0 writes do nothing. A start
// or reset the station refuses answers "busy" (exception 6), and a refused start is counted in
// input registers 5–6.
std::uint8_t ModbusServer::Impl::act(const CoilRequest& request) {
  std::uint8_t exception = 0;
  for (std::size_t i = 0; i < request.values.size(); ++i) {
    if (!request.values[i]) continue;
    const int coil = request.first + static_cast<int>(i);
    if (coil == kCoilStart) {
      if (const auto e = station.mark_async()) {
        ++refused_starts;
        say("start refused: " + e->code + " " + e->message);
        exception = kExceptionBusy;
      }
    } else if (coil == kCoilAbort) {
      station.abort();
    } else if (coil == kCoilReset) {
      if (const auto e = station.reset()) {
        say("reset refused: " + e->code + " " + e->message);
        exception = kExceptionBusy;
      }
    }
  }
  return exception;
}

void ModbusServer::Impl::refresh() {
  const ModbusImage image = modbus_image(station.status(), refused_starts);
  std::copy(image.coils.begin(), image.coils.end(), mapping->tab_bits);
  std::copy(image.inputs.begin(), image.inputs.end(), mapping->tab_input_bits);
  std::copy(image.registers.begin(), image.registers.end(), mapping->tab_input_registers);
}

}  // namespace mark

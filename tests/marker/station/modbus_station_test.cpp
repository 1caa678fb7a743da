// `marker serve --modbus` end to end, in process (served_station.hpp: a job on the simulated
// scanner with a real SQLite store). Checked against what the station did not compute: an
// independent client (pymodbus, Debian python3-pymodbus, run as a python script) reads the
// serial and outcome the store then holds; libmodbus's own client decodes the exception codes
// of the edge cases; the audit rows are read back from the store after the station closed.
#include <arpa/inet.h>
#include <modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "marker/station/modbus_map.hpp"
#include "tests/marker/cli_runner.hpp"
#include "tests/marker/station/served_station.hpp"

namespace mark {
namespace {

using test::Served;

// A libmodbus client on 127.0.0.1:`port`, or from `from` (a socket bound to that address).
class ModbusClient {
 public:
  explicit ModbusClient(int port, const char* from = nullptr) : ctx_(modbus_new_tcp("127.0.0.1", port)) {
    if (!from) {
      ok_ = modbus_connect(ctx_) == 0;
      return;
    }
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in sa{};
    sa.sin_family = AF_INET;
    ::inet_pton(AF_INET, from, &sa.sin_addr);
    if (::bind(fd, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0) {
      ::close(fd);
      return;  // bindable() says so
    }
    bound_ = true;
    sa.sin_port = htons(static_cast<std::uint16_t>(port));
    ::inet_pton(AF_INET, "127.0.0.1", &sa.sin_addr);
    ok_ = ::connect(fd, reinterpret_cast<sockaddr*>(&sa), sizeof sa) == 0;
    modbus_set_socket(ctx_, fd);
  }
  ~ModbusClient() {
    modbus_close(ctx_);
    modbus_free(ctx_);
  }
  bool connected() const { return ok_; }
  bool bindable() const { return bound_; }
  // 0 or the errno of a refusal (EMBXSBUSY: exception 6, EMBXILADD: exception 2, …).
  int write_coil(int coil, bool on) { return modbus_write_bit(ctx_, coil, on ? 1 : 0) == 1 ? 0 : errno; }
  std::array<std::uint8_t, kInputCount> inputs() {
    std::array<std::uint8_t, kInputCount> b{};
    EXPECT_EQ(modbus_read_input_bits(ctx_, 0, kInputCount, b.data()), kInputCount) << modbus_strerror(errno);
    return b;
  }
  std::array<std::uint16_t, kRegisterCount> registers() {
    std::array<std::uint16_t, kRegisterCount> r{};
    EXPECT_EQ(modbus_read_input_registers(ctx_, 0, kRegisterCount, r.data()), kRegisterCount) << modbus_strerror(errno);
    return r;
  }
  int start_coil() {
    std::uint8_t b = 9;
    EXPECT_EQ(modbus_read_bits(ctx_, kCoilStart, 1, &b), 1);
    return b;
  }
  modbus_t* ctx() { return ctx_; }

 private:
  modbus_t* ctx_;
  bool ok_ = false, bound_ = false;
};

std::uint32_t u32(const std::array<std::uint16_t, kRegisterCount>& r, int at) {
  return r[static_cast<std::size_t>(at)] | static_cast<std::uint32_t>(r[static_cast<std::size_t>(at) + 1]) << 16;
}

// The independent client: tests/marker/station/modbus_client.py PORT MARKS, its JSON.
nlohmann::json pymodbus_marks(int port, int marks) {
  const std::string command = std::string("/usr/bin/python3 ") + MARKER_SOURCE_DIR +
                              "/tests/marker/station/modbus_client.py " + std::to_string(port) + " " +
                              std::to_string(marks);
  FILE* p = ::popen(command.c_str(), "r");
  std::string out;
  char chunk[4096];
  for (std::size_t n; p && (n = std::fread(chunk, 1, sizeof chunk, p)) > 0;) out.append(chunk, n);
  const int status = p ? ::pclose(p) : -1;
  EXPECT_EQ(status, 0) << out;
  return nlohmann::json::parse(out);
}

TEST(StationModbus, PymodbusStartsMarksAndReadsTheSerialTheStoreHolds) {
  Served s;
  const nlohmann::json r = pymodbus_marks(s.modbus_port(), 3);
  ASSERT_EQ(r["parts"].size(), 3u) << r.dump();
  std::set<std::int64_t> serials;
  for (std::size_t i = 0; i < 3; ++i) {
    const nlohmann::json& part = r["parts"][i];
    EXPECT_EQ(part["marks_done"], i + 1);
    EXPECT_EQ(part["outcome"], 1);  // done
    EXPECT_EQ(part["ready"], true);
    EXPECT_EQ(part["busy"], false);
    EXPECT_EQ(part["done"], true);
    EXPECT_EQ(part["error"], false);
    EXPECT_EQ(part["start_coil"], false);
    EXPECT_EQ(part["refused_starts"], 0);
    serials.insert(part["serial"].get<std::int64_t>());
  }
  EXPECT_EQ(r["parts"][0]["serial"], 41);
  test::expect_rows_are_the_replies(s.close(), serials);  // the store: 41, 42, 43, all done
}

// Real time: a part is slow enough to see busy, refuse a second start and abort it.
TEST(StationModbus, StartWhileBusyIsRefusedAndAbortEndsThePartAborted) {
  Served s(false);
  ModbusClient c(s.modbus_port());
  ASSERT_TRUE(c.connected());
  EXPECT_EQ(c.inputs(), (std::array<std::uint8_t, kInputCount>{1, 0, 0, 0}));  // ready
  ASSERT_EQ(c.write_coil(kCoilStart, true), 0);
  EXPECT_EQ(c.start_coil(), 1);
  EXPECT_EQ(c.inputs(), (std::array<std::uint8_t, kInputCount>{0, 1, 0, 0}));  // busy
  EXPECT_EQ(c.write_coil(kCoilStart, true), EMBXSBUSY);  // refused: exception 6, nothing queued
  EXPECT_EQ(u32(c.registers(), kRegisterRefusedStarts), 1u);
  ASSERT_EQ(c.write_coil(kCoilAbort, true), 0);
  s.station->wait_idle();
  const auto last = s.station->status().last;
  ASSERT_TRUE(last);
  ASSERT_FALSE(last->objects.empty());
  EXPECT_EQ(last->objects[0].result.outcome, JobOutcome::aborted);  // the device stopped: laser off
  const auto r = c.registers();
  EXPECT_EQ(r[kRegisterOutcome], 2);            // aborted
  EXPECT_EQ(u32(r, kRegisterMarksDone), 0u);    // none ended done
  EXPECT_EQ(u32(r, kRegisterSerial), 41u);      // its number, void in the store
  EXPECT_EQ(c.inputs(), (std::array<std::uint8_t, kInputCount>{1, 0, 0, 0}));  // ready, not done
  EXPECT_EQ(c.start_coil(), 0);
  test::expect_one_part(s.close(), 2, 41, Outcome::aborted);
}

// A device fault leaves the station in error: start refused, error input set; the reset coil
// brings it back to ready.
TEST(StationModbus, ResetCoilLeavesError) {
  Served s(true, 8, "fault@50");
  ModbusClient c(s.modbus_port());
  ASSERT_EQ(c.write_coil(kCoilStart, true), 0);
  s.station->wait_idle();
  EXPECT_EQ(c.inputs(), (std::array<std::uint8_t, kInputCount>{0, 0, 0, 1}));  // error
  EXPECT_EQ(c.registers()[kRegisterOutcome], 3);                              // failed
  EXPECT_EQ(c.write_coil(kCoilStart, true), EMBXSBUSY);
  ASSERT_EQ(c.write_coil(kCoilReset, true), 0);
  EXPECT_EQ(c.inputs(), (std::array<std::uint8_t, kInputCount>{1, 0, 0, 0}));  // ready again
  EXPECT_EQ(s.station->status().state, StationState::idle);
  const auto rows = s.close();
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_TRUE(rows[0].outcome);
  EXPECT_EQ(rows[0].outcome->outcome, Outcome::failed);
}

// Frames outside the map get the protocol's exceptions and start nothing.
TEST(StationModbus, BadRequestsAnswerExceptionsAndChangeNothing) {
  Served s;
  ModbusClient c(s.modbus_port());
  std::uint8_t bits[8];
  std::uint16_t words[8];
  EXPECT_EQ(modbus_read_bits(c.ctx(), 0, 4, bits), -1);  // coil 3 does not exist
  EXPECT_EQ(errno, EMBXILADD);
  EXPECT_EQ(modbus_read_input_registers(c.ctx(), 5, 3, words), -1);
  EXPECT_EQ(errno, EMBXILADD);
  const std::uint8_t all[] = {1, 1};
  EXPECT_EQ(modbus_write_bits(c.ctx(), 0, 4, all), -1);  // start..coil 3: refused whole
  EXPECT_EQ(errno, EMBXILADD);
  EXPECT_EQ(modbus_write_register(c.ctx(), 0, 1), -1);  // no holding registers
  EXPECT_EQ(errno, EMBXILADD);
  // Write Single Coil with a value that is neither 0xFF00 nor 0: exception 3.
  const std::uint8_t odd[] = {0xFF, 0x05, 0x00, 0x00, 0x12, 0x34};
  ASSERT_GT(modbus_send_raw_request(c.ctx(), odd, sizeof odd), 0);
  std::uint8_t reply[MODBUS_TCP_MAX_ADU_LENGTH];
  EXPECT_EQ(modbus_receive_confirmation(c.ctx(), reply), 9);
  EXPECT_EQ(reply[7], 0x85);
  EXPECT_EQ(reply[8], kExceptionIllegalValue);
  EXPECT_EQ(c.write_coil(kCoilStart, false), 0);  // a 0 write: nothing
  // A start coil write with protocol id 0xFF00 is not Modbus: the connection closes, unanswered.
  const std::uint8_t not_modbus[] = {0, 9, 0xFF, 0, 0, 6, 0xFF, 0x05, 0, 0, 0xFF, 0};
  const int fd = modbus_get_socket(c.ctx());  // libmodbus leaves it non-blocking: wait for the close
  ASSERT_EQ(::send(fd, not_modbus, sizeof not_modbus, MSG_NOSIGNAL), 12);
  pollfd p{fd, POLLIN, 0};
  ASSERT_EQ(::poll(&p, 1, 5000), 1);
  EXPECT_EQ(::recv(fd, reply, sizeof reply, 0), 0);
  EXPECT_EQ(s.station->status().parts, 0u);
  EXPECT_EQ(s.close().size(), 0u);
}

// Write Multiple Coils 0–2 in one frame acts in address order: start, then abort.
TEST(StationModbus, MultipleCoilWriteActsInAddressOrder) {
  Served s(false);
  ModbusClient c(s.modbus_port());
  const std::uint8_t start_abort[] = {1, 1, 0};
  ASSERT_EQ(modbus_write_bits(c.ctx(), 0, 3, start_abort), 3);
  s.station->wait_idle();
  EXPECT_EQ(c.registers()[kRegisterOutcome], 2);  // aborted
  test::expect_one_part(s.close(), 2, 41, Outcome::aborted);
}

// A peer outside --modbus-allow is closed before it reads anything; one inside is served.
TEST(StationModbus, PeerOutsideTheAllowListIsClosedUnread) {
  Served s;
  ModbusServer guarded(*s.station, parse_host_port("127.0.0.1:0", "--modbus"),
                       {parse_allowed_net("10.20.0.0/16", "--modbus-allow")}, 8);
  ModbusClient local(guarded.port());  // 127.0.0.1: the machine's own, always allowed
  EXPECT_EQ(local.inputs()[kInputReady], 1);
  ModbusClient outside(guarded.port(), "127.0.0.2");
  if (!outside.bindable()) GTEST_SKIP() << "127.0.0.2 does not bind here; PeerAllow.* test the matcher";
  std::uint16_t words[kRegisterCount];
  EXPECT_EQ(modbus_read_input_registers(outside.ctx(), 0, kRegisterCount, words), -1);
  EXPECT_EQ(modbus_write_bit(outside.ctx(), kCoilStart, 1), -1);
  EXPECT_EQ(s.station->status().parts, 0u);
  ModbusServer allowing(*s.station, parse_host_port("127.0.0.1:0", "--modbus"),
                        {parse_allowed_net("127.0.0.2", "--modbus-allow")}, 8);
  ModbusClient inside(allowing.port(), "127.0.0.2");
  EXPECT_EQ(inside.inputs()[kInputReady], 1);
}

// --max-connections holds for Modbus clients too: one more is closed at once; a closed one
// frees its place.
TEST(StationModbus, OneClientOverTheLimitIsClosed) {
  Served s(true, 2);
  auto a = std::make_unique<ModbusClient>(s.modbus_port());
  ModbusClient b(s.modbus_port());
  EXPECT_EQ(a->inputs()[kInputReady], 1);
  EXPECT_EQ(b.inputs()[kInputReady], 1);
  ModbusClient third(s.modbus_port());
  std::uint8_t bit = 0;
  EXPECT_EQ(modbus_read_input_bits(third.ctx(), 0, 1, &bit), -1);
  a.reset();  // its FIN is queued on loopback before the next connect: the server sees it first
  ModbusClient fourth(s.modbus_port());
  EXPECT_EQ(fourth.inputs()[kInputReady], 1);
}

TEST(StationModbus, BeyondLoopbackNeedsAnAllowList) {
  Served s;
  try {
    ModbusServer open(*s.station, parse_host_port("0.0.0.0:0", "--modbus"), {}, 8);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, 61), "--modbus 0.0.0.0:0: Modbus has no authentication; listening b");
  }
  EXPECT_THROW(parse_host_port("0.0.0.0", "--modbus"), InputError);
}

// `marker serve` refuses a bad --modbus / --modbus-allow with one line, before the store is
// created or the device opened.
TEST(StationModbus, ServeRefusesBadModbusOptionsBeforeTheStoreOpens) {
  const auto dir = test::fresh_store_dir("modbus-cli");
  const std::string job = (dir / "line.json").string(), store = (dir / "out" / "s.sqlite").string();
  std::ofstream(job) << test::kStationJob;
  std::filesystem::create_directories(dir / "out");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--modbus", "0.0.0.0:1502"},
       "--modbus 0.0.0.0:1502: Modbus has no authentication; listening beyond loopback needs --modbus-allow "
       "ADDR[/BITS] naming the PLC's address or network"},
      {{"--modbus", "0.0.0.0:1502", "--modbus-allow", "10.1.0.0/33"},
       "--modbus-allow 10.1.0.0/33: the prefix length after / must be a number in 0–32"},
      {{"--modbus-allow", "10.1.0.0/16"}, "--modbus-allow: give --modbus HOST:PORT too"},
      {{"--modbus", "127.0.0.1:70000"}, "--modbus 127.0.0.1:70000: the port must be a number in 0–65535"},
  };
  for (const auto& [extra, message] : cases) {
    std::vector<std::string> args{"serve", "--job", job, "--store", store, "--create-counters"};
    args.insert(args.end(), extra.begin(), extra.end());
    const test::CliResult r = test::run_cli(args);
    EXPECT_EQ(r.code, 1) << message;
    EXPECT_EQ(r.err, "marker: " + message + "\n");
    EXPECT_TRUE(std::filesystem::is_empty(dir / "out")) << message;
  }
  std::filesystem::remove_all(dir);
}

TEST(PeerAllow, ParsesNetworksAndMatchesPeers) {
  const AllowedNet n = parse_allowed_net("192.168.10.77/24", "--modbus-allow");
  EXPECT_EQ(n.net, 0xC0A80A00u);
  EXPECT_EQ(n.mask, 0xFFFFFF00u);
  EXPECT_EQ(parse_allowed_net("10.0.0.1", "--modbus-allow").mask, 0xFFFFFFFFu);
  EXPECT_EQ(parse_allowed_net("0.0.0.0/0", "--modbus-allow").mask, 0u);
  for (const char* bad : {"10.0.0.1/33", "10.0.0/8", "10.0.0.1/", "10.0.0.1/x", "host", ""})
    EXPECT_THROW(parse_allowed_net(bad, "--modbus-allow"), InputError) << bad;
  try {
    parse_allowed_net("10.0.0.1/40", "--modbus-allow");
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--modbus-allow 10.0.0.1/40: the prefix length after / must be a number in 0–32");
  }
  const std::vector<AllowedNet> list{n};
  EXPECT_TRUE(peer_allowed(list, 0xC0A80A05u));   // 192.168.10.5
  EXPECT_FALSE(peer_allowed(list, 0xC0A80B05u));  // 192.168.11.5
  EXPECT_TRUE(peer_allowed(list, 0x7F000001u));   // 127.0.0.1 always
  EXPECT_FALSE(peer_allowed(list, 0x7F000002u));  // other loopback: held to the list
  EXPECT_TRUE(peer_allowed({}, 0x7F000002u));     // no list: loopback
  EXPECT_FALSE(peer_allowed({}, 0xC0A80A05u));
  EXPECT_EQ(dotted(0xC0A80A05u), "192.168.10.5");
}

TEST(ModbusMap, ImageFromStatus) {
  StationStatus st;
  ModbusImage m = modbus_image(st, 0);
  EXPECT_EQ(m.inputs, (std::array<std::uint8_t, kInputCount>{1, 0, 0, 0}));
  EXPECT_EQ(m.registers, (std::array<std::uint16_t, kRegisterCount>{}));
  st.state = StationState::marking;
  st.outcomes["done"] = 0x12345;
  PartResult p;
  p.serials = {{"lot", 0x10002}, {"zz", 7}};  // the first by name
  p.rejected = true;
  st.last = p;
  m = modbus_image(st, 70000);
  EXPECT_EQ(m.coils, (std::array<std::uint8_t, kCoilCount>{1, 0, 0}));
  EXPECT_EQ(m.inputs, (std::array<std::uint8_t, kInputCount>{0, 1, 0, 0}));
  EXPECT_EQ(m.registers, (std::array<std::uint16_t, kRegisterCount>{0x2345, 1, 2, 1, 4, 70000 - 65536, 1}));
  st.state = StationState::idle;
  st.last->rejected = false;
  st.last->serials = {{"sn", -1}};  // a register pair cannot hold it: 0, never a wrapped number
  m = modbus_image(st, 0);
  EXPECT_EQ(m.inputs, (std::array<std::uint8_t, kInputCount>{1, 0, 1, 0}));
  EXPECT_EQ(m.registers[kRegisterSerial], 0);
  EXPECT_EQ(m.registers[kRegisterOutcome], 1);
  st.last->serials = {{"sn", 0x100000000}};
  EXPECT_EQ(modbus_serial_value(*st.last), 0u);
}

TEST(ModbusMap, SoundFramesOnly) {
  const std::uint8_t good[] = {0, 1, 0, 0, 0, 6, 0xFF, 0x05, 0, 0, 0xFF, 0};
  EXPECT_TRUE(modbus_tcp_frame_sound(good, sizeof good));
  std::uint8_t other[sizeof good];
  std::copy(std::begin(good), std::end(good), other);
  other[2] = 0xFF;  // protocol id 0xFF00: not Modbus
  EXPECT_FALSE(modbus_tcp_frame_sound(other, sizeof other));
  other[2] = 0;
  other[5] = 7;  // the length field says one byte more
  EXPECT_FALSE(modbus_tcp_frame_sound(other, sizeof other));
  EXPECT_FALSE(modbus_tcp_frame_sound(good, 7));
}

TEST(ModbusMap, ParsesCoilWrites) {
  const std::uint8_t single[] = {0x05, 0x00, 0x02, 0xFF, 0x00};
  CoilRequest r = parse_coil_request(single, sizeof single);
  ASSERT_EQ(r.kind, CoilRequest::write);
  EXPECT_EQ(r.first, 2);
  EXPECT_EQ(r.values, std::vector<bool>{true});
  const std::uint8_t beyond[] = {0x05, 0x00, 0x03, 0xFF, 0x00};
  EXPECT_EQ(parse_coil_request(beyond, sizeof beyond).exception, kExceptionIllegalAddress);
  const std::uint8_t multi[] = {0x0F, 0x00, 0x01, 0x00, 0x02, 0x01, 0b10};
  r = parse_coil_request(multi, sizeof multi);
  ASSERT_EQ(r.kind, CoilRequest::write);
  EXPECT_EQ(r.first, 1);
  EXPECT_EQ(r.values, (std::vector<bool>{false, true}));
  const std::uint8_t short_count[] = {0x0F, 0x00, 0x00, 0x00, 0x09, 0x01, 0xFF};
  EXPECT_EQ(parse_coil_request(short_count, sizeof short_count).exception, kExceptionIllegalValue);
  const std::uint8_t read[] = {0x01, 0x00, 0x00, 0x00, 0x03};
  EXPECT_EQ(parse_coil_request(read, sizeof read).kind, CoilRequest::other);
  EXPECT_EQ(parse_coil_request(read, 0).kind, CoilRequest::other);
}

}  // namespace
}  // namespace mark

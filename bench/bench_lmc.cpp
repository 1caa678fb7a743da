// The LMC driver's host side (targets from issue 14):
// - encoding, plan in → USB list packets out: the job runner's device program (chords within
//   5 µm, blanking lines as jumps) streamed into the LMC list encoder (3072-byte packets) as the
//   runner does it — a worker converts while the encoder takes 256-command chunks — for the 62
//   characters A–Z a–z 0–9 at 1 mm and for 40 rows of them, and the 40 rows on one thread.
//   Target: 40 rows < 0.5 ms, at least 100× faster than the Python driver's 40–59 ms
//   (1.5–2 µs per command). Counters: device commands, list commands and packets per job.
// - time from `mark` (text in) to the first list packet on the wire, through the whole job
//   runner and LmcDevice on a link that timestamps the first 3072-byte write (the board's
//   answers simulated as READY, as the capture device does), for the 62 characters (more than
//   a packet: the first goes out when 256 list commands are ready) and a serial number (one
//   packet, sent at end_job).
#include <benchmark/benchmark.h>

#include <chrono>
#include <optional>
#include <string>

#include "driver/lmc/job_encoder.hpp"
#include "driver/lmc/lmc_device.hpp"
#include "fonts/catalog.hpp"
#include "marker/job/device_program.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"
#include "marker/job/program_stream.hpp"

namespace {

using namespace mark;
using Clock = std::chrono::steady_clock;

constexpr const char* kCharacters = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";

JobSpec cps_spec(int rows) {
  JobSpec spec;
  std::string text;
  for (int r = 0; r < rows; ++r) text += (r ? "\n" : "") + std::string(kCharacters);
  spec.text = text;
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 1;
  spec.layout.align = Align::center;
  spec.layout.base = Point(0, 0.75 * rows);
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, CornerStrategy::blanking, 1000);
  return spec;
}

DeviceDescription lmc_description() {
  DeviceDescription d;
  d.name = "lmc bench";
  d.level = DeviceLevel::commands;
  d.field_mm = 110;
  d.arcs = false;
  d.chord_tolerance_mm = 0.005;
  return d;
}

// Plan → device program → packets, each packet handed to `on_packet`, as the job runner does
// it: the program streams (ProgramStream) into the encoder in the runner's 256-command chunks.
template <class F>
lmc::EncoderFigures encode_once(const CompiledJob& job, const JobSpec& spec, StreamMode mode,
                                std::size_t& device_commands, F&& on_packet) {
  const lmc::FieldUnits units(110);
  ProgramStream program(job.plan, spec.laser, lmc_description(), mode);
  const lmc::BoardPen pen = lmc::encode_pen(program.pen(), 0, units);
  lmc::JobEncoder enc(units, [&](const lmc::ListPacket& p, const lmc::PacketInfo&) { on_packet(p); });
  enc.start_list(0.008, 1);
  enc.apply_pen(pen);
  std::size_t i = 0;
  for (auto chunk = program.next(0, 256); !chunk.empty(); chunk = program.next(i, 256)) {
    enc.add(chunk, i, std::span(&pen, 1));
    i += chunk.size();
  }
  enc.finish(i);
  device_commands = i;
  return enc.figures();
}

// Plan in → packets out. The plan is compiled once, outside the timing. `wire_hash` (FNV-1a of
// every packet byte, 48 bits so the counter's double holds it exactly) is taken once outside
// the timing too: an optimisation must leave it unchanged, as it must leave the wire.
void encode_plan(benchmark::State& state, int rows, StreamMode mode) {
  const JobSpec spec = cps_spec(rows);
  const CompiledJob job = compile_job(spec, DeviceLevel::commands);
  std::size_t device_commands = 0;
  std::uint64_t hash = 0xcbf29ce484222325ull;
  encode_once(job, spec, mode, device_commands, [&](const lmc::ListPacket& p) {
    for (std::uint8_t b : p.bytes()) hash = (hash ^ b) * 0x100000001b3ull;
  });
  lmc::EncoderFigures figures;
  std::uint64_t checksum = 0;
  for (auto _ : state) {
    figures = encode_once(job, spec, mode, device_commands, [&](const lmc::ListPacket& p) {
      checksum += p.bytes()[12 * 200];  // touch the packet as a USB write would read it
    });
  }
  benchmark::DoNotOptimize(checksum);
  state.counters["device_commands"] = double(device_commands);
  state.counters["list_commands"] = double(figures.list_commands);
  state.counters["packets"] = double(figures.packets);
  state.counters["wire_hash"] = double(hash & 0xFFFFFFFFFFFFull);
}

// The list encoder alone: device commands (converted once) → packets.
void encode_program(benchmark::State& state, int rows) {
  const JobSpec spec = cps_spec(rows);
  const CompiledJob job = compile_job(spec, DeviceLevel::commands);
  const DeviceProgram program = device_program(job.plan, spec.laser, lmc_description());
  const lmc::FieldUnits units(110);
  const lmc::BoardPen pen = lmc::encode_pen(program.pen, 0, units);
  std::uint64_t checksum = 0, list_commands = 0;
  for (auto _ : state) {
    lmc::JobEncoder enc(units, [&](const lmc::ListPacket& p, const lmc::PacketInfo&) {
      checksum += p.bytes()[12 * 200];
    });
    enc.start_list(0.008, 1);
    enc.apply_pen(pen);
    enc.add(program.commands, 0, std::span(&pen, 1));
    enc.finish(program.commands.size());
    list_commands = enc.figures().list_commands;
  }
  benchmark::DoNotOptimize(checksum);
  state.counters["list_commands"] = double(list_commands);
}

void BM_LmcListEncoder40Rows(benchmark::State& state) { encode_program(state, 40); }
BENCHMARK(BM_LmcListEncoder40Rows)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

// The conversion alone: plan → device commands (the job runner's device_program).
void BM_LmcDeviceProgram40Rows(benchmark::State& state) {
  const JobSpec spec = cps_spec(40);
  const CompiledJob job = compile_job(spec, DeviceLevel::commands);
  const DeviceDescription desc = lmc_description();
  for (auto _ : state) benchmark::DoNotOptimize(device_program(job.plan, spec.laser, desc));
}
BENCHMARK(BM_LmcDeviceProgram40Rows)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

// Wall time (UseRealTime): with a worker converting, the CPU column counts the calling thread
// only. 62 characters are below the stream's threshold, so they convert on one thread anyway.
void BM_LmcEncode62Characters(benchmark::State& state) { encode_plan(state, 1, StreamMode::automatic); }
BENCHMARK(BM_LmcEncode62Characters)->UseRealTime()->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_LmcEncode40Rows(benchmark::State& state) { encode_plan(state, 40, StreamMode::automatic); }
BENCHMARK(BM_LmcEncode40Rows)->UseRealTime()->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

// The same on one thread: the conversion and the encoding one after the other.
void BM_LmcEncode40RowsOneThread(benchmark::State& state) { encode_plan(state, 40, StreamMode::whole); }
BENCHMARK(BM_LmcEncode40RowsOneThread)->UseRealTime()->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

// A link that answers like a board that is always READY and never BUSY, and notes when the
// first list packet was written.
class StampLink : public lmc::LmcLink {
 public:
  void write(std::span<const std::uint8_t> bytes) override {
    if (bytes.size() == lmc::kPacketBytes && !first_packet) first_packet = Clock::now();
  }
  std::array<std::uint8_t, lmc::kReplyBytes> read() override {
    lmc::Reply r;
    r.w[3] = lmc::status::ready;
    return lmc::encode_reply(r);
  }
  std::string name() const override { return "bench link"; }
  std::optional<Clock::time_point> first_packet;
};

void mark_to_first_packet(benchmark::State& state, const JobSpec& spec) {
  lmc::LmcOptions o;
  o.init.settle_s = 0;
  o.session.poll_interval_s = 0;
  auto link = std::make_unique<StampLink>();
  StampLink* stamp = link.get();
  lmc::LmcDevice device(std::move(link), o);
  JobOptions jo;
  jo.realtime = false;
  double total_s = 0;
  for (auto _ : state) {
    stamp->first_packet.reset();
    const auto t0 = Clock::now();
    const JobResult r = run_job(spec, jo, device);
    if (r.outcome != JobOutcome::done || !stamp->first_packet) state.SkipWithError("job failed");
    const double s = std::chrono::duration<double>(*stamp->first_packet - t0).count();
    total_s += s;
    state.SetIterationTime(s);
  }
  state.counters["first_packet_us"] = total_s / double(state.iterations()) * 1e6;
}

void BM_LmcMarkToFirstPacket62Characters(benchmark::State& state) {
  mark_to_first_packet(state, cps_spec(1));
}
BENCHMARK(BM_LmcMarkToFirstPacket62Characters)->UseManualTime()->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_LmcMarkToFirstPacketSerial(benchmark::State& state) {
  JobSpec spec = cps_spec(1);
  spec.text = "SN 2026-000123";
  spec.layout.height_mm = 3;
  mark_to_first_packet(state, spec);
}
BENCHMARK(BM_LmcMarkToFirstPacketSerial)->UseManualTime()->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace

#include "marker/production/part_picture.hpp"

#include "base/error.hpp"
#include "marker/job/sim_evaluator.hpp"

namespace mark {

void PartPicture::add(const Plan& plan, const DoseRaster& dose, const std::vector<SimTraceRow>& trace) {
  if (objects_++ == 0) {
    plan_.pen = plan.pen;
    plan_.home = plan.home;
  }
  plan_.commands.insert(plan_.commands.end(), plan.commands.begin(), plan.commands.end());
  plan_.strokes += plan.strokes;
  plan_.jump_length_mm += plan.jump_length_mm;
  dose_.add(dose);
  // Each object's trace starts at its job's device time 0: run on from the last row.
  const double t0 = trace_.empty() ? 0 : trace_.back().t_s;
  for (SimTraceRow r : trace) {
    r.t_s += t0;
    trace_.push_back(r);
  }
}

PartPicture simulate_part(const JobFile& job, const JobFonts& fonts, const std::vector<ObjectText>& texts) {
  PartPicture picture;
  JobOptions options;
  options.virtual_time = true;
  options.realtime = false;  // a picture: no real-time scheduling, no locked memory
  Point home(0, 0);
  for (std::size_t i = 0; i < job.objects.size(); ++i) {
    try {
      const JobSpec spec = object_spec(job, job.objects[i], texts.at(i).text, fonts);
      CompiledJob compiled = compile_job(spec, DeviceLevel::samples, home);
      if (!compiled.plan.commands.empty()) home = compiled.plan.commands.back().end();
      SimScannerOptions scanner_options = simulator_options(spec);
      scanner_options.pixel_mm = picture.dose().pixel_mm();
      SimScanner scanner(scanner_options);
      const JobResult r = run_job_simulated(spec, std::move(compiled), options, scanner);
      picture.add(r.job.plan, scanner.picture_dose(), scanner.trace());
    } catch (const InputError& e) {
      throw InputError(object_place(job, i) + e.what());
    }
  }
  return picture;
}

PartLookSpec part_look(const JobFile& job, const JobFonts& fonts) {
  PartLookSpec look;
  for (std::size_t i = 0; i < job.objects.size(); ++i) {
    const JobSpec spec = object_spec(job, job.objects[i], "", fonts);
    if (i == 0) {
      look.response = spec.verify.response;
      look.look = spec.verify.camera.look;
    }
    for (const CodeObject& c : spec.codes) look.dark_part = look.dark_part || c.layout.invert;
  }
  return look;
}

}  // namespace mark

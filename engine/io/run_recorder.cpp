#include "engine/io/run_recorder.hpp"

#include <utility>

#include "engine/io/run_file_writer.hpp"

namespace washout::io {

RunRecorder::RunRecorder(std::string path, const Checkpoint* resume)
    : path_(std::move(path)),
      resume_(resume != nullptr),
      first_frame_(resume ? static_cast<std::size_t>(resume->frame) + 1 : 0) {}

RunRecorder::~RunRecorder() = default;

void RunRecorder::on_start(const Simulation& sim) {
  const Model& model = sim.model();
  const RunHeader header{model.scene_name, model.scene_source, model.parameter_set.to_json(),
                         sim.params().dim, sim.params().d0,    sim.context().h,
                         sim.params().dt};
  // A restarted run starts from its restored state: the steps up to it stay in the file.
  writer_ = resume_ ? std::make_unique<RunFileWriter>(
                          path_, header,
                          ResumePoint{first_frame_, static_cast<std::size_t>(sim.step_count())})
                    : std::make_unique<RunFileWriter>(path_, header);
}

void RunRecorder::record_step(const Simulation& sim, const StepReport& report) {
  steps_.record(report, sim.probe_values());
  if (sim.bodies()) bodies_.record(*sim.bodies(), report.time);
}

void RunRecorder::record_frame(const Simulation& sim, std::size_t /*frame_index*/,
                               const Checkpoint* restart) {
  if (!writer_) return;
  // The steps that led to the frame first: a file cut at any frame holds its whole history.
  append_series(*writer_, sim);
  writer_->write_frame(sim.view(), sim.step_count(), sim.model().output.fields);
  if (restart) writer_->write_checkpoint(*restart);
}

void RunRecorder::append_series(RunFileWriter& writer, const Simulation& sim) {
  if (steps_.rows() == 0) return;
  steps_.append_to(writer, sim.model().probes);
  if (sim.bodies()) bodies_.append_to(writer, *sim.bodies());
  writer.flush();
}

void RunRecorder::close(const Simulation& sim) {
  // Closed on leaving, also when appending fails.
  const std::unique_ptr<RunFileWriter> writer = std::move(writer_);
  if (writer) append_series(*writer, sim);
}

void RunRecorder::on_abort(const Simulation& sim) { close(sim); }

void RunRecorder::on_finish(const Simulation& sim, const RunSummary&) { close(sim); }

}  // namespace washout::io

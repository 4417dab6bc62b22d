#pragma once
// Keeps a run in its HDF5 file (docs/output.md) by observing it: each frame the run reports,
// with the checkpoint a restart continues from on the output grid, and the per-step series
// (/stats, /probes, /bodies) appended at each frame. The engine reports; this writes.
#include <cstddef>
#include <memory>
#include <string>

#include "engine/io/body_series.hpp"
#include "engine/io/checkpoint.hpp"
#include "engine/io/step_series.hpp"
#include "engine/sim/simulation.hpp"

namespace washout::io {

class RunFileWriter;

class RunRecorder final : public RunObserver {
 public:
  // A new run into `path` (an existing file is replaced), or, with `resume` (the checkpoint that
  // washout run --restart read from `path`), that run continued in its own file after the
  // checkpoint's frame. Throws OutputError from on_start when the file cannot be written.
  explicit RunRecorder(std::string path, const Checkpoint* resume = nullptr);
  ~RunRecorder() override;

  void on_start(const Simulation& sim) override;  // creates the file, or cuts it back
  void record_step(const Simulation& sim, const StepReport& report) override;
  void record_frame(const Simulation& sim, std::size_t frame_index,
                    const Checkpoint* restart) override;
  void on_abort(const Simulation& sim) override;  // keeps the steps so far, closes the file
  void on_finish(const Simulation& sim, const RunSummary& summary) override;  // the same
  std::string kept_in() const override { return path_; }

 private:
  // Appends the steps since the last frame and flushes the file; nothing without new steps.
  void append_series(RunFileWriter& writer, const Simulation& sim);
  void close(const Simulation& sim);

  std::string path_;
  bool resume_ = false;
  std::size_t first_frame_ = 0;  // a restarted run's first frame index
  std::unique_ptr<RunFileWriter> writer_;
  StepSeries steps_;
  BodySeries bodies_;
};

}  // namespace washout::io

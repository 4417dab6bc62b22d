// The run: steps to end_time, writes a frame every output_interval (frame 0 is t = 0), buffers
// the per-step series and appends them to the file at each frame, and turns a blow-up into a
// message that says what blew up, when, and which frame is the last good one.
#include <chrono>
#include <sstream>

#include "engine/fluid/isph_stages.hpp"
#include "engine/io/checkpoint.hpp"
#include "engine/io/run_file_writer.hpp"
#include "engine/sim/rigid_body_system.hpp"
#include "engine/sim/simulation.hpp"

namespace washout {

void Simulation::write_frame(io::RunFileWriter& writer) {
  update_boundary_pressures();
  writer.write_frame(view(), step_, model_.output.fields);
}

void Simulation::flush_series(io::RunFileWriter& writer) {
  const std::size_t rows = series_time_.size();
  if (rows == 0) return;
  writer.append("/stats/time", series_time_.data(), rows);
  writer.append("/stats/step", series_step_.data(), rows);
  writer.append("/stats/dt", series_dt_.data(), rows);
  writer.append("/stats/ppe_iterations", series_iterations_.data(), rows);
  writer.append("/stats/ppe_residual", series_residual_.data(), rows);
  writer.append("/stats/wall_seconds", series_wall_.data(), rows);
  writer.append("/stats/kinetic_energy", series_energy_.data(), rows);
  writer.append("/stats/mechanical_energy", series_mechanical_energy_.data(), rows);
  writer.append("/stats/dt_limit", series_dt_limit_.data(), rows);
  writer.append("/stats/substeps", series_substeps_.data(), rows);
  writer.append("/stats/free_surface_particles", series_free_surface_.data(), rows);
  writer.append("/stats/squeeze_film_particles", series_film_.data(), rows);
  const std::size_t probes = model_.probes.size();
  for (std::size_t k = 0; k < probes; ++k) {
    std::vector<double> values(rows);
    for (std::size_t r = 0; r < rows; ++r) values[r] = probe_series_[r * probes + k];
    writer.append("/probes/" + model_.probes[k].name + "/time", series_time_.data(), rows);
    writer.append("/probes/" + model_.probes[k].name + "/value", values.data(), rows);
  }
  for (auto* v : {&series_time_, &series_dt_, &series_residual_, &series_wall_, &series_energy_,
                  &series_mechanical_energy_})
    v->clear();
  for (auto* v : {&series_step_, &series_iterations_, &series_substeps_, &series_free_surface_,
                  &series_film_, &series_dt_limit_})
    v->clear();
  probe_series_.clear();
  if (bodies_) bodies_->flush(writer);
  writer.flush();
}

RunSummary Simulation::run(const std::string& output_path,
                           const std::vector<RunObserver*>& observers,
                           const io::Checkpoint* resume) {
  const auto& prm = model_.params;
  const auto start = std::chrono::steady_clock::now();
  RunSummary summary;
  summary.output_path = output_path;
  summary.fluid_particles = particles_.fluid_count;
  summary.boundary_particles = particles_.size() - particles_.fluid_count;

  std::size_t frame = 0;
  double next_frame = prm.output_interval;
  std::unique_ptr<io::RunFileWriter> writer;
  const io::RunHeader header{model_.scene_name,
                             model_.scene_source,
                             model_.parameter_set.to_json(),
                             prm.dim,
                             prm.d0,
                             ctx_.h,
                             prm.dt};
  if (resume) {
    // The state right after the checkpoint's frame was written, and the file cut back to it.
    restore_state(*resume);
    frame = static_cast<std::size_t>(resume->frame) + 1;
    next_frame = resume->number("next_frame");
    summary.last_frame_time = resume->number("last_frame_time");
    if (!output_path.empty())
      writer = std::make_unique<io::RunFileWriter>(
          output_path, header, io::ResumePoint{frame, static_cast<std::size_t>(step_)});
  } else if (!output_path.empty()) {
    writer = std::make_unique<io::RunFileWriter>(output_path, header);
  }
  // A frame, then, for a frame on the output grid, the full state after it: a restart from
  // it continues exactly there. The frame a stop (a signal, washout.stop) writes between two
  // has none: the restart goes back to the grid frame before it and replaces it, so that the
  // continued file is the uninterrupted run's, whatever state the solver carried.
  auto emit_frame = [&](bool on_grid) {
    auto s = timer_.measure("output");
    if (writer) {
      flush_series(*writer);
      write_frame(*writer);
      if (on_grid) {
        io::Checkpoint checkpoint;
        checkpoint.frame = static_cast<std::int64_t>(frame);
        save_state(checkpoint);
        checkpoint.numbers["next_frame"] = next_frame;
        checkpoint.numbers["last_frame_time"] = time_;
        writer->write_checkpoint(checkpoint);
      }
    }
    // The solver starts afresh after every grid frame, as it does in a run restarted there: a
    // pcg_amg set-up serving several steps would otherwise carry over the frame, and the
    // restarted run would not be the one that never stopped (a few per cent more set-ups).
    if (on_grid) solver_.reset();
    summary.last_frame_time = time_;
    ++frame;
  };
  if (!resume) {
    // The state at t = 0: densities and probes, then frame 0.
    grid_.build(particles_, 2.0 * ctx_.h, ctx_.periodic);
    grid_.build_list(particles_, particles_.fluid_count, 2.0 * ctx_.h, neighbors_);
    compute_summation_density(ctx_, neighbors_, particles_);
    if (!model_.probes.empty()) evaluate_probes();
    emit_frame(true);
  }
  bool keep_going = true;
  for (auto* o : observers) o->on_start(*this);
  if (!resume)  // a restarted run's frame was seen by the run that wrote it
    for (auto* o : observers) keep_going = o->on_frame(*this, 0) && keep_going;
  RunObserver* stopper = nullptr;
  if (!keep_going)
    for (auto* o : observers) stopper = o;

  const double tolerance = 1e-9 * prm.output_interval;
  try {
    while (keep_going && time_ < prm.end_time - tolerance) {
      StepReport report;
      try {
        // An end_time within the tolerance of a frame time ends the run on that frame's time:
        // a run continued to a later end_time (--restart) then takes the steps of one that
        // never stopped.
        report = step_until(next_frame <= prm.end_time + tolerance ? next_frame : prm.end_time);
      } catch (const UnstableError& e) {
        std::ostringstream m;
        m << "unstable at t = " << time_ << " s (step " << step_ + 1 << "): " << e.what() << ". ";
        if (writer) {
          flush_series(*writer);
          m << "The last good state is frame " << frame - 1 << " (t = " << summary.last_frame_time
            << " s) in " << output_path << ".";
        }
        summary.status = RunStatus::Unstable;
        summary.message = m.str();
        break;
      }
      series_time_.push_back(report.time);
      series_step_.push_back(report.step);
      series_dt_.push_back(report.dt);
      series_iterations_.push_back(report.ppe_iterations);
      series_residual_.push_back(report.ppe_residual);
      series_wall_.push_back(report.wall_seconds);
      series_energy_.push_back(report.kinetic_energy);
      series_mechanical_energy_.push_back(report.mechanical_energy);
      series_dt_limit_.push_back(static_cast<std::int64_t>(report.dt_limit));
      series_substeps_.push_back(report.substeps);
      series_free_surface_.push_back(static_cast<std::int64_t>(report.free_surface_particles));
      series_film_.push_back(static_cast<std::int64_t>(report.squeeze_film_particles));
      probe_series_.insert(probe_series_.end(), probe_values_.begin(), probe_values_.end());
      if (bodies_) bodies_->record(report.time);
      {
        auto s = timer_.measure("callbacks");
        for (auto* o : observers)
          if (!o->on_step(*this, report)) keep_going = false, stopper = o;
      }
      const bool at_frame = time_ >= next_frame - tolerance || time_ >= prm.end_time - tolerance;
      if (at_frame || !keep_going) {
        // The next frame time first: the frame's checkpoint holds it.
        while (next_frame <= time_ + tolerance) next_frame += prm.output_interval;
        emit_frame(at_frame);
        auto s = timer_.measure("callbacks");
        for (auto* o : observers)
          if (!o->on_frame(*this, frame - 1)) keep_going = false, stopper = o;
      }
    }
  } catch (...) {
    // A scene error mid-run (a callback or a motion function that failed): the steps done so
    // far stay in the file, so that the body reports cover them.
    try {
      if (writer) flush_series(*writer);
    } catch (const io::OutputError&) {
      // the scene's error is the one to report
    }
    throw;
  }
  if (summary.status != RunStatus::Unstable && stopper) {
    summary.status = RunStatus::StoppedByScene;
    summary.message = stopper->stop_reason();
  }
  if (writer) flush_series(*writer);
  summary.time = time_;
  summary.steps = step_;
  summary.frames = frame;
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.mean_ppe_iterations = step_ > 0 ? double(total_ppe_iterations_) / step_ : 0.0;
  summary.wall_crossings = wall_crossings_;
  summary.gap_relocations = gap_relocations_;
  summary.stage_seconds = timer_.totals();
  for (auto* o : observers) o->on_finish(*this, summary);
  return summary;
}

}  // namespace washout

// The run: steps to end_time, reports every step and a frame every output_interval (frame 0 is
// t = 0) with, on the output grid, the checkpoint a restart continues from, and turns a blow-up
// into a message that says what blew up, when, and which frame is the last good one. What is
// written is the observers' (engine/io/run_recorder.hpp keeps the run file).
#include <chrono>
#include <optional>
#include <sstream>

#include "engine/fluid/isph_stages.hpp"
#include "engine/io/checkpoint.hpp"
#include "engine/sim/rigid_body_system.hpp"
#include "engine/sim/simulation.hpp"

namespace washout {

RunSummary Simulation::run(const std::vector<RunObserver*>& observers,
                           const io::Checkpoint* resume) {
  const auto& prm = model_.params;
  const auto start = std::chrono::steady_clock::now();
  RunSummary summary;
  for (auto* o : observers)
    if (summary.output_path.empty()) summary.output_path = o->kept_in();
  summary.fluid_particles = particles_.fluid_count;
  summary.boundary_particles = particles_.size() - particles_.fluid_count;

  std::size_t frame = 0;
  double next_frame = prm.output_interval;
  if (resume) {
    // The state right after the checkpoint's frame was written.
    restore_state(*resume);
    frame = static_cast<std::size_t>(resume->frame) + 1;
    next_frame = resume->number("next_frame");
    summary.last_frame_time = resume->number("last_frame_time");
  }
  // A frame, then, for a frame on the output grid, the full state after it: a restart from
  // it continues exactly there. The frame a stop (a signal, washout.stop) writes between two
  // has none: the restart goes back to the grid frame before it and replaces it, so that the
  // continued file is the uninterrupted run's, whatever state the solver carried.
  auto emit_frame = [&](bool on_grid) {
    {
      auto s = timer_.measure("output");
      update_boundary_pressures();
      std::optional<io::Checkpoint> checkpoint;
      if (on_grid) {
        checkpoint.emplace();
        checkpoint->frame = static_cast<std::int64_t>(frame);
        save_state(*checkpoint);
        checkpoint->numbers["next_frame"] = next_frame;
        checkpoint->numbers["last_frame_time"] = time_;
      }
      for (auto* o : observers) o->record_frame(*this, frame, checkpoint ? &*checkpoint : nullptr);
    }
    // The solver starts afresh after every grid frame, as it does in a run restarted there: a
    // pcg_amg or pcg_agg set-up serving several steps would otherwise carry over the frame, and the
    // restarted run would not be the one that never stopped (a few per cent more set-ups).
    if (on_grid) solver_.reset();
    summary.last_frame_time = time_;
    ++frame;
  };
  for (auto* o : observers) o->on_start(*this);
  if (!resume) {
    // The state at t = 0: densities and probes, then frame 0.
    grid_.build(particles_, 2.0 * ctx_.h, ctx_.periodic);
    grid_.build_list(particles_, particles_.fluid_count, 2.0 * ctx_.h, neighbors_);
    compute_summation_density(ctx_, neighbors_, particles_);
    if (!model_.probes.empty()) evaluate_probes();
    emit_frame(true);
  }
  bool keep_going = true;
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
        if (!summary.output_path.empty())
          m << "The last good state is frame " << frame - 1 << " (t = " << summary.last_frame_time
            << " s) in " << summary.output_path << ".";
        summary.status = RunStatus::Unstable;
        summary.message = m.str();
        break;
      }
      {
        auto s = timer_.measure("output");
        for (auto* o : observers) o->record_step(*this, report);
      }
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
    // far stay recorded, so that the body reports cover them.
    for (auto* o : observers) {
      try {
        o->on_abort(*this);
      } catch (const std::exception&) {
        // the scene's error is the one to report
      }
    }
    throw;
  }
  if (summary.status != RunStatus::Unstable && stopper) {
    summary.status = RunStatus::StoppedByScene;
    summary.message = stopper->stop_reason();
  }
  summary.time = time_;
  summary.steps = step_;
  summary.frames = frame;
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.mean_ppe_iterations = step_ > 0 ? double(total_ppe_iterations_) / step_ : 0.0;
  summary.pressure_solver = last_solver_;
  summary.mean_active_boundary = step_ > 0 ? total_active_boundary_ / double(step_) : 0.0;
  summary.wall_crossings = wall_crossings_;
  summary.gap_relocations = gap_relocations_;
  summary.retired_particles = retired_.size();
  summary.first_retirement = describe_first_retirement();
  summary.bodies_asleep_steps = bodies_ ? bodies_->asleep_steps() : 0;
  summary.stage_seconds = timer_.totals();
  for (auto* o : observers) o->on_finish(*this, summary);
  return summary;
}

}  // namespace washout

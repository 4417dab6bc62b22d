#include "engine/io/step_series.hpp"

#include "engine/io/run_file_writer.hpp"

namespace washout::io {

void StepSeries::record(const StepReport& report, const std::vector<double>& probe_values) {
  time_.push_back(report.time);
  step_.push_back(report.step);
  dt_.push_back(report.dt);
  alpha_.push_back(report.alpha);
  ppe_iterations_.push_back(report.ppe_iterations);
  ppe_residual_.push_back(report.ppe_residual);
  wall_seconds_.push_back(report.wall_seconds);
  kinetic_energy_.push_back(report.kinetic_energy);
  mechanical_energy_.push_back(report.mechanical_energy);
  dt_limit_.push_back(static_cast<std::int64_t>(report.dt_limit));
  substeps_.push_back(report.substeps);
  free_surface_.push_back(static_cast<std::int64_t>(report.free_surface_particles));
  squeeze_film_.push_back(static_cast<std::int64_t>(report.squeeze_film_particles));
  retired_.push_back(static_cast<std::int64_t>(report.retired_particles));
  probe_rows_.insert(probe_rows_.end(), probe_values.begin(), probe_values.end());
}

void StepSeries::append_to(RunFileWriter& writer, const std::vector<ProbeSpec>& probes) {
  const std::size_t count = rows();
  if (count == 0) return;
  writer.append("/stats/time", time_.data(), count);
  writer.append("/stats/step", step_.data(), count);
  writer.append("/stats/dt", dt_.data(), count);
  writer.append("/stats/alpha", alpha_.data(), count);
  writer.append("/stats/ppe_iterations", ppe_iterations_.data(), count);
  writer.append("/stats/ppe_residual", ppe_residual_.data(), count);
  writer.append("/stats/wall_seconds", wall_seconds_.data(), count);
  writer.append("/stats/kinetic_energy", kinetic_energy_.data(), count);
  writer.append("/stats/mechanical_energy", mechanical_energy_.data(), count);
  writer.append("/stats/dt_limit", dt_limit_.data(), count);
  writer.append("/stats/substeps", substeps_.data(), count);
  writer.append("/stats/free_surface_particles", free_surface_.data(), count);
  writer.append("/stats/squeeze_film_particles", squeeze_film_.data(), count);
  writer.append("/stats/retired_particles", retired_.data(), count);
  for (std::size_t k = 0; k < probes.size(); ++k) {
    std::vector<double> values(count);
    for (std::size_t r = 0; r < count; ++r) values[r] = probe_rows_[r * probes.size() + k];
    writer.append("/probes/" + probes[k].name + "/time", time_.data(), count);
    writer.append("/probes/" + probes[k].name + "/value", values.data(), count);
  }
  for (auto* v : {&time_, &dt_, &alpha_, &ppe_residual_, &wall_seconds_, &kinetic_energy_,
                  &mechanical_energy_, &probe_rows_})
    v->clear();
  for (auto* v : {&step_, &ppe_iterations_, &substeps_, &free_surface_, &squeeze_film_, &retired_,
                  &dt_limit_})
    v->clear();
}

}  // namespace washout::io

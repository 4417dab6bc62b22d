#pragma once
// The per-step rows of /stats and /probes (docs/output.md), kept from one frame to the next and
// appended to the run file at each frame, so that a run killed between frames loses only the
// steps since the last one.
#include <cstdint>
#include <vector>

#include "engine/model/model.hpp"
#include "engine/sim/simulation.hpp"

namespace washout::io {

class RunFileWriter;

class StepSeries {
 public:
  // One row: the step's report and the probes' values after it.
  void record(const StepReport& report, const std::vector<double>& probe_values);
  std::size_t rows() const { return time_.size(); }
  // Appends the rows kept so far (probe k's under /probes/<probes[k].name>) and forgets them.
  void append_to(RunFileWriter& writer, const std::vector<ProbeSpec>& probes);

 private:
  std::vector<double> time_, dt_, alpha_, ppe_residual_, wall_seconds_, kinetic_energy_,
      mechanical_energy_;
  std::vector<std::int64_t> step_, ppe_iterations_, substeps_, free_surface_, squeeze_film_,
      retired_, dt_limit_;
  std::vector<double> probe_rows_;  // row-major, one value per probe
};

}  // namespace washout::io

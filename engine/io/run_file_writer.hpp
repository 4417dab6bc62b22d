#pragma once
// Writes one run to one HDF5 file with the schema of INTERFACE.md ("Output: HDF5"), flushed
// after every frame so that a run killed at any moment leaves a readable file. An XDMF sidecar
// (same name, .xdmf) is rewritten with each frame so that ParaView opens the particle frames.
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/particle_view.hpp"
#include "engine/io/checkpoint.hpp"

namespace washout::io {

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RunHeader {
  std::string scene_name;
  std::string scene_source;
  std::string parameters_json;
  int dim = 2;
  double d0 = 0.0, h = 0.0, dt = 0.0;  // dt: the fixed step, or 0 when adaptive
};

// Where a restarted run continues an existing file: after frame `frames - 1`, with `series_rows`
// rows in every per-step series (/stats, /probes, /bodies).
struct ResumePoint {
  std::size_t frames = 0;
  std::size_t series_rows = 0;
};

class RunFileWriter {
 public:
  // A new file (an existing one at `path` is replaced).
  RunFileWriter(const std::string& path, const RunHeader& header);
  // An existing run file continued (`washout run --restart`): frames after the resume point are
  // deleted, every per-step series is cut to resume.series_rows rows, the root attributes a
  // finished run adds (wall_seconds, scores, ...) are removed and `parameters` is replaced by
  // header.parameters_json. Frame numbering continues.
  RunFileWriter(const std::string& path, const RunHeader& header, const ResumePoint& resume);
  ~RunFileWriter();
  RunFileWriter(const RunFileWriter&) = delete;
  RunFileWriter& operator=(const RunFileWriter&) = delete;

  const std::string& path() const { return path_; }
  std::size_t frames_written() const { return frames_.size(); }

  // Writes /frames/NNNNNN with the requested fields (position is always written).
  void write_frame(const ParticleView& view, std::int64_t step,
                   const std::vector<std::string>& fields);
  // Appends rows to an extendible dataset ("/stats/time", "/probes/p1/value", ...), creating it
  // and its groups on first use. `columns` = 1 gives a 1-D dataset.
  void append(const std::string& dataset, const double* rows, std::size_t row_count,
              std::size_t columns = 1);
  void append(const std::string& dataset, const std::int64_t* rows, std::size_t row_count,
              std::size_t columns = 1);
  void set_string_attribute(const std::string& object, const std::string& name,
                            const std::string& value);
  // Writes the state of frame checkpoint.frame into /checkpoint/a (even frames) or
  // /checkpoint/b (odd), overwriting what that slot held two frames before. The slot is marked
  // incomplete (and flushed) before its data change and complete after: a run killed while
  // writing one slot leaves the other, the previous frame's, whole.
  void write_checkpoint(const Checkpoint& checkpoint);
  void flush();

 private:
  struct FrameRecord {
    std::string name;
    double time;
    std::size_t count;
    bool has_velocity, has_pressure;
  };
  long long ensure_group(const std::string& path);
  void write_xdmf() const;
  void write_header(const RunHeader& header);  // a new file's root attributes

  std::string path_;
  long long file_ = -1;
  int dim_ = 2;
  std::vector<FrameRecord> frames_;
};

// Adds (or replaces) root attributes of a closed run file: numbers as float64, texts as
// fixed-length UTF-8, as the writer stores its own. Used after a run for its cost and scores.
void write_root_attributes(const std::string& path,
                           const std::vector<std::pair<std::string, double>>& numbers,
                           const std::vector<std::pair<std::string, std::string>>& texts);

}  // namespace washout::io

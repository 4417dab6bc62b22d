#pragma once
// Reads a washout run file (HDF5, schema in docs/output.md and INTERFACE.md).
// Used by `washout render`, by scene tests and by studies. Errors throw RunFileError
// with the file name and the missing object.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/core/particle_view.hpp"
#include "engine/io/checkpoint.hpp"

namespace washout::io {

class RunFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One output frame, copied out of the file. Vectors are [count, dim] row-major, as stored.
struct FrameData {
  int dim = 2;
  double time = 0.0;
  std::int64_t step = 0;
  double d0 = 0.0;
  std::size_t count = 0;
  std::vector<double> position;
  std::vector<double> velocity;  // empty if the run did not write it
  std::vector<double> pressure;  // empty if the run did not write it
  std::vector<std::uint8_t> kind;
  std::vector<std::uint64_t> id;
  std::vector<std::int32_t> body;
  ParticleView view() const;  // valid while this FrameData lives
};

class RunFileReader {
 public:
  explicit RunFileReader(const std::string& path);
  ~RunFileReader();
  RunFileReader(const RunFileReader&) = delete;
  RunFileReader& operator=(const RunFileReader&) = delete;

  const std::string& path() const { return path_; }
  int dim() const { return dim_; }
  double d0() const { return d0_; }
  std::size_t frame_count() const { return frame_names_.size(); }
  std::vector<double> frame_times() const;
  FrameData read_frame(std::size_t index) const;  // throws if index >= frame_count()

  bool has(const std::string& object_path) const;  // e.g. "/bodies/girder"
  // A text attribute of an object (the root by default); throws if it is missing.
  std::string string_attribute(const std::string& name, const std::string& object = "/") const;
  bool has_attribute(const std::string& object, const std::string& name) const;
  // The names of a group's members, sorted (empty if the group does not exist).
  std::vector<std::string> children(const std::string& group) const;
  double double_attribute(const std::string& name) const;  // root attribute
  // The scene script's text: the /scene_source dataset, or the root attribute of older files.
  std::string scene_source() const;
  // A whole dataset as doubles, flattened row-major, e.g. "/stats/time", "/bodies/g/position".
  std::vector<double> read_doubles(const std::string& dataset_path) const;
  std::vector<std::size_t> shape(const std::string& dataset_path) const;
  // The state of the last frame with a complete checkpoint (/checkpoint/a or /b, whichever is
  // newer and whole), or nothing when the file has none. Throws for a checkpoint of another
  // format.
  std::optional<Checkpoint> checkpoint() const;

 private:
  std::string path_;
  long long file_ = -1;  // hid_t
  int dim_ = 2;
  double d0_ = 0.0;
  std::vector<std::string> frame_names_;
};

}  // namespace washout::io

#pragma once
// The full state of a run at one frame, at full precision, for `washout run --restart`
// (docs/output.md "Checkpoint", docs/reliability.md "Restart"). A bag of named arrays and
// numbers: the Simulation, the rigid bodies and the run loop put in what their next step reads,
// the run file stores it under /checkpoint and gives it back unchanged, bit for bit.
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace washout::io {

// A checkpoint that lacks an entry, or holds one of the wrong size: the file is not from this
// scene or this version.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Checkpoint {
  // Bumped whenever what the state holds changes: an older checkpoint is refused.
  static constexpr std::int64_t kFormat = 1;

  std::int64_t frame = -1;  // the frame (/frames/NNNNNN) this state belongs to
  std::map<std::string, double> numbers;
  std::map<std::string, std::int64_t> counts;
  std::map<std::string, std::vector<double>> reals;
  std::map<std::string, std::vector<std::int64_t>> integers;
  std::map<std::string, std::vector<std::uint8_t>> bytes;

  // Readers: throw CheckpointError naming the entry when it is missing or, where a size is
  // given, of another size.
  double number(const std::string& name) const;
  std::int64_t count(const std::string& name) const;
  const std::vector<double>& real(const std::string& name, std::size_t size) const;
  const std::vector<double>& real(const std::string& name) const;
  const std::vector<std::int64_t>& integer(const std::string& name) const;
  const std::vector<std::uint8_t>& byte(const std::string& name, std::size_t size) const;
  bool has_real(const std::string& name) const { return reals.count(name) != 0; }
  bool has_byte(const std::string& name) const { return bytes.count(name) != 0; }
};

// FNV-1a over bytes, for fingerprints of a state's constant parts (the particle layout).
std::uint64_t fnv1a(const void* data, std::size_t size,
                    std::uint64_t hash = 14695981039346656037ull);

}  // namespace washout::io

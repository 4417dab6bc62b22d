#pragma once
// washout.validation{...}: a scene declares how its run is scored against a reference (an
// analytic solution or a CSV under validation/reference/). The error function is Lua, called
// once after the run with a read-only view of the run file (docs/validation.md "Scoring a
// scene"); the shared metrics live in scripts/validation.lua. Nothing here touches the physics.
#include <limits>
#include <string>
#include <vector>

struct lua_State;

namespace washout::lua {

// One declared score and, after evaluate(), its value.
struct ValidationScore {
  std::string name;       // "front", "water_levels", ...; the first declared is the primary
  std::string metric;     // what the number is, e.g. "RMS of Z - Z_ref over T <= 3"
  std::string reference;  // where the reference comes from
  double bound = std::numeric_limits<double>::quiet_NaN();  // documented acceptable error
  double error = std::numeric_limits<double>::quiet_NaN();
  std::string failure;  // set when the error function raised an error
};

class SceneValidation {
 public:
  // Adds `validation` to the table on top of the stack (the `washout` table).
  void install(lua_State* L);
  bool empty() const { return entries_.empty(); }
  // Calls each error function with the run file; a Lua error becomes the score's `failure`.
  std::vector<ValidationScore> evaluate(lua_State* L, const std::string& run_file) const;

 private:
  struct Entry {
    ValidationScore score;
    int function_ref;
  };
  static int l_validation(lua_State* L);
  std::vector<Entry> entries_;
};

// The folder validation/reference/ of the source tree (WASHOUT_REFERENCE overrides it).
std::string reference_dir();

}  // namespace washout::lua

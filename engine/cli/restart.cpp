#include "engine/cli/restart.hpp"

#include <map>
#include <optional>

#include "engine/io/run_file_reader.hpp"

namespace washout::cli {

bool restart_may_change(const std::string& parameter) {
  return parameter == "end_time" || parameter == "threads" || parameter == "max_particles";
}

std::vector<std::pair<std::string, std::string>> parse_parameter_json(const std::string& json) {
  // The flat object ParameterSet::to_json writes: "name": number | "text" | [numbers] | null.
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t k = 0;
  auto fail = [&](const char* what) {
    throw RestartError(std::string("its parameters attribute is not the JSON washout writes (") +
                       what + " at character " + std::to_string(k) + ")");
  };
  auto skip_space = [&] {
    while (k < json.size() && (json[k] == ' ' || json[k] == '\n' || json[k] == '\t')) ++k;
  };
  auto read_string = [&] {
    if (k >= json.size() || json[k] != '"') fail("a string expected");
    const std::size_t begin = k++;
    while (k < json.size() && json[k] != '"') k += json[k] == '\\' ? 2 : 1;
    if (k >= json.size()) fail("an unterminated string");
    return json.substr(begin, ++k - begin);
  };
  skip_space();
  if (k >= json.size() || json[k++] != '{') fail("'{' expected");
  skip_space();
  if (k < json.size() && json[k] == '}') return out;
  while (true) {
    skip_space();
    std::string name = read_string();
    name = name.substr(1, name.size() - 2);
    skip_space();
    if (k >= json.size() || json[k++] != ':') fail("':' expected");
    skip_space();
    std::string value;
    if (k < json.size() && json[k] == '"') {
      value = read_string();
    } else {
      const std::size_t begin = k;
      int depth = 0;
      while (k < json.size() && (depth > 0 || (json[k] != ',' && json[k] != '}'))) {
        depth += json[k] == '[' ? 1 : json[k] == ']' ? -1 : 0;
        ++k;
      }
      value = json.substr(begin, k - begin);
      while (!value.empty() && value.back() == ' ') value.pop_back();
      if (value.empty()) fail("a value expected");
    }
    out.emplace_back(name, value);
    skip_space();
    if (k >= json.size()) fail("'}' expected");
    if (json[k] == '}') break;
    if (json[k++] != ',') fail("',' expected");
  }
  return out;
}

io::Checkpoint load_restart(const std::string& run_path, const Model& model) {
  const std::string cannot = "cannot restart from " + run_path + ": ";
  try {
    io::RunFileReader reader(run_path);
    if (reader.scene_source() != model.scene_source) {
      std::string name;
      if (reader.has_attribute("/", "scene_name")) name = reader.string_attribute("scene_name");
      throw RestartError(cannot + "it is a run of another scene" +
                         (name.empty() ? std::string() : " ('" + name + "')") +
                         " or of an earlier version of " + model.scene_path +
                         " (the scene text stored in it differs); a restart continues the same "
                         "scene");
    }
    std::map<std::string, std::string> then;
    try {
      for (auto& [name, value] : parse_parameter_json(reader.string_attribute("parameters")))
        then[name] = value;
    } catch (const RestartError& e) {
      throw RestartError(cannot + e.what());
    }
    std::string differences;
    int count = 0;
    for (auto& [name, now] : parse_parameter_json(model.parameter_set.to_json())) {
      if (restart_may_change(name)) continue;
      const auto it = then.find(name);
      const std::string before = it == then.end() ? "(not set)" : it->second;
      if (before == now) continue;
      if (++count <= 4)
        differences += (count > 1 ? ", " : "") + name + " = " + before + " there, " + now + " here";
    }
    for (const auto& [name, value] : then)
      if (!restart_may_change(name) && !model.parameter_set.has(name) && ++count <= 4)
        differences += (count > 1 ? ", " : "") + name + " = " + value + " there, not set here";
    if (count > 0)
      throw RestartError(cannot + "it was run with other parameters (" + differences +
                         (count > 4 ? ", and " + std::to_string(count - 4) + " more" : "") +
                         "); restart with the same --set values (only end_time, threads and "
                         "max_particles may change)");
    std::optional<io::Checkpoint> checkpoint = reader.checkpoint();
    if (!checkpoint)
      throw RestartError(cannot +
                         "it holds no complete checkpoint (written before washout wrote "
                         "checkpoints, or a run stopped before its first frame was whole)");
    // Every per-step series must hold the checkpoint's steps: they are cut back to them.
    const std::int64_t steps = checkpoint->count("step");
    for (const std::string group : {"/stats", "/probes", "/bodies"})
      for (const auto& child : reader.children(group)) {
        const std::string path = group + "/" + child;
        const auto members = reader.children(path);
        const std::vector<std::string> datasets =
            members.empty() ? std::vector<std::string>{path} : [&] {
              std::vector<std::string> v;
              for (const auto& m : members) v.push_back(path + "/" + m);
              return v;
            }();
        for (const auto& dataset : datasets) {
          const auto shape = reader.shape(dataset);
          if (shape.empty() || static_cast<std::int64_t>(shape[0]) < steps)
            throw RestartError(
                cannot + dataset + " has " + std::to_string(shape.empty() ? 0 : shape[0]) +
                " rows, fewer than the " + std::to_string(steps) +
                " steps of its checkpoint (frame " + std::to_string(checkpoint->frame) + ")");
        }
      }
    return std::move(*checkpoint);
  } catch (const io::RunFileError& e) {
    throw RestartError(cannot + e.what());
  } catch (const io::CheckpointError& e) {
    throw RestartError(cannot + e.what());
  }
}

}  // namespace washout::cli

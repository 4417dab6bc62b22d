// Mutated scenes (fixed seed, bounded count and time): whatever the mutation, washout ends with
// 0, 1 or 2 within the time bound; never another status, a signal or a hang.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <regex>

#include "reliability/run_washout.hpp"

namespace washout {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::string join(const std::vector<std::string>& lines) {
  std::string t;
  for (const auto& l : lines) t += l + "\n";
  return t;
}

// One random edit of the kinds a hand-edited scene suffers.
std::string mutate(const std::string& scene, std::mt19937& rng) {
  auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  std::vector<std::string> lines = lines_of(scene);
  static const char* numbers[] = {"0",    "-1", "1e9",   "1e-9", "(0/0)", "math.huge",
                                  "-0.5", "3",  "\"x\"", "nil",  "{}",    "true"};
  static const char* statements[] = {"error({})",
                                     "error()",
                                     "error(1)",
                                     "washout.stop()",
                                     "washout.on_step(function(s) error({}) end)",
                                     "washout.on_frame(function(s) return {} end)",
                                     "washout.box {}",
                                     "washout.fluid {}",
                                     "local x = nil + 1"};
  switch (pick(6)) {
    case 0: {  // a number replaced
      const std::regex number(R"(\b\d+(\.\d+)?(e-?\d+)?\b)");
      std::string& l = lines[pick(lines.size())];
      std::vector<std::smatch> found;
      for (auto it = std::sregex_iterator(l.begin(), l.end(), number); it != std::sregex_iterator();
           ++it)
        found.push_back(*it);
      if (found.empty()) break;
      const auto& m = found[pick(found.size())];
      l = l.substr(0, m.position()) + numbers[pick(std::size(numbers))] +
          l.substr(m.position() + m.length());
      break;
    }
    case 1:
      lines.erase(lines.begin() + static_cast<long>(pick(lines.size())));
      break;
    case 2: {
      const auto k = pick(lines.size());
      lines.insert(lines.begin() + static_cast<long>(k), lines[k]);
      break;
    }
    case 3:
      lines.insert(lines.begin() + static_cast<long>(pick(lines.size() + 1)),
                   statements[pick(std::size(statements))]);
      break;
    case 4: {  // one character changed
      std::string& l = lines[pick(lines.size())];
      if (!l.empty()) l[pick(l.size())] = "{}()=,\"x0 "[pick(10)];
      break;
    }
    default: {  // cut short
      std::string t = join(lines);
      return t.substr(0, pick(t.size()));
    }
  }
  return join(lines);
}

TEST(FuzzScenes, MutatedScenesEndWithZeroOneOrTwo) {
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "fuzz_scenes";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ifstream in(std::string(WASHOUT_SOURCE_DIR) + "/tests/data/broken/base.lua");
  std::stringstream base;
  base << in.rdbuf();
  std::mt19937 rng(20240516);
  const int count = 40;
  std::map<int, int> by_status;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < count; ++k) {
    std::string scene = base.str();
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits; ++e) scene = mutate(scene, rng);
    const fs::path path = dir / ("mutant_" + std::to_string(k) + ".lua");
    std::ofstream(path) << scene;
    // Bounds keep every mutant fast: few particles, short Lua calls, a short run.
    const auto r = test::run_washout(
        {"run", path.string(), "--out", (dir / ("out_" + std::to_string(k))).string(), "--quiet",
         "--lua-time-limit", "2", "--lua-memory-limit", "128", "--set", "max_particles=20000",
         "--set", "end_time=0.02"},
        (dir / ("mutant_" + std::to_string(k) + ".log")).string(), 60);
    ++by_status[r.status];
    EXPECT_FALSE(r.timed_out) << path << " hung";
    EXPECT_EQ(r.signal, 0) << path << " died by signal " << r.signal << "\n" << r.output;
    EXPECT_TRUE(r.status == 0 || r.status == 1 || r.status == 2)
        << path << " exited " << r.status << "\n"
        << r.output;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("fuzz: %d mutants in %.1f s;", count, seconds);
  for (const auto& [status, n] : by_status) std::printf(" exit %d: %d", status, n);
  std::printf("\n");
}

}  // namespace
}  // namespace washout

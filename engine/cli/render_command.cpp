#include "engine/cli/render_command.hpp"

#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/io/run_file_reader.hpp"
#include "render/frame_renderer.hpp"

extern char** environ;

namespace washout::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kExitOk = 0;
constexpr int kExitBadInput = 1;
constexpr int kExitOutput = 3;
constexpr int kVideoFramesPerSecond = 25;

constexpr const char* kUsage = R"(usage: washout render RUN.h5 [options]

Draws the particle frames of a run file as PNG images DIR/frame_NNNNNN.png, numbered by
output-frame index (frame_000000.png is the initial state).

options:
  --out DIR            folder for the images (default: <folder of RUN.h5>/frames)
  --every K            draw every K-th output frame (default 1: all)
  --frame I            draw only output frame I
  --width W            image width in pixels (default 1280)
  --height H           image height in pixels (default 720)
  --color FIELD        fluid colour: speed (default), pressure, vertical_velocity
  --range MIN,MAX      fixed colour range (default: from the first frame with any spread)
  --camera PRESET      3D view: perspective (default), side, top; 2D is always the x-y plane
  --region X0,Y0,X1,Y1 fit the view to this box instead of all particles (a zoom); in 3D
                       X0,Y0,Z0,X1,Y1,Z1
  --supersample S      render at S times the size and average down, 1 to 4 (default 2)
  --no-cutaway         3D: also draw the walls between the camera and the water
  --video              also make DIR/<run name>.mp4 with ffmpeg, if ffmpeg is installed
  -h, --help           show this help

exit status: 0 success, 1 bad input, 3 output could not be written
)";

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RenderCommandOptions {
  std::string run_path;
  std::string out_dir;
  int every = 1;
  std::optional<long long> frame;
  bool video = false;
  bool help = false;
  render::RenderOptions render;
};

long long parse_integer(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  long long value = 0;
  try {
    value = std::stoll(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) {
    throw UsageError(option + " needs a whole number, not '" + text + "'");
  }
  return value;
}

double parse_number(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) {
    throw UsageError(option + " needs a number, not '" + text + "'");
  }
  return value;
}

int parse_positive_int(const std::string& option, const std::string& text) {
  const long long v = parse_integer(option, text);
  if (v < 1 || v > 1000000) throw UsageError(option + " must be a positive whole number");
  return static_cast<int>(v);
}

// --region X0,Y0,X1,Y1 (2D) or X0,Y0,Z0,X1,Y1,Z1 (3D): the box the view is fitted to.
render::CameraSpec with_region(render::CameraSpec camera, const std::string& name,
                               const std::string& text) {
  std::vector<double> numbers;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    numbers.push_back(parse_number(name, text.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (numbers.size() != 4 && numbers.size() != 6)
    throw UsageError(
        "--region needs X0,Y0,X1,Y1 (2D) or X0,Y0,Z0,X1,Y1,Z1 (3D), e.g. 0.5,0,2.5,0.6");
  const int n = static_cast<int>(numbers.size() / 2);
  camera.region_components = n;
  for (int a = 0; a < n; ++a) {
    camera.region_min[a] = numbers[a];
    camera.region_max[a] = numbers[n + a];
  }
  return camera;
}

RenderCommandOptions parse(int argc, char** argv) {
  RenderCommandOptions o;
  std::vector<std::string> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string name = args[i];
    std::optional<std::string> inline_value;
    if (name.rfind("--", 0) == 0 && name.find('=') != std::string::npos) {
      inline_value = name.substr(name.find('=') + 1);
      name = name.substr(0, name.find('='));
    }
    auto value = [&]() -> std::string {
      if (inline_value) return *inline_value;
      if (i + 1 >= args.size()) throw UsageError(name + " needs a value");
      return args[++i];
    };
    if (name == "-h" || name == "--help") {
      o.help = true;
    } else if (name == "--out") {
      o.out_dir = value();
    } else if (name == "--every") {
      o.every = parse_positive_int(name, value());
    } else if (name == "--frame") {
      o.frame = parse_integer(name, value());
      if (*o.frame < 0) throw UsageError("--frame must be 0 or more");
    } else if (name == "--width") {
      o.render.width = parse_positive_int(name, value());
    } else if (name == "--height") {
      o.render.height = parse_positive_int(name, value());
    } else if (name == "--color" || name == "--colour") {
      o.render.color_field = value();
    } else if (name == "--camera") {
      o.render.camera.preset = value();
    } else if (name == "--supersample") {
      o.render.supersample = parse_positive_int(name, value());
    } else if (name == "--range") {
      const std::string text = value();
      const std::size_t comma = text.find(',');
      if (comma == std::string::npos) throw UsageError("--range needs MIN,MAX, e.g. 0,2.5");
      o.render.fixed_range = true;
      o.render.range_min = parse_number(name, text.substr(0, comma));
      o.render.range_max = parse_number(name, text.substr(comma + 1));
    } else if (name == "--region") {
      o.render.camera = with_region(o.render.camera, name, value());
    } else if (name == "--video") {
      o.video = true;
    } else if (name == "--no-cutaway") {
      o.render.cutaway_walls = false;
    } else if (name.rfind("-", 0) == 0 && name.size() > 1) {
      throw UsageError("unknown option " + name);
    } else if (o.run_path.empty()) {
      o.run_path = name;
    } else {
      throw UsageError("more than one run file given ('" + o.run_path + "' and '" + name + "')");
    }
  }
  if (o.help) return o;
  if (o.run_path.empty()) throw UsageError("no run file given");
  if (o.frame && o.every != 1) throw UsageError("use either --frame or --every, not both");
  if (o.out_dir.empty()) {
    const fs::path parent = fs::path(o.run_path).parent_path();
    o.out_dir = (parent.empty() ? fs::path("frames") : parent / "frames").string();
  }
  return o;
}

std::string frame_file_name(std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%06zu.png", index);
  return name;
}

bool ffmpeg_available() { return std::system("command -v ffmpeg >/dev/null 2>&1") == 0; }

// Runs a program found on PATH with the given arguments (no shell, so no quoting problems).
int run_program(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Stitches exactly the frames written now (an ffconcat list, so that other PNGs in the folder
// and gaps left by --every do not matter) into an H.264 video at 25 frames per second.
int make_video(const fs::path& out_dir, const std::vector<std::string>& frames,
               const std::string& run_path) {
  if (!ffmpeg_available()) {
    std::printf(
        "washout render: --video skipped: ffmpeg is not installed (it is optional; the PNG "
        "frames are in %s; install ffmpeg, e.g. apt-get install ffmpeg, to make videos)\n",
        out_dir.string().c_str());
    return kExitOk;
  }
  if (frames.size() < 2) {
    std::printf("washout render: --video skipped: a video needs at least two frames\n");
    return kExitOk;
  }
  const fs::path list = out_dir / "frames.ffconcat";
  {
    std::ofstream out(list);
    out << "ffconcat version 1.0\n";
    for (const std::string& f : frames) {
      out << "file '" << f << "'\nduration " << 1.0 / kVideoFramesPerSecond << "\n";
    }
    out << "file '" << frames.back() << "'\n";  // the demuxer needs the last entry twice
    if (!out) {
      std::fprintf(stderr, "washout render: cannot write %s\n", list.string().c_str());
      return kExitOutput;
    }
  }
  const fs::path video = out_dir / (fs::path(run_path).stem().string() + ".mp4");
  const int status = run_program(
      {"ffmpeg", "-y", "-loglevel", "error", "-f", "concat", "-safe", "0", "-i", list.string(),
       "-vf", "fps=" + std::to_string(kVideoFramesPerSecond) + ",scale=trunc(iw/2)*2:trunc(ih/2)*2",
       "-pix_fmt", "yuv420p", video.string()});
  std::error_code ignored;
  fs::remove(list, ignored);
  if (status != 0) {
    std::fprintf(stderr, "washout render: ffmpeg failed (exit %d) making %s\n", status,
                 video.string().c_str());
    return kExitOutput;
  }
  std::printf("video %s\n", video.string().c_str());
  return kExitOk;
}

int render_frames(const RenderCommandOptions& o) {
  render::FrameRenderer renderer(o.render);  // validates field, camera, size first
  const io::RunFileReader reader(o.run_path);
  const std::size_t count = reader.frame_count();
  if (count == 0) {
    std::fprintf(stderr, "washout render: %s has no frames\n", o.run_path.c_str());
    return kExitBadInput;
  }
  std::vector<std::size_t> indices;
  if (o.frame) {
    if (static_cast<unsigned long long>(*o.frame) >= count) {
      std::fprintf(stderr,
                   "washout render: frame %lld is out of range: %s has %zu frames (0..%zu)\n",
                   *o.frame, o.run_path.c_str(), count, count - 1);
      return kExitBadInput;
    }
    indices.push_back(static_cast<std::size_t>(*o.frame));
  } else {
    for (std::size_t i = 0; i < count; i += static_cast<std::size_t>(o.every)) indices.push_back(i);
  }

  const fs::path out_dir(o.out_dir);
  std::error_code error;
  fs::create_directories(out_dir, error);
  if (error || !fs::is_directory(out_dir)) {
    std::fprintf(stderr, "washout render: cannot create output folder %s: %s\n",
                 out_dir.string().c_str(), error ? error.message().c_str() : "not a folder");
    return kExitOutput;
  }

  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> written;
  for (const std::size_t index : indices) {
    const io::FrameData frame = reader.read_frame(index);
    const std::string name = frame_file_name(index);
    renderer.render_png(frame.view(), (out_dir / name).string());
    written.push_back(name);
    std::printf("frame %zu (t = %.4f s, %zu particles) -> %s\n", index, frame.time, frame.count,
                (out_dir / name).string().c_str());
    std::fflush(stdout);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%zu frame(s) in %.2f s (%.3f s per frame) in %s\n", written.size(), seconds,
              seconds / static_cast<double>(written.size()), out_dir.string().c_str());
  if (const auto range = renderer.color_range()) {
    std::printf("colour %s from %g to %g\n", o.render.color_field.c_str(), range->min, range->max);
  }
  return o.video ? make_video(out_dir, written, o.run_path) : kExitOk;
}

}  // namespace

int run_render_command(int argc, char** argv) {
  RenderCommandOptions options;
  try {
    options = parse(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "washout render: %s (see washout render --help)\n", e.what());
    return kExitBadInput;
  }
  if (options.help) {
    std::fputs(kUsage, stdout);
    return kExitOk;
  }
  try {
    return render_frames(options);
  } catch (const render::ImageWriteError& e) {
    std::fprintf(stderr, "washout render: %s\n", e.what());
    return kExitOutput;
  } catch (const render::ContextError& e) {
    std::fprintf(stderr, "washout render: %s\n", e.what());
    return kExitOutput;
  } catch (const render::RenderError& e) {
    std::fprintf(stderr, "washout render: %s\n", e.what());
    return kExitBadInput;
  } catch (const io::RunFileError& e) {
    std::fprintf(stderr, "washout render: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {  // e.g. a frame too large to hold: never an abort
    std::fprintf(stderr, "washout render: cannot read %s: %s\n", options.run_path.c_str(),
                 e.what());
    return kExitBadInput;
  }
}

}  // namespace washout::cli

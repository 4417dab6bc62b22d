// `washout render`: frames written and numbered by output-frame index, --every/--frame/--out,
// exit statuses for bad input (1) and unwritable output (3), --video with and without ffmpeg,
// and every `washout render` example of docs/render.md run against a small run file.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <png.h>
#include <sys/stat.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/cli/render_command.hpp"
#include "render/frame_renderer.hpp"

namespace washout {
namespace {

namespace fs = std::filesystem;

// One frame's particles stored as in the run file: vectors [N, dim] row-major.
struct StoredFrame {
  int dim = 2;
  double d0 = 0.01;
  double time = 0.0;
  std::vector<double> position, velocity, pressure;
  std::vector<std::uint8_t> kind;
  std::vector<std::int32_t> body;

  std::size_t count() const { return kind.size(); }
  void add(ParticleKind k, std::vector<double> x, std::vector<double> v, double p) {
    position.insert(position.end(), x.begin(), x.end());
    velocity.insert(velocity.end(), v.begin(), v.end());
    pressure.push_back(p);
    kind.push_back(static_cast<std::uint8_t>(k));
    body.push_back(k == ParticleKind::RigidBody ? 0 : -1);
  }
  ParticleView view() const {  // a plain view with the HDF5 layout (stride dim)
    ParticleView v;
    v.dim = dim;
    v.count = count();
    v.time = time;
    v.d0 = d0;
    for (int a = 0; a < dim; ++a) {
      v.position.component[a] = position.data() + a;
      v.velocity.component[a] = velocity.data() + a;
    }
    v.position.stride = v.velocity.stride = static_cast<std::size_t>(dim);
    v.pressure = pressure.data();
    v.kind = kind.data();
    v.body = body.data();
    return v;
  }
};

// A 2D water column (12 x 8) on a floor, with a small rigid block; water speeds up with time.
StoredFrame column_2d(double time) {
  StoredFrame f;
  f.time = time;
  const double d = f.d0;
  for (int i = 0; i < 12; ++i) {
    for (int j = 0; j < 8; ++j) {
      f.add(ParticleKind::Fluid, {(i + 0.5) * d + time * 0.1, (j + 0.5) * d},
            {time * (1.0 + i), -time}, 9810.0 * (8 - j) * d);
    }
  }
  for (int i = -3; i < 25; ++i)
    f.add(ParticleKind::FixedWall, {(i + 0.5) * d, -0.5 * d}, {0, 0}, 0);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      f.add(ParticleKind::RigidBody, {0.18 + i * d, 0.02 + j * d}, {0, 0}, 0);
  }
  return f;
}

// A 3D block of water (6 x 4 x 5) on a floor, gravity along -z.
StoredFrame block_3d(double time) {
  StoredFrame f;
  f.dim = 3;
  f.d0 = 0.02;
  f.time = time;
  const double d = f.d0;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 4; ++j) {
      for (int k = 0; k < 5; ++k) {
        f.add(ParticleKind::Fluid, {(i + 0.5) * d, (j + 0.5) * d, (k + 0.5) * d},
              {0.1 * i, 0.0, -0.05 * k}, 9810.0 * (5 - k) * d);
      }
    }
  }
  for (int i = -1; i < 10; ++i) {
    for (int j = -1; j < 5; ++j) {
      f.add(ParticleKind::FixedWall, {(i + 0.5) * d, (j + 0.5) * d, -0.5 * d}, {0, 0, 0}, 0);
    }
  }
  return f;
}

void write_attribute(hid_t object, const char* name, hid_t type, const void* value) {
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attribute, type, value);
  H5Aclose(attribute);
  H5Sclose(space);
}

void write_dataset(hid_t group, const char* name, hid_t type, std::vector<hsize_t> dims,
                   const void* data) {
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t set = H5Dcreate2(group, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  H5Dclose(set);
  H5Sclose(space);
}

// Writes the run-file schema of INTERFACE.md (the parts the renderer reads).
void write_run_file(const fs::path& path, const std::vector<StoredFrame>& frames) {
  fs::create_directories(path.parent_path());
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(file, 0) << path;
  const int dim = frames.front().dim;
  const double d0 = frames.front().d0;
  write_attribute(file, "dim", H5T_NATIVE_INT, &dim);
  write_attribute(file, "d0", H5T_NATIVE_DOUBLE, &d0);
  const hid_t group = H5Gcreate2(file, "/frames", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  for (std::size_t index = 0; index < frames.size(); ++index) {
    const StoredFrame& f = frames[index];
    char name[32];
    std::snprintf(name, sizeof(name), "%06zu", index);
    const hid_t g = H5Gcreate2(group, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const std::int64_t step = static_cast<std::int64_t>(index) * 10;
    write_attribute(g, "time", H5T_NATIVE_DOUBLE, &f.time);
    write_attribute(g, "step", H5T_NATIVE_INT64, &step);
    const hsize_t n = f.count(), d = static_cast<hsize_t>(f.dim);
    std::vector<std::uint64_t> ids(n);
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
    write_dataset(g, "position", H5T_NATIVE_DOUBLE, {n, d}, f.position.data());
    write_dataset(g, "velocity", H5T_NATIVE_DOUBLE, {n, d}, f.velocity.data());
    write_dataset(g, "pressure", H5T_NATIVE_DOUBLE, {n}, f.pressure.data());
    write_dataset(g, "kind", H5T_NATIVE_UINT8, {n}, f.kind.data());
    write_dataset(g, "id", H5T_NATIVE_UINT64, {n}, ids.data());
    write_dataset(g, "body", H5T_NATIVE_INT32, {n}, f.body.data());
    H5Gclose(g);
  }
  H5Gclose(group);
  H5Fclose(file);
}

fs::path test_dir(const std::string& name) {
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "render_command" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A 2D run of `frames` output frames at 0.1 s intervals, in its own folder.
fs::path make_run_2d(const std::string& name, int frames) {
  std::vector<StoredFrame> data;
  for (int i = 0; i < frames; ++i) data.push_back(column_2d(0.1 * i));
  const fs::path path = test_dir(name) / "run.h5";
  write_run_file(path, data);
  return path;
}

int run(std::vector<std::string> args) {
  args.insert(args.begin(), "render");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  return cli::run_render_command(static_cast<int>(args.size()), argv.data());
}

struct PngInfo {
  bool ok = false;
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

PngInfo read_png(const fs::path& path) {
  PngInfo info;
  png_image image;
  std::memset(&image, 0, sizeof(image));
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return info;
  image.format = PNG_FORMAT_RGB;
  info.rgb.resize(PNG_IMAGE_SIZE(image));
  info.ok = png_image_finish_read(&image, nullptr, info.rgb.data(), 0, nullptr) != 0;
  info.width = static_cast<int>(image.width);
  info.height = static_cast<int>(image.height);
  return info;
}

std::vector<std::string> png_names(const fs::path& dir) {
  std::vector<std::string> names;
  if (!fs::exists(dir)) return names;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".png") names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += n + " ";
  return s;
}

TEST(RenderCommand, WritesEveryFrameNumberedByIndex) {
  const fs::path run_file = make_run_2d("all", 3);
  const fs::path out = run_file.parent_path() / "images";
  const int status =
      run({run_file.string(), "--out", out.string(), "--width", "320", "--height", "180"});
  const auto names = png_names(out);
  std::printf("exit %d, wrote: %s\n", status, joined(names).c_str());
  EXPECT_EQ(status, 0);
  EXPECT_EQ(names,
            (std::vector<std::string>{"frame_000000.png", "frame_000001.png", "frame_000002.png"}));
  const PngInfo png = read_png(out / "frame_000002.png");
  std::printf("frame_000002.png: %dx%d, readable %d\n", png.width, png.height, png.ok);
  EXPECT_TRUE(png.ok);
  EXPECT_EQ(png.width, 320);
  EXPECT_EQ(png.height, 180);
}

TEST(RenderCommand, EveryFrameAndDefaultFolder) {
  const fs::path run_file = make_run_2d("every", 5);
  EXPECT_EQ(run({run_file.string(), "--every", "2", "--width", "200", "--height", "120"}), 0);
  const fs::path default_out = run_file.parent_path() / "frames";
  const auto every = png_names(default_out);
  std::printf("--every 2 wrote into %s: %s\n", default_out.c_str(), joined(every).c_str());
  EXPECT_EQ(every,
            (std::vector<std::string>{"frame_000000.png", "frame_000002.png", "frame_000004.png"}));
  const fs::path single = run_file.parent_path() / "single";
  EXPECT_EQ(run({run_file.string(), "--frame", "3", "--out", single.string(), "--width", "200",
                 "--height", "120"}),
            0);
  const auto one = png_names(single);
  std::printf("--frame 3 wrote: %s\n", joined(one).c_str());
  EXPECT_EQ(one, std::vector<std::string>{"frame_000003.png"});
}

TEST(RenderCommand, StridedRunFileViewDrawsTheSameImageAsMemory) {
  const StoredFrame frame = block_3d(0.5);
  const fs::path run_file = test_dir("same3d") / "block.h5";
  write_run_file(run_file, {frame});
  const fs::path out = run_file.parent_path() / "frames";
  ASSERT_EQ(run({run_file.string(), "--frame", "0", "--camera", "side", "--color", "pressure",
                 "--width", "320", "--height", "180"}),
            0);
  const PngInfo from_file = read_png(out / "frame_000000.png");
  render::RenderOptions options;
  options.width = 320;
  options.height = 180;
  options.camera.preset = "side";
  options.color_field = "pressure";
  render::FrameRenderer renderer(options);
  const render::Image direct = renderer.render(frame.view());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < direct.bytes().size() && i < from_file.rgb.size(); ++i) {
    differing += direct.bytes()[i] != from_file.rgb[i];
  }
  std::printf("3D side view through the command vs in memory: %zu of %zu bytes differ\n", differing,
              direct.bytes().size());
  ASSERT_TRUE(from_file.ok);
  EXPECT_EQ(from_file.rgb.size(), direct.bytes().size());
  EXPECT_EQ(differing, 0u);
}

TEST(RenderCommand, BadInputExitsWithOne) {
  const fs::path run_file = make_run_2d("bad", 2);
  const std::string out = (run_file.parent_path() / "frames").string();
  struct Case {
    const char* what;
    std::vector<std::string> args;
  };
  const std::vector<Case> cases = {
      {"missing run file", {"/nonexistent/run.h5"}},
      {"frame out of range", {run_file.string(), "--frame", "7"}},
      {"unknown colour field", {run_file.string(), "--color", "vorticity"}},
      {"unknown camera preset", {run_file.string(), "--camera", "fisheye"}},
      {"unknown option", {run_file.string(), "--colour-map", "jet"}},
      {"bad range", {run_file.string(), "--range", "5,1"}},
      {"range without comma", {run_file.string(), "--range", "5"}},
      {"empty region", {run_file.string(), "--region", "0.5,0,0.2,0.6"}},
      {"region of three numbers", {run_file.string(), "--region", "0,0,1"}},
      {"3D region for a 2D run", {run_file.string(), "--region", "0,0,0,1,1,1"}},
      {"bad width", {run_file.string(), "--width", "wide"}},
      {"no run file", {"--every", "2"}},
      {"frame and every", {run_file.string(), "--frame", "0", "--every", "2"}},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = c.args;
    args.insert(args.end(), {"--out", out});
    const int status = run(args);
    std::printf("%s: exit %d\n", c.what, status);
    EXPECT_EQ(status, 1) << c.what;
  }
  EXPECT_TRUE(png_names(out).empty()) << "nothing is drawn for bad input";
  EXPECT_EQ(run({"--help"}), 0);
}

TEST(RenderCommand, UnwritableOutputExitsWithThree) {
  const fs::path run_file = make_run_2d("unwritable", 1);
  const fs::path blocker = run_file.parent_path() / "a_file";
  std::ofstream(blocker) << "not a folder";
  const int status = run({run_file.string(), "--out", (blocker / "frames").string()});
  std::printf("output folder below a regular file: exit %d\n", status);
  EXPECT_EQ(status, 3);
  // The image's own path is taken by a folder: the PNG itself cannot be written.
  const fs::path taken = run_file.parent_path() / "taken";
  fs::create_directories(taken / "frame_000000.png");
  const int png_status =
      run({run_file.string(), "--out", taken.string(), "--width", "200", "--height", "120"});
  std::printf("image path taken by a folder: exit %d\n", png_status);
  EXPECT_EQ(png_status, 3);
  // A folder that exists but refuses new files (skipped as root, who may write anywhere).
  const fs::path locked = run_file.parent_path() / "locked";
  fs::create_directories(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  const bool can_write = std::ofstream(locked / "probe").good();
  if (!can_write) {
    const int locked_status =
        run({run_file.string(), "--out", locked.string(), "--width", "200", "--height", "120"});
    std::printf("read-only output folder: exit %d\n", locked_status);
    EXPECT_EQ(locked_status, 3);
  } else {
    std::printf("read-only folder case skipped: this user can write anywhere\n");
  }
  fs::permissions(locked, fs::perms::owner_all);
}

// Runs the command with PATH set to one folder, so the presence of ffmpeg is controlled.
int run_with_path(const fs::path& path_dir, std::vector<std::string> args) {
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  setenv("PATH", path_dir.c_str(), 1);
  const int status = run(std::move(args));
  setenv("PATH", saved.c_str(), 1);
  return status;
}

TEST(RenderCommand, VideoIsOptional) {
  const fs::path run_file = make_run_2d("video", 5);
  const fs::path dir = run_file.parent_path();
  const fs::path empty_bin = dir / "empty_bin";
  fs::create_directories(empty_bin);
  const int without =
      run_with_path(empty_bin, {run_file.string(), "--video", "--width", "200", "--height", "120"});
  std::printf("--video without ffmpeg: exit %d, %zu frames\n", without,
              png_names(dir / "frames").size());
  EXPECT_EQ(without, 0);
  EXPECT_EQ(png_names(dir / "frames").size(), 5u);

  // A stand-in ffmpeg that records its arguments and the frame list, and makes the video file.
  const fs::path fake_bin = dir / "fake_bin";
  fs::create_directories(fake_bin);
  const fs::path record = dir / "ffmpeg_args.txt", list_copy = dir / "ffmpeg_list.txt";
  {
    std::ofstream script(fake_bin / "ffmpeg");
    script << "#!/bin/sh\nPATH=/usr/bin:/bin\nprintf '%s\\n' \"$@\" > '" << record.string() << "'\n"
           << "cp \"$9\" '" << list_copy.string() << "'\n"
           << "for last; do :; done\ntouch \"$last\"\n";
  }
  fs::permissions(fake_bin / "ffmpeg", fs::perms::owner_all);
  const fs::path out = dir / "every2";
  const int with = run_with_path(fake_bin, {run_file.string(), "--video", "--every", "2", "--out",
                                            out.string(), "--width", "200", "--height", "120"});
  std::ifstream list_in(list_copy);
  std::stringstream list;
  list << list_in.rdbuf();
  std::printf("--video with a stand-in ffmpeg: exit %d, list:\n%s", with, list.str().c_str());
  EXPECT_EQ(with, 0);
  EXPECT_TRUE(fs::exists(out / "run.mp4"));
  EXPECT_NE(list.str().find("file 'frame_000000.png'\nduration 0.04\nfile 'frame_000002.png'"),
            std::string::npos);
  EXPECT_EQ(list.str().find("frame_000001.png"), std::string::npos) << "only frames drawn now";
  EXPECT_FALSE(fs::exists(out / "frames.ffconcat")) << "the list is removed afterwards";
}

// Every `washout render ...` line in docs/render.md's ```sh blocks must work. The run file of
// the example is replaced by a small 2D run, --out folders by test folders, and the size made
// small so that the test stays fast.
TEST(RenderCommand, DocumentedExamplesRun) {
  std::ifstream doc(std::string(WASHOUT_SOURCE_DIR) + "/docs/render.md");
  ASSERT_TRUE(doc.good()) << "docs/render.md is missing";
  const fs::path run_file = make_run_2d("docs", 3);
  const fs::path empty_bin = run_file.parent_path() / "empty_bin";
  fs::create_directories(empty_bin);
  std::string line;
  bool in_code = false;
  int examples = 0;
  while (std::getline(doc, line)) {
    if (line.rfind("```", 0) == 0) {
      in_code = line == "```sh";  // the runnable examples; the synopsis is a ```text block
      continue;
    }
    if (!in_code || line.rfind("washout render", 0) != 0) continue;
    std::istringstream words(line);
    std::vector<std::string> args;
    std::string word;
    words >> word >> word;  // "washout render"
    while (words >> word) {
      if (word == "#") break;  // a trailing comment
      if (word.size() > 3 && word.substr(word.size() - 3) == ".h5") word = run_file.string();
      if (!args.empty() && args.back() == "--out") word = (run_file.parent_path() / word).string();
      args.push_back(word);
    }
    args.insert(args.end(), {"--width", "200", "--height", "120"});  // later options win
    const int status = run_with_path(empty_bin, args);
    std::printf("doc example: %s -> exit %d\n", line.c_str(), status);
    EXPECT_EQ(status, 0) << line;
    ++examples;
  }
  EXPECT_GE(examples, 4);
}

}  // namespace
}  // namespace washout

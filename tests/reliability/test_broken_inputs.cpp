// The broken-input corpus (tests/data/broken/manifest.txt): every scene, argument list and run
// file in it must be refused with its documented exit status and a message naming the problem;
// never an abort, a signal or a hang. One table, one test.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>

#include "reliability/run_washout.hpp"

namespace washout {
namespace {

namespace fs = std::filesystem;
const fs::path kCorpus = fs::path(WASHOUT_SOURCE_DIR) / "tests/data/broken";

// A minimal run file in the layout of docs/output.md, spoilt by the caller's edits.
struct RunFileSpec {
  bool dim_as_text = false;
  double dim = 2, d0 = 0.01;
  bool write_d0 = true, frames_group = true, frame_is_dataset = false, write_time = true;
  bool write_kind = true;
  std::size_t n = 4, position_columns = 2, kind_rows = 4, velocity_rows = 4;
  std::uint8_t kind_value = 0;
  double position_value = 0.5;
};

void attribute(hid_t object, const char* name, double value) {
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(object, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_DOUBLE, &value);
  H5Aclose(a);
  H5Sclose(space);
}

template <class T>
void dataset(hid_t group, const char* name, hid_t type, std::size_t rows, std::size_t columns,
             T value) {
  hsize_t dims[2] = {rows, columns};
  hid_t space = H5Screate_simple(columns > 0 ? 2 : 1, dims, nullptr);
  hid_t d = H5Dcreate2(group, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<T> data(rows * std::max<std::size_t>(columns, 1), value);
  H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  H5Dclose(d);
  H5Sclose(space);
}

void write_run_file(const fs::path& path, const RunFileSpec& s) {
  hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (s.dim_as_text) {
    hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, 3);
    hid_t space = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(f, "dim", type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, type, "two");
    H5Aclose(a);
    H5Sclose(space);
    H5Tclose(type);
  } else {
    attribute(f, "dim", s.dim);
  }
  if (s.write_d0) attribute(f, "d0", s.d0);
  if (s.frames_group) {
    hid_t frames = H5Gcreate2(f, "frames", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (s.frame_is_dataset) {
      dataset<double>(frames, "000000", H5T_NATIVE_DOUBLE, 3, 0, 1.0);
    } else {
      hid_t g = H5Gcreate2(frames, "000000", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      if (s.write_time) attribute(g, "time", 0.0);
      attribute(g, "step", 0.0);
      dataset<double>(g, "position", H5T_NATIVE_DOUBLE, s.n, s.position_columns, s.position_value);
      dataset<double>(g, "velocity", H5T_NATIVE_DOUBLE, s.velocity_rows, 2, 0.0);
      if (s.write_kind)
        dataset<std::uint8_t>(g, "kind", H5T_NATIVE_UINT8, s.kind_rows, 0, s.kind_value);
      H5Gclose(g);
    }
    H5Gclose(frames);
  }
  H5Fclose(f);
}

void generate_run_files(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream(dir / "not_hdf5.h5") << "this is not an HDF5 file\n";
  std::ofstream(dir / "empty.h5");
  const std::map<std::string, RunFileSpec> files = {
      {"valid.h5", {}},
      {"dim_zero.h5", {.dim = 0}},
      {"dim_seven.h5", {.dim = 7}},
      {"dim_text.h5", {.dim_as_text = true}},
      {"no_d0.h5", {.write_d0 = false}},
      {"d0_negative.h5", {.d0 = -1}},
      {"no_frames.h5", {.frames_group = false}},
      {"position_columns.h5", {.position_columns = 3}},
      {"kind_short.h5", {.kind_rows = 3}},
      {"velocity_long.h5", {.velocity_rows = 5}},
      {"kind_nine.h5", {.kind_value = 9}},
      {"position_nan.h5", {.position_value = NAN}},
      {"frame_dataset.h5", {.frame_is_dataset = true}},
      {"no_time.h5", {.write_time = false}},
      {"no_kind.h5", {.write_kind = false}},
  };
  for (const auto& [name, spec] : files) write_run_file(dir / name, spec);
}

// A real run of base.lua for the --restart cases ($G/restart_source.h5), and copies of it
// spoilt by hand: no checkpoint, no complete one, another format, another particle layout, a
// series shorter than the checkpoint's steps.
void for_each_slot(hid_t f, const std::function<void(hid_t)>& edit) {
  for (const char* slot : {"/checkpoint/a", "/checkpoint/b"})
    if (H5Lexists(f, "/checkpoint", H5P_DEFAULT) > 0 && H5Lexists(f, slot, H5P_DEFAULT) > 0) {
      hid_t g = H5Gopen2(f, slot, H5P_DEFAULT);
      edit(g);
      H5Gclose(g);
    }
}

void set_integer(hid_t object, const char* name, std::int64_t value) {
  if (H5Aexists(object, name) > 0) H5Adelete(object, name);
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(object, name, H5T_NATIVE_INT64, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_INT64, &value);
  H5Aclose(a);
  H5Sclose(space);
}

void generate_restart_files(const fs::path& dir) {
  const fs::path run = dir / "restart_run";
  const auto r = test::run_washout(
      {"run", (kCorpus / "base.lua").string(), "--out", run.string(), "--quiet", "--threads", "1"},
      (dir / "restart_run.log").string(), 60);
  ASSERT_EQ(r.status, 0) << r.output;
  fs::copy_file(run / "base.h5", dir / "restart_source.h5", fs::copy_options::overwrite_existing);
  const std::map<std::string, std::function<void(hid_t)>> edits = {
      {"no_checkpoint.h5", [](hid_t f) { H5Ldelete(f, "/checkpoint", H5P_DEFAULT); }},
      {"checkpoint_incomplete.h5",
       [](hid_t f) {
         for_each_slot(f, [](hid_t g) {
           H5Adelete(g, "complete");
           set_integer(g, "complete", 0);
         });
       }},
      {"checkpoint_format.h5",
       [](hid_t f) { for_each_slot(f, [](hid_t g) { set_integer(g, "format", 99); }); }},
      {"layout_changed.h5",
       [](hid_t f) { for_each_slot(f, [](hid_t g) { set_integer(g, "layout", 12345); }); }},
      {"series_short.h5",
       [](hid_t f) {
         hid_t d = H5Dopen2(f, "/stats/time", H5P_DEFAULT);
         hsize_t rows[1] = {1};
         H5Dset_extent(d, rows);
         H5Dclose(d);
       }},
  };
  for (const auto& [name, edit] : edits) {
    fs::copy_file(run / "base.h5", dir / name, fs::copy_options::overwrite_existing);
    hid_t f = H5Fopen((dir / name).c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0) << name;
    edit(f);
    H5Fclose(f);
  }
}

std::string substitute(std::string text, const std::string& key, const std::string& value) {
  for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
    text.replace(at, key.size(), value);
  return text;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

TEST(BrokenInputs, EveryCaseRefusedWithItsStatusAndMessage) {
  const fs::path work = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "broken_inputs";
  fs::remove_all(work);
  generate_run_files(work / "generated");
  generate_restart_files(work / "generated");
  std::ifstream manifest(kCorpus / "manifest.txt");
  ASSERT_TRUE(manifest) << "no manifest in " << kCorpus;
  int cases = 0, line_number = 0;
  std::map<int, int> by_status;
  for (std::string line; std::getline(manifest, line);) {
    ++line_number;
    if (line.empty() || line[0] == '#') continue;
    const auto bar1 = line.find('|'), bar2 = line.find('|', bar1 + 1);
    ASSERT_NE(bar2, std::string::npos) << "manifest line " << line_number << ": " << line;
    const int expected = std::stoi(line.substr(0, bar1));
    const std::string fragment = trim(line.substr(bar1 + 1, bar2 - bar1 - 1));
    const fs::path out = work / ("case_" + std::to_string(line_number));
    std::string args = line.substr(bar2 + 1);
    args = substitute(args, "$D", kCorpus.string());
    args = substitute(args, "$G", (work / "generated").string());
    args = substitute(args, "$O", out.string());
    fs::create_directories(work / "logs");
    const auto log = work / "logs" / ("case_" + std::to_string(line_number) + ".log");
    const auto r = test::run_washout(test::split_words(args), log.string(), 60);
    ++cases;
    ++by_status[r.status];
    EXPECT_FALSE(r.timed_out) << "line " << line_number << " hung: " << args;
    EXPECT_EQ(r.signal, 0) << "line " << line_number << " died by signal " << r.signal << ": "
                           << args << "\n"
                           << r.output;
    EXPECT_EQ(r.status, expected) << "line " << line_number << ": " << args << "\n" << r.output;
    EXPECT_NE(r.output.find(fragment), std::string::npos)
        << "line " << line_number << ": expected '" << fragment << "' in:\n"
        << r.output;
  }
  EXPECT_GE(cases, 60);
  std::printf("broken-input corpus: %d cases;", cases);
  for (const auto& [status, count] : by_status) std::printf(" exit %d: %d", status, count);
  std::printf("\n");
}

}  // namespace
}  // namespace washout

#include "engine/io/run_file_reader.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace washout::io {
namespace {

herr_t collect_name(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->push_back(name);
  return 0;
}

bool exists(hid_t file, const std::string& path) {
  // H5Lexists needs every intermediate link to exist: check each prefix.
  std::size_t pos = 0;
  while ((pos = path.find('/', pos + 1)) != std::string::npos)
    if (H5Lexists(file, path.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
  return H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0;
}

template <class T>
std::vector<T> read_all(hid_t file, const std::string& path, hid_t type, const std::string& fname) {
  hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) throw RunFileError(fname + ": no dataset " + path);
  hid_t space = H5Dget_space(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<T> data(static_cast<std::size_t>(std::max<hssize_t>(n, 0)));
  herr_t status = n > 0 ? H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) : 0;
  H5Sclose(space);
  H5Dclose(set);
  if (status < 0) throw RunFileError(fname + ": cannot read " + path);
  return data;
}

double read_double_attribute(hid_t object, const char* name, const std::string& where) {
  if (H5Aexists(object, name) <= 0) throw RunFileError(where + ": missing attribute " + name);
  hid_t attr = H5Aopen(object, name, H5P_DEFAULT);
  hid_t space = H5Aget_space(attr);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  H5Sclose(space);
  hid_t type = H5Aget_type(attr);
  const bool numeric = H5Tget_class(type) == H5T_INTEGER || H5Tget_class(type) == H5T_FLOAT;
  H5Tclose(type);
  double v = 0;
  const herr_t status = numeric && n == 1 ? H5Aread(attr, H5T_NATIVE_DOUBLE, &v) : -1;
  H5Aclose(attr);
  if (status < 0) throw RunFileError(where + ": attribute " + name + " is not a number");
  return v;
}

// The extent of a dataset, or a RunFileError if it is not a dataset.
std::vector<hsize_t> dataset_dims(hid_t file, const std::string& path, const std::string& fname) {
  hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) throw RunFileError(fname + ": " + path + " is not a dataset");
  hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  H5Dclose(set);
  return dims;
}

std::string dims_text(const std::vector<hsize_t>& dims) {
  std::string t = "[";
  for (std::size_t k = 0; k < dims.size(); ++k) t += (k ? ", " : "") + std::to_string(dims[k]);
  return t + "]";
}

}  // namespace

ParticleView FrameData::view() const {
  ParticleView v;
  v.dim = dim;
  v.count = count;
  v.time = time;
  v.d0 = d0;
  for (int a = 0; a < dim; ++a) {
    v.position.component[a] = position.data() + a;
    if (!velocity.empty()) v.velocity.component[a] = velocity.data() + a;
  }
  v.position.stride = v.velocity.stride = static_cast<std::size_t>(dim);
  v.pressure = pressure.empty() ? nullptr : pressure.data();
  v.kind = kind.empty() ? nullptr : kind.data();
  v.body = body.empty() ? nullptr : body.data();
  return v;
}

RunFileReader::RunFileReader(const std::string& path) : path_(path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (!std::filesystem::exists(path) || H5Fis_hdf5(path.c_str()) <= 0)
    throw RunFileError("cannot open run file '" + path + "' (missing or not HDF5)");
  // Without HDF5's file lock: a run holds its file locked while it writes, and a reader that asks
  // for the lock (HDF5's default) could not open the file of a run still going, which
  // `washout render` and the study's readers are meant to do. The writer flushes after every
  // frame (run_file_writer.cpp), so the frames read are whole; a frame being written when the
  // file is opened is not listed yet or fails to read, and the reader says so.
  const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_file_locking(access, false, true);
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, access);
  H5Pclose(access);
  if (file_ < 0) throw RunFileError("cannot open run file '" + path + "'");
  const double dim = read_double_attribute(file_, "dim", path);
  d0_ = read_double_attribute(file_, "d0", path);
  // Everything downstream divides by dim and scales by d0: refuse a file that lies about them.
  if (dim != 2 && dim != 3) {
    H5Fclose(file_);
    throw RunFileError(path + ": attribute dim must be 2 or 3, got " + std::to_string(dim));
  }
  if (!(d0_ > 0) || !std::isfinite(d0_)) {
    H5Fclose(file_);
    throw RunFileError(path + ": attribute d0 must be a positive length");
  }
  dim_ = static_cast<int>(dim);
  if (exists(file_, "/frames")) {
    hid_t frames = H5Gopen2(file_, "/frames", H5P_DEFAULT);
    H5Literate(frames, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_name, &frame_names_);
    H5Gclose(frames);
    std::sort(frame_names_.begin(), frame_names_.end());
  }
}

RunFileReader::~RunFileReader() {
  if (file_ >= 0) H5Fclose(file_);
}

std::vector<double> RunFileReader::frame_times() const {
  std::vector<double> t;
  for (const auto& name : frame_names_) {
    hid_t g = H5Gopen2(file_, ("/frames/" + name).c_str(), H5P_DEFAULT);
    t.push_back(read_double_attribute(g, "time", path_ + ":/frames/" + name));
    H5Gclose(g);
  }
  return t;
}

FrameData RunFileReader::read_frame(std::size_t index) const {
  if (index >= frame_names_.size())
    throw RunFileError(path_ + ": frame " + std::to_string(index) + " out of range (the file has " +
                       std::to_string(frame_names_.size()) + " frames)");
  const std::string base = "/frames/" + frame_names_[index];
  FrameData f;
  f.dim = dim_;
  f.d0 = d0_;
  hid_t g = H5Gopen2(file_, base.c_str(), H5P_DEFAULT);
  if (g < 0) throw RunFileError(path_ + ": " + base + " is not a group");
  try {
    f.time = read_double_attribute(g, "time", path_ + ":" + base);
    f.step = static_cast<std::int64_t>(read_double_attribute(g, "step", path_ + ":" + base));
  } catch (...) {
    H5Gclose(g);
    throw;
  }
  H5Gclose(g);
  if (!std::isfinite(f.time)) throw RunFileError(path_ + ": " + base + " time is not finite");
  // Shapes first, before any read: every field holds one row per particle.
  const std::string where = path_ + ":" + base;
  if (!exists(file_, base + "/position")) throw RunFileError(where + ": no position dataset");
  if (!exists(file_, base + "/kind")) throw RunFileError(where + ": no kind dataset");
  const auto pdims = dataset_dims(file_, base + "/position", where);
  if (pdims.size() != 2 || pdims[1] != static_cast<hsize_t>(dim_))
    throw RunFileError(where + "/position has shape " + dims_text(pdims) + ", expected [N, " +
                       std::to_string(dim_) + "]");
  const hsize_t n = pdims[0];
  auto expect = [&](const char* field, std::size_t rank) {
    const std::string p = base + "/" + field;
    if (!exists(file_, p)) return;
    const auto d = dataset_dims(file_, p, where);
    const bool ok = d.size() == rank && d[0] == n && (rank == 1 || d[1] == hsize_t(dim_));
    if (!ok)
      throw RunFileError(where + "/" + field + " has shape " + dims_text(d) + ", expected [" +
                         std::to_string(n) + (rank == 2 ? ", " + std::to_string(dim_) : "") +
                         "] like position");
  };
  expect("velocity", 2);
  expect("pressure", 1);
  expect("kind", 1);
  expect("id", 1);
  expect("body", 1);
  f.position = read_all<double>(file_, base + "/position", H5T_NATIVE_DOUBLE, path_);
  f.count = static_cast<std::size_t>(n);
  for (double x : f.position)
    if (!std::isfinite(x)) throw RunFileError(where + "/position holds a non-finite value");
  if (exists(file_, base + "/velocity"))
    f.velocity = read_all<double>(file_, base + "/velocity", H5T_NATIVE_DOUBLE, path_);
  if (exists(file_, base + "/pressure"))
    f.pressure = read_all<double>(file_, base + "/pressure", H5T_NATIVE_DOUBLE, path_);
  f.kind = read_all<std::uint8_t>(file_, base + "/kind", H5T_NATIVE_UINT8, path_);
  for (std::uint8_t k : f.kind)
    if (k > 4)
      throw RunFileError(where + "/kind holds " + std::to_string(k) +
                         " (kinds: 0 fluid, 1 fixed wall, 2 moving wall, 3 rigid body, "
                         "4 retired fluid)");
  if (exists(file_, base + "/id"))
    f.id = read_all<std::uint64_t>(file_, base + "/id", H5T_NATIVE_UINT64, path_);
  if (exists(file_, base + "/body"))
    f.body = read_all<std::int32_t>(file_, base + "/body", H5T_NATIVE_INT32, path_);
  return f;
}

bool RunFileReader::has(const std::string& object_path) const { return exists(file_, object_path); }

bool RunFileReader::has_attribute(const std::string& object, const std::string& name) const {
  return exists(file_, object) &&
         H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

std::vector<std::string> RunFileReader::children(const std::string& group) const {
  std::vector<std::string> names;
  if (!exists(file_, group)) return names;
  hid_t g = H5Gopen2(file_, group.c_str(), H5P_DEFAULT);
  if (g < 0) return names;
  H5Literate(g, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_name, &names);
  H5Gclose(g);
  std::sort(names.begin(), names.end());
  return names;
}

std::string RunFileReader::string_attribute(const std::string& name,
                                            const std::string& object) const {
  if (!has_attribute(object, name))
    throw RunFileError(path_ + ": missing attribute " + object + " " + name);
  hid_t attr = H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  hid_t type = H5Aget_type(attr);
  const std::size_t size = H5Tget_size(type);
  std::string value(size, '\0');
  hid_t memory_type = H5Tcopy(H5T_C_S1);
  H5Tset_size(memory_type, size);
  H5Tset_strpad(memory_type, H5T_STR_NULLPAD);
  H5Tset_cset(memory_type, H5Tget_cset(type));  // as stored (the writer uses UTF-8): no conversion
  H5Aread(attr, memory_type, value.data());
  H5Tclose(memory_type);
  H5Tclose(type);
  H5Aclose(attr);
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

std::string RunFileReader::scene_source() const {
  if (!exists(file_, "/scene_source")) return string_attribute("scene_source");
  hid_t set = H5Dopen2(file_, "/scene_source", H5P_DEFAULT);
  if (set < 0) throw RunFileError(path_ + ": cannot open /scene_source");
  hid_t type = H5Dget_type(set);
  const std::size_t size = H5Tget_class(type) == H5T_STRING ? H5Tget_size(type) : 0;
  hid_t space = H5Dget_space(set);
  const bool scalar = H5Sget_simple_extent_type(space) == H5S_SCALAR;
  H5Sclose(space);
  if (size == 0 || !scalar || H5Tis_variable_str(type) > 0) {
    H5Tclose(type);
    H5Dclose(set);
    throw RunFileError(path_ + ": /scene_source is not a text");
  }
  std::string value(size, '\0');
  hid_t memory_type = H5Tcopy(H5T_C_S1);
  H5Tset_size(memory_type, size);
  H5Tset_strpad(memory_type, H5T_STR_NULLPAD);
  H5Tset_cset(memory_type, H5Tget_cset(type));
  const herr_t status = H5Dread(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.data());
  H5Tclose(memory_type);
  H5Tclose(type);
  H5Dclose(set);
  if (status < 0) throw RunFileError(path_ + ": cannot read /scene_source");
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

double RunFileReader::double_attribute(const std::string& name) const {
  return read_double_attribute(file_, name.c_str(), path_);
}

std::vector<double> RunFileReader::read_doubles(const std::string& dataset_path) const {
  if (!exists(file_, dataset_path)) throw RunFileError(path_ + ": no dataset " + dataset_path);
  return read_all<double>(file_, dataset_path, H5T_NATIVE_DOUBLE, path_);
}

std::vector<std::size_t> RunFileReader::shape(const std::string& dataset_path) const {
  if (!exists(file_, dataset_path)) throw RunFileError(path_ + ": no dataset " + dataset_path);
  hid_t set = H5Dopen2(file_, dataset_path.c_str(), H5P_DEFAULT);
  hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  H5Dclose(set);
  return {dims.begin(), dims.end()};
}

namespace {

herr_t collect_attribute_name(hid_t, const char* name, const H5A_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->push_back(name);
  return 0;
}

// A checkpoint slot's frame, or -1 unless it is marked complete.
std::int64_t complete_frame(hid_t file, const std::string& slot) {
  if (!exists(file, slot)) return -1;
  hid_t g = H5Gopen2(file, slot.c_str(), H5P_DEFAULT);
  if (g < 0) return -1;
  std::int64_t frame = -1;
  std::int32_t complete = 0;
  if (H5Aexists(g, "complete") > 0 && H5Aexists(g, "frame") > 0) {
    hid_t a = H5Aopen(g, "complete", H5P_DEFAULT);
    if (H5Aread(a, H5T_NATIVE_INT32, &complete) < 0) complete = 0;
    H5Aclose(a);
    a = H5Aopen(g, "frame", H5P_DEFAULT);
    if (complete != 1 || H5Aread(a, H5T_NATIVE_INT64, &frame) < 0) frame = -1;
    H5Aclose(a);
  }
  H5Gclose(g);
  return frame;
}

}  // namespace

std::optional<Checkpoint> RunFileReader::checkpoint() const {
  std::string best;
  std::int64_t best_frame = -1;
  for (const char* slot : {"/checkpoint/a", "/checkpoint/b"}) {
    const std::int64_t frame = complete_frame(file_, slot);
    // Its frame must be in the file too (a frame is written before its checkpoint).
    char name[32];
    std::snprintf(name, sizeof name, "%06lld", static_cast<long long>(frame));
    const bool present = frame >= 0 && std::binary_search(frame_names_.begin(), frame_names_.end(),
                                                          std::string(name));
    if (present && frame > best_frame) best = slot, best_frame = frame;
  }
  if (best_frame < 0) return std::nullopt;
  Checkpoint c;
  c.frame = best_frame;
  hid_t g = H5Gopen2(file_, best.c_str(), H5P_DEFAULT);
  std::vector<std::string> attributes;
  H5Aiterate2(g, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_attribute_name, &attributes);
  const std::string where = path_ + ":" + best;
  for (const auto& name : attributes) {
    if (name == "complete" || name == "frame") continue;
    hid_t a = H5Aopen(g, name.c_str(), H5P_DEFAULT);
    hid_t type = H5Aget_type(a);
    const H5T_class_t type_class = H5Tget_class(type);
    H5Tclose(type);
    herr_t status = -1;
    if (type_class == H5T_FLOAT) {
      status = H5Aread(a, H5T_NATIVE_DOUBLE, &c.numbers[name]);
    } else if (type_class == H5T_INTEGER) {
      status = H5Aread(a, H5T_NATIVE_INT64, &c.counts[name]);
    }
    H5Aclose(a);
    if (status < 0) {
      H5Gclose(g);
      throw RunFileError(where + ": cannot read attribute " + name);
    }
  }
  const auto format = c.counts.find("format");
  if (format == c.counts.end() || format->second != Checkpoint::kFormat) {
    H5Gclose(g);
    throw RunFileError(
        where + ": a checkpoint of format " +
        (format == c.counts.end() ? std::string("?") : std::to_string(format->second)) +
        "; this washout continues format " + std::to_string(Checkpoint::kFormat));
  }
  c.counts.erase("format");
  std::vector<std::string> datasets;
  H5Literate(g, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_name, &datasets);
  H5Gclose(g);
  for (const auto& name : datasets) {
    const std::string path = best + "/" + name;
    hid_t set = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    if (set < 0) throw RunFileError(where + ": " + name + " is not a dataset");
    hid_t type = H5Dget_type(set);
    const H5T_class_t type_class = H5Tget_class(type);
    const std::size_t size = H5Tget_size(type);
    H5Tclose(type);
    H5Dclose(set);
    if (type_class == H5T_FLOAT)
      c.reals[name] = read_all<double>(file_, path, H5T_NATIVE_DOUBLE, path_);
    else if (type_class == H5T_INTEGER && size == 1)
      c.bytes[name] = read_all<std::uint8_t>(file_, path, H5T_NATIVE_UINT8, path_);
    else if (type_class == H5T_INTEGER)
      c.integers[name] = read_all<std::int64_t>(file_, path, H5T_NATIVE_INT64, path_);
    else
      throw RunFileError(where + ": " + name + " is neither numbers nor integers");
  }
  return c;
}

}  // namespace washout::io

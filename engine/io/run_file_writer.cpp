#include "engine/io/run_file_writer.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>

namespace washout::io {
namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw OutputError("HDF5: could not " + what);
}

void write_attribute(hid_t object, const std::string& name, hid_t type, const void* value) {
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  check(attr, "create attribute " + name);
  check(H5Awrite(attr, type, value), "write attribute " + name);
  H5Aclose(attr);
  H5Sclose(space);
}

void write_string_attribute(hid_t object, const std::string& name, const std::string& value) {
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  H5Tset_cset(type, H5T_CSET_UTF8);
  if (H5Aexists(object, name.c_str()) > 0) H5Adelete(object, name.c_str());
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  check(attr, "create attribute " + name);
  check(H5Awrite(attr, type, value.empty() ? "" : value.data()), "write attribute " + name);
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
}

// A text of any size as a scalar string dataset: attributes stored in the object header are
// limited to 64 KiB, a scene script is not.
void write_string_dataset(hid_t object, const std::string& name, const std::string& value) {
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  H5Tset_cset(type, H5T_CSET_UTF8);
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t set = H5Dcreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  check(set, "create dataset " + name);
  check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.empty() ? "" : value.data()),
        "write dataset " + name);
  H5Dclose(set);
  H5Sclose(space);
  H5Tclose(type);
}

// The largest text kept as an attribute as well, below HDF5's 64 KiB header-message limit.
constexpr std::size_t kMaxTextAttribute = 60000;

template <class T>
void write_dataset(hid_t group, const std::string& name, hid_t type, const std::vector<T>& data,
                   std::size_t rows, std::size_t columns) {
  hsize_t dims[2] = {rows, columns};
  hid_t space = H5Screate_simple(columns > 1 ? 2 : 1, dims, nullptr);
  hid_t set = H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  check(set, "create dataset " + name);
  if (rows > 0)
    check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "write " + name);
  H5Dclose(set);
  H5Sclose(space);
}

// An attribute written anew: deleted first if the object has it already.
void replace_attribute(hid_t object, const std::string& name, hid_t type, const void* value) {
  if (H5Aexists(object, name.c_str()) > 0) H5Adelete(object, name.c_str());
  write_attribute(object, name, type, value);
}

herr_t collect_attribute(hid_t, const char* name, const H5A_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->push_back(name);
  return 0;
}

herr_t collect_link(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->push_back(name);
  return 0;
}

std::vector<std::string> attribute_names(hid_t object) {
  std::vector<std::string> names;
  H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_attribute, &names);
  return names;
}

std::vector<std::string> child_names(hid_t group) {
  std::vector<std::string> names;
  H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_link, &names);
  return names;
}

// The root attributes the writer puts there when it creates a file.
bool is_header_attribute(const std::string& name) {
  for (const char* h :
       {"washout_version", "scene_name", "scene_source", "parameters", "dim", "d0", "h", "dt"})
    if (name == h) return true;
  return false;
}

// Every dataset below `group` (recursively) with more than `rows` rows is cut to `rows`.
void cut_series(hid_t file, const std::string& group, std::size_t rows) {
  hid_t g = H5Gopen2(file, group.c_str(), H5P_DEFAULT);
  if (g < 0) return;
  for (const auto& name : child_names(g)) {
    const std::string path = group + "/" + name;
    H5O_info_t info;
    if (H5Oget_info_by_name(file, path.c_str(), &info, H5P_DEFAULT) < 0) continue;
    if (info.type == H5O_TYPE_GROUP) {
      cut_series(file, path, rows);
    } else if (info.type == H5O_TYPE_DATASET) {
      hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
      hid_t space = H5Dget_space(set);
      hsize_t dims[2] = {0, 0};
      const int rank = H5Sget_simple_extent_ndims(space);
      H5Sget_simple_extent_dims(space, dims, nullptr);
      H5Sclose(space);
      if (rank >= 1 && dims[0] > rows) {
        dims[0] = rows;
        check(H5Dset_extent(set, dims), "cut " + path + " to " + std::to_string(rows) + " rows");
      }
      H5Dclose(set);
    }
  }
  H5Gclose(g);
}

// One array of a checkpoint: written into the dataset of that name if it has the same type and
// size (a checkpoint slot is rewritten in place every other frame), else created anew.
void write_state_array(hid_t group, const std::string& name, hid_t type, const void* data,
                       std::size_t size) {
  if (H5Lexists(group, name.c_str(), H5P_DEFAULT) > 0) {
    hid_t set = H5Dopen2(group, name.c_str(), H5P_DEFAULT);
    hid_t space = H5Dget_space(set);
    hid_t stored = H5Dget_type(set);
    const bool same = H5Sget_simple_extent_npoints(space) == static_cast<hssize_t>(size) &&
                      H5Tequal(stored, type) > 0;
    H5Tclose(stored);
    H5Sclose(space);
    if (same) {
      if (size > 0)
        check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write checkpoint " + name);
      H5Dclose(set);
      return;
    }
    H5Dclose(set);
    check(H5Ldelete(group, name.c_str(), H5P_DEFAULT), "replace checkpoint " + name);
  }
  hsize_t dims[1] = {size};
  hid_t space = H5Screate_simple(1, dims, nullptr);
  hid_t set = H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  check(set, "create checkpoint " + name);
  if (size > 0)
    check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write checkpoint " + name);
  H5Dclose(set);
  H5Sclose(space);
}

}  // namespace

RunFileWriter::RunFileWriter(const std::string& path, const RunHeader& header)
    : path_(path), dim_(header.dim) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // we report errors ourselves
  std::error_code ec;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  // HDF5 locks the file while a run writes it: a second run given the same output is refused.
  if (file_ < 0)
    throw OutputError("cannot create output file '" + path +
                      "' (a folder that is not writable, or another run writing the same file)");
  write_header(header);
  H5Gclose(ensure_group("/frames"));
  flush();
}

void RunFileWriter::write_header(const RunHeader& header) {
  write_string_attribute(file_, "washout_version", WASHOUT_VERSION);
  write_string_attribute(file_, "scene_name", header.scene_name);
  write_string_dataset(file_, "scene_source", header.scene_source);
  if (header.scene_source.size() <= kMaxTextAttribute)  // for readers of older files
    write_string_attribute(file_, "scene_source", header.scene_source);
  write_string_attribute(file_, "parameters", header.parameters_json);
  const std::int32_t dim = header.dim;
  replace_attribute(file_, "dim", H5T_NATIVE_INT32, &dim);
  replace_attribute(file_, "d0", H5T_NATIVE_DOUBLE, &header.d0);
  replace_attribute(file_, "h", H5T_NATIVE_DOUBLE, &header.h);
  replace_attribute(file_, "dt", H5T_NATIVE_DOUBLE, &header.dt);
}

RunFileWriter::RunFileWriter(const std::string& path, const RunHeader& header,
                             const ResumePoint& resume)
    : path_(path), dim_(header.dim) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file_ < 0) throw OutputError("cannot open '" + path + "' to continue it");
  // What a finished run added to the root goes: the continued run writes its own at its end.
  // The scene and its parameters were checked against the checkpoint's run before: only the
  // parameters that may change on a restart (end_time, threads, max_particles) are new.
  for (const auto& name : attribute_names(file_))
    if (!is_header_attribute(name)) H5Adelete(file_, name.c_str());
  write_string_attribute(file_, "washout_version", WASHOUT_VERSION);
  write_string_attribute(file_, "parameters", header.parameters_json);
  // Frames after the resume point: a frame written after the last complete checkpoint.
  hid_t frames = H5Gopen2(file_, "/frames", H5P_DEFAULT);
  if (frames < 0) throw OutputError(path + ": no /frames group to continue");
  for (const auto& name : child_names(frames)) {
    char* end = nullptr;
    const unsigned long index = std::strtoul(name.c_str(), &end, 10);
    if (*end != '\0' || index >= resume.frames) {
      check(H5Ldelete(frames, name.c_str(), H5P_DEFAULT), "delete frame " + name);
      continue;
    }
    hid_t group = H5Gopen2(frames, name.c_str(), H5P_DEFAULT);
    check(group, "open frame " + name);
    FrameRecord record{name, 0.0, 0, H5Lexists(group, "velocity", H5P_DEFAULT) > 0,
                       H5Lexists(group, "pressure", H5P_DEFAULT) > 0};
    hid_t attr = H5Aopen(group, "time", H5P_DEFAULT);
    check(attr, "read the time of frame " + name);
    H5Aread(attr, H5T_NATIVE_DOUBLE, &record.time);
    H5Aclose(attr);
    hid_t set = H5Dopen2(group, "position", H5P_DEFAULT);
    check(set, "open the positions of frame " + name);
    hid_t space = H5Dget_space(set);
    hsize_t dims[2] = {0, 0};
    H5Sget_simple_extent_dims(space, dims, nullptr);
    record.count = dims[0];
    H5Sclose(space);
    H5Dclose(set);
    H5Gclose(group);
    frames_.push_back(record);
  }
  H5Gclose(frames);
  if (frames_.size() != resume.frames)
    throw OutputError(path + " holds " + std::to_string(frames_.size()) +
                      " whole frames before the checkpoint, expected " +
                      std::to_string(resume.frames));
  // Per-step series: the rows after the checkpoint's step go.
  for (const char* root : {"/stats", "/probes", "/bodies"})
    if (H5Lexists(file_, root, H5P_DEFAULT) > 0) cut_series(file_, root, resume.series_rows);
  write_xdmf();
  flush();
}

RunFileWriter::~RunFileWriter() {
  if (file_ >= 0) {
    H5Fflush(file_, H5F_SCOPE_GLOBAL);
    H5Fclose(file_);
  }
}

long long RunFileWriter::ensure_group(const std::string& path) {
  // Creates every missing group along the path and returns the last one (caller closes it).
  std::string partial;
  std::stringstream in(path);
  std::string piece;
  hid_t group = H5Gopen2(file_, "/", H5P_DEFAULT);
  while (std::getline(in, piece, '/')) {
    if (piece.empty()) continue;
    partial += "/" + piece;
    hid_t next = H5Lexists(file_, partial.c_str(), H5P_DEFAULT) > 0
                     ? H5Gopen2(file_, partial.c_str(), H5P_DEFAULT)
                     : H5Gcreate2(file_, partial.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Gclose(group);
    if (next < 0) throw OutputError("HDF5: cannot create group " + partial + " in " + path_);
    group = next;
  }
  return group;
}

void RunFileWriter::write_frame(const ParticleView& view, std::int64_t step,
                                const std::vector<std::string>& fields) {
  // Before anything is written: a frame refused leaves no group behind.
  if (view.id) {
    std::vector<std::uint8_t> seen(view.count, 0);
    for (std::size_t i = 0; i < view.count; ++i)
      if (view.id[i] >= view.count || seen[view.id[i]]++)
        throw OutputError("frame " + std::to_string(frames_.size()) +
                          ": the particle ids are not a permutation of 0 .. N-1 (id " +
                          std::to_string(view.id[i]) + ")");
  }
  char name[32];
  std::snprintf(name, sizeof name, "/frames/%06zu", frames_.size());
  hid_t group = ensure_group(name);
  write_attribute(group, "time", H5T_NATIVE_DOUBLE, &view.time);
  write_attribute(group, "step", H5T_NATIVE_INT64, &step);
  const std::size_t n = view.count;
  auto wants = [&](const char* f) {
    for (const auto& x : fields)
      if (x == f) return true;
    return false;
  };
  // Row id of the particle at index i: the frames list particles by id, whatever order the run
  // keeps them in.
  auto row = [&](std::size_t i) { return view.id ? static_cast<std::size_t>(view.id[i]) : i; };
  auto vector_block = [&](const VectorView& v) {
    std::vector<double> block(n * dim_);
    for (std::size_t i = 0; i < n; ++i)
      for (int a = 0; a < dim_; ++a) block[row(i) * dim_ + a] = v(i, a);
    return block;
  };
  auto by_row = [&](const auto* values) {
    std::vector<std::remove_const_t<std::remove_pointer_t<decltype(values)>>> rows(n);
    for (std::size_t i = 0; i < n; ++i) rows[row(i)] = values[i];
    return rows;
  };
  write_dataset(group, "position", H5T_NATIVE_DOUBLE, vector_block(view.position), n, dim_);
  const bool velocity = wants("velocity") && view.velocity.component[0];
  const bool pressure = wants("pressure") && view.pressure;
  if (velocity)
    write_dataset(group, "velocity", H5T_NATIVE_DOUBLE, vector_block(view.velocity), n, dim_);
  if (pressure) write_dataset(group, "pressure", H5T_NATIVE_DOUBLE, by_row(view.pressure), n, 1);
  if (view.kind)  // kind is always written: readers need it to tell fluid from walls
    write_dataset(group, "kind", H5T_NATIVE_UINT8, by_row(view.kind), n, 1);
  if (wants("id")) {
    std::vector<std::uint64_t> ids(n);
    for (std::size_t i = 0; i < n; ++i) ids[i] = i;
    write_dataset(group, "id", H5T_NATIVE_UINT64, ids, n, 1);
  }
  if (wants("body")) {
    std::vector<std::int32_t> body(n, -1);
    if (view.body) body = by_row(view.body);
    write_dataset(group, "body", H5T_NATIVE_INT32, body, n, 1);
  }
  H5Gclose(group);
  frames_.push_back({std::string(name).substr(8), view.time, n, velocity, pressure});
  write_xdmf();
  flush();
}

namespace {
template <class T>
void append_rows(hid_t file, long long group_id, const std::string& name, hid_t type, const T* rows,
                 std::size_t row_count, std::size_t columns) {
  const int rank = columns > 1 ? 2 : 1;
  hid_t set;
  hsize_t old_rows = 0;
  if (H5Lexists(group_id, name.c_str(), H5P_DEFAULT) > 0) {
    set = H5Dopen2(group_id, name.c_str(), H5P_DEFAULT);
    hid_t space = H5Dget_space(set);
    hsize_t dims[2] = {0, 0};
    H5Sget_simple_extent_dims(space, dims, nullptr);
    H5Sclose(space);
    old_rows = dims[0];
  } else {
    hsize_t dims[2] = {0, columns}, max[2] = {H5S_UNLIMITED, columns}, chunk[2] = {256, columns};
    hid_t space = H5Screate_simple(rank, dims, max);
    hid_t props = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(props, rank, chunk);
    set = H5Dcreate2(group_id, name.c_str(), type, space, H5P_DEFAULT, props, H5P_DEFAULT);
    H5Pclose(props);
    H5Sclose(space);
  }
  check(set, "create or open dataset " + name);
  (void)file;
  if (row_count > 0) {
    hsize_t new_dims[2] = {old_rows + row_count, columns};
    check(H5Dset_extent(set, new_dims), "extend dataset " + name);
    hid_t file_space = H5Dget_space(set);
    hsize_t start[2] = {old_rows, 0}, count[2] = {row_count, columns};
    H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr);
    hid_t memory_space = H5Screate_simple(rank, count, nullptr);
    check(H5Dwrite(set, type, memory_space, file_space, H5P_DEFAULT, rows), "append to " + name);
    H5Sclose(memory_space);
    H5Sclose(file_space);
  }
  H5Dclose(set);
}

std::pair<std::string, std::string> split_path(const std::string& dataset) {
  const auto slash = dataset.find_last_of('/');
  return {dataset.substr(0, slash), dataset.substr(slash + 1)};
}
}  // namespace

void RunFileWriter::append(const std::string& dataset, const double* rows, std::size_t row_count,
                           std::size_t columns) {
  const auto [group_path, name] = split_path(dataset);
  hid_t group = ensure_group(group_path);
  append_rows(file_, group, name, H5T_NATIVE_DOUBLE, rows, row_count, columns);
  H5Gclose(group);
}

void RunFileWriter::append(const std::string& dataset, const std::int64_t* rows,
                           std::size_t row_count, std::size_t columns) {
  const auto [group_path, name] = split_path(dataset);
  hid_t group = ensure_group(group_path);
  append_rows(file_, group, name, H5T_NATIVE_INT64, rows, row_count, columns);
  H5Gclose(group);
}

void RunFileWriter::set_string_attribute(const std::string& object, const std::string& name,
                                         const std::string& value) {
  hid_t group = ensure_group(object);
  write_string_attribute(group, name, value);
  H5Gclose(group);
}

void RunFileWriter::write_checkpoint(const Checkpoint& c) {
  const std::string slot = c.frame % 2 == 0 ? "/checkpoint/a" : "/checkpoint/b";
  hid_t group = ensure_group(slot);
  const std::int32_t incomplete = 0, complete = 1;
  replace_attribute(group, "complete", H5T_NATIVE_INT32, &incomplete);
  flush();
  std::vector<std::string> keep;
  for (const auto& [name, v] : c.reals) {
    write_state_array(group, name, H5T_NATIVE_DOUBLE, v.data(), v.size());
    keep.push_back(name);
  }
  for (const auto& [name, v] : c.integers) {
    write_state_array(group, name, H5T_NATIVE_INT64, v.data(), v.size());
    keep.push_back(name);
  }
  for (const auto& [name, v] : c.bytes) {
    write_state_array(group, name, H5T_NATIVE_UINT8, v.data(), v.size());
    keep.push_back(name);
  }
  for (const auto& name : child_names(group))
    if (std::find(keep.begin(), keep.end(), name) == keep.end())
      H5Ldelete(group, name.c_str(), H5P_DEFAULT);
  for (const auto& name : attribute_names(group))
    if (name != "complete") H5Adelete(group, name.c_str());
  for (const auto& [name, v] : c.numbers) write_attribute(group, name, H5T_NATIVE_DOUBLE, &v);
  for (const auto& [name, v] : c.counts) write_attribute(group, name, H5T_NATIVE_INT64, &v);
  write_attribute(group, "frame", H5T_NATIVE_INT64, &c.frame);
  write_attribute(group, "format", H5T_NATIVE_INT64, &Checkpoint::kFormat);
  replace_attribute(group, "complete", H5T_NATIVE_INT32, &complete);
  H5Gclose(group);
  flush();
}

void RunFileWriter::flush() {
  if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) throw OutputError("cannot flush " + path_);
}

void RunFileWriter::write_xdmf() const {
  const std::string xdmf_path = std::filesystem::path(path_).replace_extension(".xdmf").string();
  const std::string h5_name = std::filesystem::path(path_).filename().string();
  std::ofstream out(xdmf_path + ".tmp");
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  const char* geometry = dim_ == 2 ? "XY" : "XYZ";
  for (const auto& f : frames_) {
    const std::string base = h5_name + ":/frames/" + f.name + "/";
    out << "   <Grid Name=\"frame" << f.name << "\" GridType=\"Uniform\">\n"
        << "    <Time Value=\"" << f.time << "\"/>\n"
        << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << f.count << "\"/>\n"
        << "    <Geometry GeometryType=\"" << geometry << "\">\n"
        << "     <DataItem Dimensions=\"" << f.count << " " << dim_
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << base
        << "position</DataItem>\n"
        << "    </Geometry>\n";
    if (f.has_velocity)
      out << "    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n"
          << "     <DataItem Dimensions=\"" << f.count << " " << dim_
          << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << base
          << "velocity</DataItem>\n    </Attribute>\n";
    if (f.has_pressure)
      out << "    <Attribute Name=\"pressure\" AttributeType=\"Scalar\" Center=\"Node\">\n"
          << "     <DataItem Dimensions=\"" << f.count
          << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << base
          << "pressure</DataItem>\n    </Attribute>\n";
    out << "    <Attribute Name=\"kind\" AttributeType=\"Scalar\" Center=\"Node\">\n"
        << "     <DataItem Dimensions=\"" << f.count
        << "\" NumberType=\"UChar\" Precision=\"1\" Format=\"HDF\">" << base
        << "kind</DataItem>\n    </Attribute>\n   </Grid>\n";
  }
  out << "  </Grid>\n </Domain>\n</Xdmf>\n";
  out.close();
  std::error_code ec;
  std::filesystem::rename(xdmf_path + ".tmp", xdmf_path, ec);
}

void write_root_attributes(const std::string& path,
                           const std::vector<std::pair<std::string, double>>& numbers,
                           const std::vector<std::pair<std::string, std::string>>& texts) {
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) throw OutputError("cannot open " + path + " to add attributes");
  try {
    for (const auto& [name, value] : numbers) {
      if (H5Aexists(file, name.c_str()) > 0) H5Adelete(file, name.c_str());
      write_attribute(file, name, H5T_NATIVE_DOUBLE, &value);
    }
    for (const auto& [name, value] : texts) write_string_attribute(file, name, value);
  } catch (const OutputError& e) {
    H5Fclose(file);
    throw OutputError(std::string(e.what()) + " of " + path);
  }
  if (H5Fclose(file) < 0) throw OutputError("cannot close " + path);
}

}  // namespace washout::io

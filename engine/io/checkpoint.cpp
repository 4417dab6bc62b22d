#include "engine/io/checkpoint.hpp"

namespace washout::io {
namespace {

template <class Map>
const typename Map::mapped_type& find(const Map& map, const std::string& name, const char* what) {
  const auto it = map.find(name);
  if (it == map.end())
    throw CheckpointError("the checkpoint has no " + std::string(what) + " '" + name + "'");
  return it->second;
}

template <class Vector>
const Vector& sized(const Vector& v, const std::string& name, std::size_t size) {
  if (v.size() != size)
    throw CheckpointError("the checkpoint's '" + name + "' has " + std::to_string(v.size()) +
                          " values, this scene needs " + std::to_string(size));
  return v;
}

}  // namespace

double Checkpoint::number(const std::string& name) const { return find(numbers, name, "number"); }

std::int64_t Checkpoint::count(const std::string& name) const {
  return find(counts, name, "count");
}

const std::vector<double>& Checkpoint::real(const std::string& name, std::size_t size) const {
  return sized(real(name), name, size);
}

const std::vector<double>& Checkpoint::real(const std::string& name) const {
  return find(reals, name, "array");
}

const std::vector<std::int64_t>& Checkpoint::integer(const std::string& name) const {
  return find(integers, name, "array");
}

const std::vector<std::uint8_t>& Checkpoint::byte(const std::string& name, std::size_t size) const {
  return sized(find(bytes, name, "array"), name, size);
}

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t k = 0; k < size; ++k) {
    hash ^= p[k];
    hash *= 1099511628211ull;
  }
  return hash;
}

}  // namespace washout::io

#pragma once
// One pressure system of a real run (A, b and the solver's initial guess x0) in a small binary
// file, written by bench_ppe_dump and read by bench_solvers. Layout, native endianness:
//   "WPPE1\0\0\0", rows (u64), nonzeros (u64), row_start (i64 x rows+1), column (i32 x nnz),
//   value (f64 x nnz), b (f64 x rows), x0 (f64 x rows)
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/solvers/sparse_matrix.hpp"

namespace washout::bench {

struct PpeSystem {
  CsrMatrix A;
  std::vector<double> b, x0;
};

inline void write_ppe_system(const std::string& path, const CsrMatrix& A,
                             const std::vector<double>& b, const std::vector<double>& x0) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write " + path);
  const char magic[8] = {'W', 'P', 'P', 'E', '1', 0, 0, 0};
  const std::uint64_t rows = A.rows, nnz = A.nonzeros();
  std::vector<double> guess(x0);
  guess.resize(A.rows, 0.0);
  bool ok = std::fwrite(magic, 1, 8, f) == 8 && std::fwrite(&rows, 8, 1, f) == 1 &&
            std::fwrite(&nnz, 8, 1, f) == 1 &&
            std::fwrite(A.row_start.data(), 8, rows + 1, f) == rows + 1 &&
            std::fwrite(A.column.data(), 4, nnz, f) == nnz &&
            std::fwrite(A.value.data(), 8, nnz, f) == nnz &&
            std::fwrite(b.data(), 8, rows, f) == rows &&
            std::fwrite(guess.data(), 8, rows, f) == rows;
  ok = std::fclose(f) == 0 && ok;
  if (!ok) throw std::runtime_error("cannot write " + path);
}

inline PpeSystem read_ppe_system(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw std::runtime_error("cannot read " + path);
  char magic[8];
  std::uint64_t rows = 0, nnz = 0;
  PpeSystem s;
  bool ok = std::fread(magic, 1, 8, f) == 8 && std::memcmp(magic, "WPPE1", 5) == 0 &&
            std::fread(&rows, 8, 1, f) == 1 && std::fread(&nnz, 8, 1, f) == 1;
  if (ok) {
    s.A.rows = rows;
    s.A.row_start.resize(rows + 1);
    s.A.column.resize(nnz);
    s.A.value.resize(nnz);
    s.b.resize(rows);
    s.x0.resize(rows);
    ok = std::fread(s.A.row_start.data(), 8, rows + 1, f) == rows + 1 &&
         std::fread(s.A.column.data(), 4, nnz, f) == nnz &&
         std::fread(s.A.value.data(), 8, nnz, f) == nnz &&
         std::fread(s.b.data(), 8, rows, f) == rows && std::fread(s.x0.data(), 8, rows, f) == rows;
  }
  std::fclose(f);
  if (!ok)
    throw std::runtime_error(path + " is not a pressure system file (bench/ppe_system_file.hpp)");
  return s;
}

}  // namespace washout::bench

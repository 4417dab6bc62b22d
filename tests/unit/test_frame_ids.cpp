// Frames list particles by id (engine/io/run_file_writer.cpp): a run that keeps its fluid in
// cell order (reorder_interval) hands the writer its arrays with each particle's id, and the
// writer puts every particle at its id's row, so a frame reads the same whatever the order.
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "engine/io/run_file_reader.hpp"
#include "engine/io/run_file_writer.hpp"

namespace washout {
namespace {

TEST(FrameIds, EachParticleIsWrittenAtItsIdsRow) {
  const auto dir = std::filesystem::path(WASHOUT_TEST_OUTPUT_DIR) / "frame_ids";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "ids.h5").string();
  // Four particles held in the order of ids 2, 0, 3, 1; particle id k sits at x = k.
  const std::vector<std::uint64_t> id = {2, 0, 3, 1};
  const std::vector<double> x = {2, 0, 3, 1}, y = {20, 0, 30, 10}, u = {-2, 0, -3, -1},
                            v = {0, 0, 0, 0}, pressure = {200, 0, 300, 100};
  const std::vector<std::uint8_t> kind = {0, 0, 1, 0};     // id 3 is a wall
  const std::vector<std::int32_t> body = {-1, -1, 5, -1};  // ... of body 5, say
  ParticleView view;
  view.dim = 2;
  view.count = 4;
  view.position.component[0] = x.data(), view.position.component[1] = y.data();
  view.velocity.component[0] = u.data(), view.velocity.component[1] = v.data();
  view.pressure = pressure.data();
  view.kind = kind.data();
  view.body = body.data();
  view.id = id.data();
  {
    io::RunHeader header;
    header.scene_name = "ids";
    header.dim = 2;
    header.d0 = 0.01;
    io::RunFileWriter writer(path, header);
    writer.write_frame(view, 0, {"velocity", "pressure", "id", "body"});
    // Anything but a permutation of 0 .. N-1 is refused, not written out of bounds.
    const std::vector<std::uint64_t> twice = {2, 0, 2, 1};
    view.id = twice.data();
    EXPECT_THROW(writer.write_frame(view, 1, {"id"}), io::OutputError);
  }
  io::RunFileReader reader(path);
  EXPECT_EQ(reader.frame_count(), 1u);  // the refused frame left nothing behind
  const io::FrameData f = reader.read_frame(0);
  ASSERT_EQ(f.count, 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(f.id[k], k);
    EXPECT_EQ(f.position[2 * k], double(k));
    EXPECT_EQ(f.position[2 * k + 1], 10.0 * k);
    EXPECT_EQ(f.velocity[2 * k], -double(k));
    EXPECT_EQ(f.pressure[k], 100.0 * k);
    EXPECT_EQ(f.kind[k], k == 3 ? 1 : 0);
    EXPECT_EQ(f.body[k], k == 3 ? 5 : -1);
  }
}

}  // namespace
}  // namespace washout

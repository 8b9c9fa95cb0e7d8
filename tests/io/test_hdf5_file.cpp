// The HDF5 wrapper (io/hdf5_file): round trips of every dataset and attribute kind, and no
// timestamps in the file, so that equal content gives equal bytes.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>

#include "io/hdf5_file.hpp"
#include "support/scene_text.hpp"

using rotorsweep::io::Hdf5Location;

namespace {

void write_sample(const std::string& path) {
  const auto file = Hdf5Location::create_file(path);
  file.set_flag("complete", true);
  file.set_attribute("scene", std::string("[model]\nrows = 2\n"));
  file.set_attribute("wall_seconds", 1.5);
  file.set_attribute("threads", std::int64_t(2));
  const auto group = file.create_group("members");
  group.write("A", std::vector<double>{1, 2, NAN}, {}, "substrate strength");
  group.write("theta", std::vector<double>{1, 2, 3, 4, 5, 6}, {3, 2});
  group.write("periods_run", std::vector<std::int64_t>{4, 5, 6});
  group.write("ic", std::vector<std::string>{"FM", "AFM", "random"});
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST_CASE("datasets and attributes round-trip", "[io][hdf5]") {
  const auto dir = rotorsweep::testing::scratch_directory("hdf5");
  const std::string path = (dir / "sample.h5").string();
  write_sample(path);
  const auto file = Hdf5Location::open_file(path);
  CHECK(file.attribute_flag("complete"));
  CHECK(file.attribute_string("scene") == "[model]\nrows = 2\n");
  CHECK(file.attribute_double("wall_seconds") == 1.5);
  CHECK(file.attribute_double("threads") == 2);
  CHECK_FALSE(file.has_attribute("absent"));
  REQUIRE(file.has("members"));
  const auto group = file.open_group("members");
  CHECK(group.members() == std::vector<std::string>{"A", "ic", "periods_run", "theta"});
  const auto A = group.read_doubles("A");
  CHECK(A[1] == 2);
  CHECK(std::isnan(A[2]));
  std::vector<hsize_t> dims;
  CHECK(group.read_doubles("theta", &dims) == std::vector<double>{1, 2, 3, 4, 5, 6});
  CHECK(dims == std::vector<hsize_t>{3, 2});
  CHECK(group.read_integers("periods_run") == std::vector<std::int64_t>{4, 5, 6});
  CHECK(group.read_strings("ic") == std::vector<std::string>{"FM", "AFM", "random"});
  CHECK(group.read_bytes("periods_run").size() == 3 * 8);
  CHECK_THROWS_WITH(group.read_doubles("absent"), Catch::Contains("absent"));
}

TEST_CASE("equal content gives equal bytes (no timestamps)", "[io][hdf5]") {
  const auto dir = rotorsweep::testing::scratch_directory("hdf5-bytes");
  write_sample((dir / "a.h5").string());
  write_sample((dir / "b.h5").string());
  CHECK(bytes_of((dir / "a.h5").string()) == bytes_of((dir / "b.h5").string()));
}

TEST_CASE("unopenable files are errors naming the path", "[io][hdf5]") {
  const auto dir = rotorsweep::testing::scratch_directory("hdf5-errors");
  CHECK_THROWS_WITH(Hdf5Location::open_file((dir / "absent.h5").string()), Catch::Contains("absent.h5"));
  CHECK_THROWS_WITH(Hdf5Location::create_file((dir / "no" / "such" / "dir.h5").string()),
                    Catch::Contains("dir.h5"));
}

TEST_CASE("pre-sized table columns of one, two and three dimensions take rows in any subset", "[io][hdf5]") {
  using rotorsweep::io::ColumnType;
  const auto dir = rotorsweep::testing::scratch_directory("hdf5-columns");
  const std::string path = (dir / "columns.h5").string();
  {
    const auto file = Hdf5Location::create_file(path);
    file.create_column("flat", ColumnType::float64, {4, 0, 0}, "");
    file.create_column("rows", ColumnType::int64, {4, 3, 0}, "");
    file.create_column("blocks", ColumnType::float64, {4, 2, 0, 3}, "samples × rotors");
    const std::vector<hsize_t> rows{0, 2, 3};  // row 1 is left unwritten
    file.write_rows("flat", rows, std::vector<double>{1, 3, 4}.data());
    file.write_rows("rows", rows, std::vector<std::int64_t>{0, 1, 2, 20, 21, 22, 30, 31, 32}.data());
    std::vector<double> blocks;
    for (const int r : {0, 2, 3})
      for (int k = 0; k < 6; ++k) blocks.push_back(10 * r + k);
    file.write_rows("blocks", rows, blocks.data());
  }
  const auto file = Hdf5Location::open_file(path);
  CHECK(file.shape("blocks") == std::pair<hsize_t, hsize_t>{4, 6});  // values per row
  std::vector<hsize_t> dims;
  file.read_doubles("blocks", &dims);
  CHECK(dims == std::vector<hsize_t>{4, 2, 3});
  CHECK(file.read_rows_doubles("blocks", 2, 2) ==
        std::vector<double>{20, 21, 22, 23, 24, 25, 30, 31, 32, 33, 34, 35});
  CHECK(file.read_rows_integers("rows", 2, 1) == std::vector<std::int64_t>{20, 21, 22});
  CHECK(file.read_rows_doubles("flat", 3, 1) == std::vector<double>{4});
}

TEST_CASE("scattered rows (a GPU's first and second pass) land where they belong, those between kept",
          "[io][hdf5]") {
  using rotorsweep::io::ColumnType;
  const auto dir = rotorsweep::testing::scratch_directory("hdf5-scattered");
  const std::string path = (dir / "scattered.h5").string();
  constexpr hsize_t rows_in_file = 3000;
  // every tenth row: 300 runs of one row, sparser than a span (points for narrow rows, parts of 16 runs
  // for wide ones); every third: 1 000 runs filling a third of their span (the span, read back and written
  // whole); then every row left, around those written (the span again, keeping them)
  const hsize_t stride = GENERATE(hsize_t(10), hsize_t(3));
  INFO("every " << stride << "th row first, then the rest");
  std::vector<hsize_t> first, rest;
  for (hsize_t r = 0; r < rows_in_file; ++r) (r % stride == 1 ? first : rest).push_back(r);
  const auto value = [](hsize_t r, int k) { return 100.0 * double(r) + k; };
  const auto label = [](hsize_t r) { return "row " + std::to_string(r); };
  const auto write = [&](const Hdf5Location& file, const std::vector<hsize_t>& rows) {
    std::vector<double> flat, blocks;
    std::vector<std::int64_t> pairs;
    std::vector<std::string> labels;
    for (const hsize_t r : rows) {
      flat.push_back(double(r));
      pairs.insert(pairs.end(), {std::int64_t(r), -std::int64_t(r)});
      for (int k = 0; k < 12; ++k) blocks.push_back(value(r, k));
      labels.push_back(label(r));
    }
    file.write_rows("flat", rows, flat.data());
    file.write_rows("pairs", rows, pairs.data());
    file.write_rows("blocks", rows, blocks.data());
    file.write_rows("labels", rows, labels);
  };
  {
    const auto file = Hdf5Location::create_file(path);
    file.create_column("flat", ColumnType::float64, {rows_in_file, 0, 0}, "");
    file.create_column("pairs", ColumnType::int64, {rows_in_file, 2, 0}, "");
    file.create_column("blocks", ColumnType::float64, {rows_in_file, 3, 0, 4}, "");
    file.create_column("labels", ColumnType::text, {rows_in_file, 0, 16}, "");
    write(file, first);
  }
  write(Hdf5Location::open_file_for_writing(path), rest);
  const auto file = Hdf5Location::open_file(path);
  const auto flat = file.read_rows_doubles("flat", 0, rows_in_file);
  const auto pairs = file.read_rows_integers("pairs", 0, rows_in_file);
  const auto blocks = file.read_rows_doubles("blocks", 0, rows_in_file);
  const auto labels = file.read_rows_strings("labels", 0, rows_in_file);
  std::size_t wrong = 0;
  for (hsize_t r = 0; r < rows_in_file; ++r) {
    bool right = flat[r] == double(r) && pairs[2 * r] == std::int64_t(r) &&
                 pairs[2 * r + 1] == -std::int64_t(r) && labels[r] == label(r);
    for (int k = 0; k < 12; ++k) right = right && blocks[12 * r + std::size_t(k)] == value(r, k);
    wrong += !right;
  }
  CHECK(wrong == 0);
}

TEST_CASE("a reader holding a file open does not keep its writer from opening it", "[io][hdf5]") {
  // a run reopens the file it created once it is in place; `info` or h5py reading it at that moment, in
  // another process, must not make the run fail (OutputTarget's locks, not HDF5's, keep writers apart)
  const auto dir = rotorsweep::testing::scratch_directory("hdf5-reader-writer");
  const std::string path = (dir / "shared.h5").string();
  Hdf5Location::create_file(path).set_flag("complete", false);
  int held[2], release[2];
  REQUIRE(::pipe(held) == 0);
  REQUIRE(::pipe(release) == 0);
  char byte = 1;
  const pid_t reader = ::fork();
  REQUIRE(reader >= 0);
  if (reader == 0) {  // the reader: holds the file open until told to let go
    {
      const auto file = Hdf5Location::open_file(path);
      if (::write(held[1], &byte, 1) != 1) ::_exit(1);
      if (::read(release[0], &byte, 1) != 1) ::_exit(1);
    }
    ::_exit(0);
  }
  REQUIRE(::read(held[0], &byte, 1) == 1);  // an event: the reader has the file open
  std::string failure;
  try {
    Hdf5Location::open_file_for_writing(path).set_flag("complete", true);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  REQUIRE(::write(release[1], &byte, 1) == 1);
  int status = 0;
  ::waitpid(reader, &status, 0);
  CHECK(failure.empty());
  CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
  CHECK(Hdf5Location::open_file(path).attribute_flag("complete"));
}

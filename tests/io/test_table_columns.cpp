// A table's rows packed where a member finishes and written by another thread (io/table_columns.hpp):
// every column's values land in their member's row, NaN beyond a short vector, text padded with NUL.
#include <catch2/catch.hpp>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/table_columns.hpp"
#include "support/scene_text.hpp"

namespace {

using Column = rotorsweep::io::TableColumn<int>;
using rotorsweep::io::Hdf5Location;

/// Member m's columns: a real, an integer, a text, and a vector of width 3 holding m % 3 values.
std::vector<Column> columns() {
  return {
      Column::real_valued("x", "", [](const int& m) { return 0.5 * m; }),
      Column::integer_valued("n", "", [](const int& m) { return std::int64_t(-m); }),
      Column::text_valued("label", 4, "", [](const int& m) { return std::string(std::size_t(m % 5), 'a'); }),
      Column::vector_valued("v", 3, "",
                            [](const int& m) { return std::vector<double>(std::size_t(m % 3), m); })};
}

}  // namespace

TEST_CASE("packed rows land in their members' rows, whatever order they are packed in", "[io][hdf5]") {
  const auto dir = rotorsweep::testing::scratch_directory("table-columns");
  const std::string path = (dir / "packed.h5").string();
  constexpr int members = 40;
  const auto table = columns();
  {
    const auto file = Hdf5Location::create_file(path);
    rotorsweep::io::create_table_columns(file, table, members);
    std::vector<rotorsweep::io::PackedRow> packed;
    for (int m = members - 1; m >= 0; m -= 2) packed.push_back({std::size_t(m), {}});  // odd rows only
    std::vector<hsize_t> rows;
    std::vector<const rotorsweep::io::PackedRow*> order;
    for (auto it = packed.rbegin(); it != packed.rend(); ++it) {
      it->bytes = rotorsweep::io::pack_table_row(table, int(it->index));
      rows.push_back(it->index);
      order.push_back(&*it);
    }
    rotorsweep::io::write_packed_rows(file, table, rows, order);
  }
  const auto file = Hdf5Location::open_file(path);
  const auto x = file.read_rows_doubles("x", 0, members);
  const auto n = file.read_rows_integers("n", 0, members);
  const auto label = file.read_rows_strings("label", 0, members);
  const auto v = file.read_rows_doubles("v", 0, members);
  for (int m = 1; m < members; m += 2) {
    INFO("member " << m);
    CHECK(x[std::size_t(m)] == 0.5 * m);
    CHECK(n[std::size_t(m)] == -m);
    CHECK(label[std::size_t(m)] == std::string(std::size_t(m % 5), 'a'));
    for (int k = 0; k < 3; ++k)
      CHECK((k < m % 3 ? v[std::size_t(3 * m + k)] == m : std::isnan(v[std::size_t(3 * m + k)])));
  }
}

TEST_CASE("a text longer than its column is refused when the row is packed, naming the column", "[io]") {
  auto table = columns();
  table[2] = Column::text_valued("label", 2, "", [](const int&) { return std::string("abc"); });
  CHECK_THROWS_WITH(rotorsweep::io::pack_table_row(table, 1),
                    Catch::Contains("label") && Catch::Contains("abc"));
}

// Sweeps with coupling tables and open rows (docs/model.md §1 "Extended couplings", §8): an explicit
// nearest-neighbour table through CoupledRows against today's model, scalar and SIMD lanes and
// thread counts giving the same bits, the table's scene keys, and bad tables named.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/row_models.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "support/scene_sweep.hpp"

using namespace rotorsweep::ensemble;
using Catch::Detail::Approx;
using rotorsweep::testing::sweep;

namespace {
const std::string grid =
    "[drive]\ng = [0.0011]\n[sweep]\nA = [1.0, 3.0, 11.0, 12.0]\n[initial]\nkinds = [\"AFM\", \"FM\"]\n"
    "[numerics]\nrtol = 1e-10\natol = 1e-13\n";

}  // namespace

TEST_CASE("an explicit nearest-neighbour table reproduces today's model outside CP",
          "[ensemble][couplings]") {
  const auto nearest = sweep("[model]\nrows = 12\n" + grid);
  const auto table = sweep("[model]\nrows = 12\ncoupling_table = { a = 1.5, b = [1.0], c = [0.0] }\n" + grid);
  REQUIRE(nearest.size() == table.size());
  for (std::size_t i = 0; i < nearest.size(); ++i) {
    INFO("member " << i);
    REQUIRE(table[i].status == rotorsweep::kernels::LaneStatus::ok);
    CHECK(table[i].regime == nearest[i].regime);
    CHECK(table[i].dissipation() == Approx(nearest[i].dissipation()).epsilon(1e-7).margin(1e-12));
  }
}

TEST_CASE("dipolar sweeps: lanes and threads do not change the bits, open rows differ from periodic",
          "[ensemble][couplings]") {
  const std::string model = "[model]\nrows = 10\ncouplings = \"dipolar\"\nrange = \"all\"\n";
  const auto simd = sweep(model + grid, 2);
  const auto scalar = sweep(model + grid + "lanes = \"scalar\"\n", 1);
  const auto open = sweep(model + "boundary = \"open\"\n" + grid, 1);
  REQUIRE(simd.size() == scalar.size());
  for (std::size_t i = 0; i < simd.size(); ++i) {
    INFO("member " << i);
    CHECK(simd[i].status == rotorsweep::kernels::LaneStatus::ok);
    CHECK(simd[i].dissipation() == scalar[i].dissipation());
    CHECK(simd[i].theta_final == scalar[i].theta_final);
    CHECK(open[i].dissipation() != simd[i].dissipation());
  }
}

TEST_CASE("coupling keys are read, and bad tables are named", "[ensemble][couplings][io]") {
  using rotorsweep::io::parse_scene_text;
  const std::string rest = "[drive]\ng = [0.01]\n[sweep]\nA = [1.0]\n";
  const auto dipolar = parse_scene_text(
      "[model]\nrows = 8\ncouplings = \"dipolar\"\nrange = 3\nrow_length = 7\nboundary = \"open\"\n" + rest,
      "s");
  CHECK(dipolar.couplings.kind == RowCouplings::Kind::dipolar);
  CHECK(dipolar.couplings.range == 3);
  CHECK(dipolar.couplings.row_length == 7);
  CHECK(dipolar.couplings.open);
  CHECK(dipolar.model == rotorsweep::ensemble::RowModelKind::coupled);
  CHECK(dipolar.couplings.for_rows(8).b == dipolar_table(3, 7).b);
  // periodic rows: a partner N/2 away is counted once
  const auto ring =
      parse_scene_text("[model]\nrows = 8\ncouplings = \"dipolar\"\nrange = \"all\"\n" + rest, "s");
  const auto table = ring.couplings.for_rows(8);
  REQUIRE(table.range() == 4);
  CHECK(table.b[3] == 0.5 * dipolar_table(4, 0).b[3]);
  CHECK(parse_scene_text("[model]\nrows = 8\n" + rest, "s").model ==
        rotorsweep::ensemble::RowModelKind::nearest_neighbour);
  CHECK(parse_scene_text("[model]\nrows = 8\nboundary = \"open\"\n" + rest, "s").model ==
        rotorsweep::ensemble::RowModelKind::coupled);

  const auto refused = [&](const std::string& model, const std::string& key) {
    INFO(model);
    CHECK_THROWS_WITH(parse_scene_text("[model]\nrows = 8\n" + model + rest, "s"), Catch::Contains(key));
  };
  refused("couplings = \"dipolar\"\nrange = 5\n", "model.range");
  refused("couplings = \"dipolar\"\nrange = 8\nboundary = \"open\"\n", "model.range");
  refused("couplings = \"dipolar\"\nrange = 0\n", "model.range");
  refused("couplings = \"dipolar\"\nrange = -1\n", "model.range");
  refused("couplings = \"dipolar\"\nrow_length = \"long\"\n", "model.row_length");
  refused("range = 2\n", "model.range");
  refused("couplings = \"next\"\n", "model.couplings");
  refused("coupling_table = { a = 1.5, b = [1.0, 0.2], c = [0.0] }\n", "model.coupling_table.c");
  refused("coupling_table = { a = 1.5, b = [1.0], c = [0.0], d = 1 }\n", "model.coupling_table.d");
  refused("coupling_table = { a = 1.5, c = [0.0] }\n", "model.coupling_table.b");
  refused("coupling_table = { a = 1.5, b = [1.0, 1.0, 1.0, 1.0, 1.0], c = [0, 0, 0, 0, 0] }\n",
          "model.coupling_table");
  refused("couplings = \"nearest\"\ncoupling_table = { a = 1.5, b = [1.0], c = [0.0] }\n", "exclude");
  refused("boundary = \"closed\"\n", "model.boundary");
  refused("couplings = \"dipolar\"\n[disorder]\ncoupling = 0.1\n", "disorder.coupling");
  refused("boundary = \"open\"\n[disorder]\ncoupling_rows = [0.1, 0.0]\n", "disorder.coupling_rows");
  CHECK_NOTHROW(parse_scene_text(
      "[model]\nrows = 8\ncouplings = \"dipolar\"\n[disorder]\nA = 0.1\nanisotropy = 0.1\n" + rest, "s"));
}

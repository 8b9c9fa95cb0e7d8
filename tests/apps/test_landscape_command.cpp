// `rotorsweep landscape chambers|curves|jump-friction`: complete HDF5 files with the documented
// datasets and values, and exit code 2 for bad options.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "io/hdf5_file.hpp"
#include "io/output_target.hpp"
#include "support/cli.hpp"
#include "support/scene_text.hpp"

using namespace rotorsweep::testing;
using rotorsweep::io::Hdf5Location;

TEST_CASE("landscape chambers writes the raster and counts the seven zones", "[apps][landscape]") {
  const auto dir = scratch_directory("landscape-chambers");
  const auto path = (dir / "c.h5").string();
  const auto run = run_cli("landscape chambers --A-cells 120 --tau-cells 90 -q -o '" + path + "'", dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("7 zones"));
  const auto file = Hdf5Location::open_file(path);
  CHECK(file.attribute_flag("complete"));
  CHECK(file.attribute_double("zones") == 7);
  std::vector<hsize_t> dims;
  file.read_doubles("A", &dims);
  CHECK(dims == std::vector<hsize_t>{120});
  const auto minima = file.read_integers("minima"), saddles = file.read_integers("saddles"),
             maxima = file.read_integers("maxima");
  REQUIRE(minima.size() == 120 * 90);
  for (std::size_t k = 0; k < minima.size(); ++k) REQUIRE(minima[k] - saddles[k] + maxima[k] == 0);
  CHECK(file.read_integers("counts").size() == 120 * 90 * 9);
}

TEST_CASE("landscape curves and jump-friction write their closed forms", "[apps][landscape]") {
  const auto dir = scratch_directory("landscape-curves");
  const auto curves = (dir / "curves.h5").string(), jump = (dir / "jump.h5").string();
  REQUIRE(run_cli("landscape curves --samples 500 -o '" + curves + "'", dir).exit_code == 0);
  const auto c = Hdf5Location::open_file(curves);
  for (const char* name :
       {"fm_tangential", "fm_transverse", "off_diagonal_plus", "off_diagonal_minus", "alignment"}) {
    INFO(name);
    const auto tau = c.open_group(name).read_doubles("tau");
    CHECK(tau.size() > 100);
    for (double t : tau) REQUIRE((t >= 0 && t <= std::acos(0.0)));
  }
  CHECK(c.attribute_double("A_star") == Approx(8.778365775883558));

  REQUIRE(run_cli("landscape jump-friction --count 101 -o '" + jump + "'", dir).exit_code == 0);
  const auto j = Hdf5Location::open_file(jump);
  CHECK(j.attribute_flag("complete"));
  const auto A = j.read_doubles("A"), J = j.read_doubles("J");
  REQUIRE(A.size() == 101);
  CHECK(A.front() == Approx(4.634583466980286));
  CHECK(J.front() == Approx(4.975766521411717));
  CHECK(J.back() == Approx(0).margin(1e-12));
  for (std::size_t i = 1; i < J.size(); ++i) CHECK(J[i] < J[i - 1]);

  const auto info = run_cli("info '" + jump + "'", dir);
  INFO(info.output);
  CHECK(info.exit_code == 0);
  CHECK_THAT(info.output, Catch::Contains("landscape jump-friction"));
  CHECK_THAT(info.output, Catch::Contains("A_star       8.77836577588355"));
}

TEST_CASE("landscape rejects bad options with exit code 2", "[apps][landscape]") {
  const auto dir = scratch_directory("landscape-bad");
  const auto out = " -o '" + (dir / "x.h5").string() + "'";
  CHECK(run_cli("landscape chambers --A-min 5 --A-max 2" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape chambers --A-cells 1" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape jump-friction --count 0" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape curves", dir).exit_code == 2);  // -o is required
  CHECK(run_cli("landscape bifurcations" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape chambers --A-max inf" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape chambers --A-min nan" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape curves --A-max nan" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape curves --A-max -5" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape curves -o ''", dir).exit_code == 2);
  CHECK(run_cli("landscape curves --coefficients 1.5,2" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape curves --coefficients 1.5,2,nan" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape curves --range 2 --coefficients 1.5,2,0" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape curves --row-length 5" + out, dir).exit_code == 2);  // needs --range
  CHECK(run_cli("landscape curves --range 2 --row-length 0" + out, dir).exit_code == 2);
  CHECK(run_cli("landscape jump-friction --A-min 9 --A-max 3" + out, dir).exit_code == 2);
  // coefficients without a CP window: one message naming them, not options never given, and no NaN file
  for (const char* command : {"jump-friction --count 3", "curves", "chambers"}) {
    const auto run = run_cli("landscape " + std::string(command) + " --coefficients 0,0,0" + out, dir);
    INFO(run.output);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains("--coefficients") && !Catch::Contains("--A-min"));
  }
  CHECK(!std::filesystem::exists(dir / "x.h5"));
}

TEST_CASE("landscape refuses a raster or grid that would not fit in memory, saying what it needs",
          "[apps][landscape]") {
  const auto dir = scratch_directory("landscape-memory");
  const auto out = " -o '" + (dir / "x.h5").string() + "'";
  const auto refused = [&](const std::string& command, const std::string& option) {
    const auto run = run_cli(command + out, dir, "ulimit -v 2000000; ");
    INFO(run.output);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains("GiB") && Catch::Contains(option) && Catch::Contains("ulimit -v"));
  };
  refused("landscape chambers -q --A-cells 100000 --tau-cells 100000", "--A-cells");
  refused("landscape jump-friction -q --count 100000000", "--count");
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);
}

TEST_CASE("landscape on a full disk: a clear error and no file", "[apps][landscape][files]") {
  const auto dir = scratch_directory("landscape-full-disk");
  // a 40 x 30 raster: 0.1 s to compute, 180 kB to write, beyond the 8 or 16 kB the limit allows
  const auto run =
      run_cli("landscape chambers -q --A-cells 40 --tau-cells 30 -o '" + (dir / "c.h5").string() + "'", dir,
              "ulimit -f 16; ");
  CHECK(run.exit_code == 1);
  CHECK_THAT(run.output, Catch::Contains("File too large"));
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);
}

TEST_CASE("landscape jump-friction for point-dipole rows: their coefficients, CP interval and cycle",
          "[apps][landscape]") {
  const auto dir = scratch_directory("landscape-dipolar");
  const auto jump = (dir / "jump.h5").string(), nearest = (dir / "nearest.h5").string();
  REQUIRE(run_cli("landscape jump-friction --range 4 --count 21 -q -o '" + jump + "'", dir).exit_code == 0);
  const auto j = Hdf5Location::open_file(jump);
  CHECK(j.attribute_double("a") == Approx(2.1154969038));  // `couplings --range 4`
  CHECK(j.attribute_double("b") == Approx(2.3926076195));
  CHECK(j.attribute_double("c") == Approx(2.1015765433));
  CHECK(j.attribute_double("A_star") > 12);
  const auto J_cycle = j.read_doubles("J_cycle"), rho = j.read_doubles("rho_cycle");
  REQUIRE(J_cycle.size() == 21);
  for (std::size_t i = 1; i + 1 < J_cycle.size(); ++i) CHECK(J_cycle[i] > 0);
  REQUIRE(run_cli("landscape jump-friction --coefficients 1.5,2,0 --A-min 3 --A-max 10 --count 8 -q -o '" +
                      nearest + "'",
                  dir)
              .exit_code == 0);
  const auto n = Hdf5Location::open_file(nearest);
  CHECK(n.attribute_double("A_star") == Approx(8.778365775883558));
  const auto A = n.read_doubles("A"), J = n.read_doubles("J"), cycle = n.read_doubles("J_cycle");
  REQUIRE(A.size() == 8);
  for (std::size_t i = 0; i < A.size(); ++i) {
    INFO("A = " << A[i]);
    if (std::isnan(J[i]))
      CHECK(cycle[i] == 0);  // outside [A_-, A_*]
    else
      CHECK(cycle[i] == Approx(J[i]).margin(1e-7));
  }
}

TEST_CASE("landscape and table stop on SIGINT and SIGTERM leaving no temporary file or directory",
          "[apps][landscape][files]") {
  const auto dir = scratch_directory("landscape-signal");
  for (const auto& [signal, code] : {std::pair<std::string, int>{"INT", 130}, {"TERM", 143}}) {
    const auto out = dir / "made" / "for" / "it.h5";  // directories the run creates
    const auto run = run_cli_signalled("landscape chambers --A-cells 4000 -q -o '" + out.string() + "'", dir,
                                       signal, "0.5");
    INFO(run.output);
    CHECK(run.exit_code == code);
    CHECK_THAT(run.output, Catch::Contains("stopped by SIG" + signal + ": nothing written"));
    CHECK_FALSE(std::filesystem::exists(dir / "made"));
  }
  // the paper's table takes under a second: signalled at once, it leaves nothing either
  const auto table =
      run_cli_signalled("table --rtol 1e-12 -o '" + (dir / "table.csv").string() + "'", dir, "INT", "0.05");
  CHECK(table.exit_code == 130);
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    CHECK(entry.path().filename() == "cli-output.txt");
}

TEST_CASE("landscape replaces a file that is not HDF5 only with --force", "[apps][landscape]") {
  const auto dir = scratch_directory("landscape-force");
  const auto path = write_text(dir / "notes.h5", "not a result\n");
  const std::string base = "landscape curves --samples 50 -o '" + path.string() + "'";
  const auto refused = run_cli(base, dir);
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.output, Catch::Contains("--force"));
  CHECK(run_cli(base + " --force", dir).exit_code == 0);
  CHECK(rotorsweep::io::is_hdf5_file(path));
}

namespace {

/// One row of table's CSV (A,ic,W,S,R,paper_R,relative_deviation,steps_per_period,paper_W,paper_S,R_error,
/// R_error_kind,W_error,S_error).
struct TableRow {
  double A = 0, W = 0, S = 0, R = 0, paper_R = 0, deviation = 0, steps = 0, paper_W = 0, paper_S = 0,
         error = 0, W_error = 0, S_error = 0;
  std::string ic, kind;
};

/// The provenance lines of a table's CSV ("# ..."), read up to and including the columns' names (`header`).
std::string provenance(std::istream& in, std::string& header) {
  std::string lines, line;
  while (std::getline(in, line) && line.rfind("# ", 0) == 0) lines += line + "\n";
  header = line;
  return lines;
}

TableRow table_row(const std::string& line) {
  TableRow row;
  char ic[8] = {}, kind[24] = {};
  REQUIRE(std::sscanf(line.c_str(), "%lf,%7[^,],%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%23[^,],%lf,%lf", &row.A, ic,
                      &row.W, &row.S, &row.R, &row.paper_R, &row.deviation, &row.steps, &row.paper_W,
                      &row.paper_S, &row.error, kind, &row.W_error, &row.S_error) == 14);
  row.ic = ic;
  row.kind = kind;
  return row;
}

}  // namespace

TEST_CASE("table prints W and S that agree with R outside CP, beside the paper's W, S, R", "[apps][table]") {
  const auto dir = scratch_directory("table-estimators");
  const auto csv = dir / "table.csv";
  // two noise draws for the CP entries (the command's default is 8): each draw's flags are checked the same
  const auto run = run_cli("table --replicas 2 -o '" + csv.string() + "'", dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  std::ifstream in(csv);
  std::string line;
  const std::string made = provenance(in, line);
  CHECK(line ==
        "A,ic,W,S,R,paper_R,relative_deviation,steps_per_period,paper_W,paper_S,R_error,R_error_kind,W_error,"
        "S_error");
  // how it was made: program, stepper, tolerances, window, disorder, what R_error means
  CHECK_THAT(made, Catch::StartsWith("# rotorsweep table: the paper's dissipation integrals") &&
                       Catch::Contains("# written by rotorsweep ") &&
                       Catch::Contains("# stepper rodas4p2, rtol 1e-09 (W and S outside CP at rtol 1e-12), "
                                       "triangular window over periods 3 and 4\n") &&
                       Catch::Contains("# disorder: none\n") && Catch::Contains("# R_error: ") &&
                       Catch::Contains("# W_error, S_error: "));
  // dev/unc only where the error bounds R: not for the symmetry-limited CP entries
  for (const char* entry : {"    6  AFM", "    8   FM"}) {
    const auto at = run.output.find(entry);
    REQUIRE(at != std::string::npos);
    const std::string row = run.output.substr(at, run.output.find('\n', at) - at);
    INFO(row);
    CHECK_THAT(row, Catch::Contains("       - symmetry-limited"));
  }
  int outside_cp = 0;
  while (std::getline(in, line)) {
    INFO(line);
    const TableRow row = table_row(line);
    const double A = row.A, W = row.W, S = row.S, R = row.R, paper_R = row.paper_R, error = row.error;
    const std::string kind = row.kind;
    CHECK(row.paper_W > 0);
    CHECK(row.paper_S > 0);
    CHECK(error > 0);
    if (A == 6 || A == 8) {  // CP: symmetry-limited, the error the shadow run's difference
      CHECK(kind == "symmetry-limited");
      CHECK(error > 1e-6 * R);  // far above the local estimate
      CHECK(row.W_error > 1e-6 * R);  // W and S from R's run: their shadow's difference, finite
      CHECK(row.S_error > 1e-6 * R);
      CHECK(std::isfinite(row.W_error));
      CHECK(std::isfinite(row.S_error));
      continue;
    }
    ++outside_cp;
    CHECK(kind == "resolved");
    CHECK(error < 1e-5 * R);
    CHECK(std::fabs(R / paper_R - 1) < 2 * error / R + 1e-6);  // the paper's 7 digits
    CHECK(std::fabs(W / R - 1) < 1e-6);  // at rtol 1e-9 alone they were off by up to 4.7e-4
    CHECK(std::fabs(S / R - 1) < 1e-6);
    // the tolerance pair's estimate for the rtol 1e-12 run: 2e-3 of its difference from the 1e-9 run (up to 1.5e-6 R)
    CHECK(row.W_error > 0);
    CHECK(row.W_error < 1e-5 * R);
    CHECK(row.S_error > 0);
    CHECK(row.S_error < 1e-5 * R);
  }
  CHECK(outside_cp == 6);
  // each CP entry over noise draws, with its spread and its flags: none resolved, all symmetry-limited
  CHECK_THAT(run.output,
             Catch::Contains("CP entries over 2 noise draws (seed 1") && Catch::Contains("0 / 2 / 0 of 2"));
}

TEST_CASE("table --disorder: the CP entries' errors become bounds, their values the disorder's",
          "[apps][table]") {
  const auto dir = scratch_directory("table-disorder");
  const auto csv = dir / "table.csv";
  const auto run = run_cli(
      "table --disorder 1e-5 --rtol 1e-7 --estimator-rtol 1e-7 --replicas 1 -o '" + csv.string() + "'", dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("disorder sigma_A = 1e-05 (realization 0 of seed 1)"));
  std::ifstream in(csv);
  std::string line;
  CHECK_THAT(provenance(in, line), Catch::Contains("# disorder: sigma_A = 1e-05, seed 1 (realization 0)\n") &&
                                       Catch::Contains("# stepper rodas4p2, rtol 1e-07 (W and S outside CP at "
                                                       "rtol 1e-07), triangular window"));
  std::map<std::string, std::array<double, 3>> cp;  // A and start: R, its error, the paper's R
  while (std::getline(in, line)) {
    INFO(line);
    const TableRow row = table_row(line);
    CHECK(row.kind == "resolved");  // every entry, CP included: the disorder breaks the symmetry
    if (row.A == 6 || row.A == 8) cp[std::to_string(int(row.A)) + row.ic] = {row.R, row.error, row.paper_R};
  }
  REQUIRE(cp.size() == 4);
  for (const char* A : {"6", "8"}) {
    INFO("A = " << A);
    const auto fm = cp[std::string(A) + "FM"], afm = cp[std::string(A) + "AFM"];
    CHECK(std::fabs(fm[0] - afm[0]) <= fm[1] + afm[1]);  // both starts reach the disorder's one orbit
    CHECK(fm[0] < 0.9 * fm[2]);  // 12 % (A = 6) and 38 % (A = 8) below the paper's symmetric value
  }
  // bad values: one message naming the option, exit code 2
  for (const std::string bad :
       {"--disorder 2", "--disorder -1", "--disorder nan", "--disorder-seed -1", "--disorder-seed 1.5"}) {
    const auto refused = run_cli("table " + bad, dir);
    INFO(bad << ": " << refused.output);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.output, Catch::Contains(bad.substr(0, bad.find(' '))));
  }
}

TEST_CASE(
    "table: the paper's triangular window equals the uniform mean outside CP and separates the "
    "estimators in CP",
    "[apps][table]") {
  const auto dir = scratch_directory("table-window");
  // R, and W and S in CP, come from the run at --rtol; W and S outside CP, which this test does not read,
  // from the second run at --estimator-rtol, here the same tolerance instead of 1e-12
  const auto read = [&](const std::string& window) {
    const auto csv = dir / (window + ".csv");
    const auto run = run_cli(
        "table --replicas 1 --estimator-rtol 1e-9 --window " + window + " -o '" + csv.string() + "'", dir);
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    CHECK_THAT(run.output, Catch::Contains(window + " window"));
    std::ifstream in(csv);
    std::string line;
    CHECK_THAT(provenance(in, line), Catch::Contains(window + " window over periods 3 and 4"));
    std::vector<std::array<double, 4>> rows;  // A, W, S, R
    while (std::getline(in, line)) {
      double A = 0, W = 0, S = 0, R = 0;
      char ic[8] = {};
      REQUIRE(std::sscanf(line.c_str(), "%lf,%7[^,],%lf,%lf,%lf", &A, ic, &W, &S, &R) == 5);
      rows.push_back({A, W, S, R});
    }
    return rows;
  };
  const auto triangular = read("triangular"), uniform = read("uniform");
  REQUIRE(triangular.size() == 10);
  REQUIRE(uniform.size() == 10);
  for (std::size_t i = 0; i < triangular.size(); ++i) {
    const auto& t = triangular[i];
    const auto& u = uniform[i];
    INFO("A = " << t[0] << ", entry " << i);
    if (t[0] == 6 || t[0] == 8) {  // CP: no two periods alike
      CHECK(std::fabs(t[3] / u[3] - 1) > 1e-6);
      CHECK(std::fabs(u[1] / u[3] - 1) < 1e-5);  // whole periods: W and R agree
    } else {
      CHECK(std::fabs(t[3] / u[3] - 1) < 1e-9);  // a periodic state: the window does not matter
    }
  }
  // under the paper's window the estimators differ in CP, as the paper's do
  double largest = 0;
  for (const auto& t : triangular)
    if (t[0] == 6 || t[0] == 8) largest = std::max(largest, std::fabs(t[1] / t[3] - 1));
  CHECK(largest > 1e-4);
  CHECK(run_cli("table --window trapezoid", dir).exit_code == 2);
}

TEST_CASE("table refuses a seed outside 0 … 2⁶³ − 1 instead of wrapping or rounding it", "[apps][table]") {
  const auto dir = scratch_directory("table-seed");
  for (const char* bad : {"-1", "18446744073709551616", "9223372036854775808", "1e23", "2.5", "+3", ""}) {
    const auto run = run_cli("table --replicas 2 --seed '" + std::string(bad) + "'", dir);
    INFO(bad << ": " << run.output);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains("--seed"));
  }
}

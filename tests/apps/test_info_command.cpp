// `rotorsweep info`: the summary of a finished file, the warning and exit code 1 for an
// incomplete one (of a slider scan too: its done rows only), and exit code 2 for a file that is not a
// rotorsweep file.
#include <catch2/catch.hpp>

#include "ensemble/rows/member_plan.hpp"
#include "io/result_file.hpp"
#include "io/scene_parser.hpp"
#include "support/cli.hpp"
#include "support/scene_text.hpp"

using namespace rotorsweep::testing;

TEST_CASE("info summarises a finished run", "[apps][info]") {
  const auto dir = scratch_directory("info");
  write_text(dir / "s.toml",
             "[model]\nrows = 4\n[drive]\ng = [0.01]\n[sweep]\nA = [1, 11]\n"
             "[initial]\nkinds = [\"FM\"]\nreplicas = 3\n");
  REQUIRE(run_cli("run '" + (dir / "s.toml").string() + "' -o '" + (dir / "s.h5").string() + "'", dir)
              .exit_code == 0);
  const auto info = run_cli("info '" + (dir / "s.h5").string() + "' --scene", dir);
  INFO(info.output);
  CHECK(info.exit_code == 0);
  CHECK_THAT(info.output, Catch::Contains("members      6"));
  CHECK_THAT(info.output, Catch::Contains("status       ok 6"));
  CHECK_THAT(info.output, Catch::Contains("regime       FM 6"));
  CHECK_THAT(info.output, Catch::Contains("replicas = 3"));
  CHECK_THAT(info.output, !Catch::Contains("INCOMPLETE"));
}

TEST_CASE("info counts symmetry-limited members apart from unresolved ones", "[apps][info]") {
  const auto dir = scratch_directory("info-flags");
  write_text(dir / "s.toml",
             "[model]\nrows = 4\n[drive]\ng = [0.01]\n[sweep]\nA = [1, 6]\n[initial]\nkinds = [\"AFM\"]\n"
             "replicas = 2\n");
  const auto run =
      run_cli("run '" + (dir / "s.toml").string() + "' -o '" + (dir / "s.h5").string() + "'", dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const auto info = run_cli("info '" + (dir / "s.h5").string() + "'", dir);
  INFO(info.output);
  CHECK(info.exit_code == 0);
  // A = 6 is CP: its D is decided by the integration error, which is no bound, but not "not resolved"
  CHECK_THAT(info.output, Catch::Contains("regime       AFM 2 CP 2"));
  CHECK_THAT(info.output, Catch::Contains("warning      2 members whose D an asymmetry below rtol decides"));
  CHECK_THAT(info.output, !Catch::Contains("not resolved"));
  CHECK_THAT(run.output, Catch::Contains("warning: 2 members whose D an asymmetry of the rows below rtol decides") &&
                             !Catch::Contains("not resolved") && !Catch::Contains("tighten"));
}

TEST_CASE("info flags incomplete files and rejects others", "[apps][info]") {
  const auto dir = scratch_directory("info-incomplete");
  const auto scene =
      rotorsweep::io::parse_scene_text("[model]\nrows = 4\n[drive]\ng = [0.01]\n[sweep]\nA = [1]\n", "s");
  {
    rotorsweep::io::ResultFile started((dir / "started.h5").string(), scene,
                                       {"s", "0", "unknown", "cpu", "sse2"});
  }
  const auto info = run_cli("info '" + (dir / "started.h5").string() + "'", dir);
  CHECK(info.exit_code == 1);
  CHECK_THAT(info.output, Catch::Contains("INCOMPLETE"));
  write_text(dir / "text.h5", "not hdf5");
  CHECK(run_cli("info '" + (dir / "text.h5").string() + "'", dir).exit_code == 2);
  // HDF5 files that rotorsweep did not write: empty, or claiming to be complete
  rotorsweep::io::Hdf5Location::create_file((dir / "empty.h5").string()).close();
  {
    auto complete = rotorsweep::io::Hdf5Location::create_file((dir / "complete.h5").string());
    complete.set_flag("complete", true);
    complete.close();
  }
  for (const char* foreign : {"empty.h5", "complete.h5"}) {
    const auto refused = run_cli("info '" + (dir / foreign).string() + "'", dir);
    INFO(refused.output);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.output, Catch::Contains("is not a rotorsweep file"));
  }
}

TEST_CASE("info on a partial file counts its rows marked done, and a slider's shows only them",
          "[apps][info]") {
  using namespace rotorsweep;
  const auto dir = scratch_directory("info-partial");
  // a run killed after writing two batches: members_done says what /members/done marks
  const auto scene =
      io::parse_scene_text("[model]\nrows = 4\n[drive]\ng = [0.01]\n[sweep]\nA = [1, 2, 3, 4]\n", "s");
  const auto rows = (dir / "rows.h5.partial").string();
  {
    io::ResultFile killed(rows, scene, {"s", "0", "unknown", "cpu", "sse2"});
    const ensemble::MemberPlan plan(scene);
    for (const std::size_t index : {0, 2}) {
      std::vector<ensemble::MemberResult> batch(1);
      batch[0].index = index;
      killed.write_results(plan, batch);
    }
  }  // no keep_partial(): the process was killed
  CHECK(io::Hdf5Location::open_file(rows).attribute_double("members_done") == 2);
  const auto rows_info = run_cli("info '" + rows + "'", dir);
  CHECK(rows_info.exit_code == 1);
  CHECK_THAT(rows_info.output, Catch::Contains("2 of 4 members done"));
  // a slider scan's partial file: rows not done hold whatever the disk held (zeros, empty text)
  const auto slider =
      write_text(dir / "slider.toml",
                 "[slider]\ncolumns = 2\nrows = 1\n[substrate]\ncolumns = 5\nrows = 5\n[drive]\n"
                 "rest = 0.1\nend = 2.1\n[sweep]\nseparation = [7e-3, 8e-3, 9e-3]\n");
  const auto scan = (dir / "scan.h5").string();
  REQUIRE(run_cli("slider -q '" + slider.string() + "' -o '" + scan + "'", dir).exit_code == 0);
  {
    const auto file = io::Hdf5Location::open_file_for_writing(scan);
    file.set_flag("complete", false);
    const auto members = file.open_group("members");
    const signed char no = 0;
    const double zero = 0;
    members.write_rows("done", {1}, &no);
    for (const char* column : {"separation", "speed", "damping", "friction"})
      members.write_rows(column, {1}, &zero);
    members.write_rows("status", {1}, std::vector<std::string>{""});
  }
  const auto info = run_cli("info '" + scan + "'", dir);
  INFO(info.output);
  CHECK(info.exit_code == 1);
  CHECK_THAT(info.output, Catch::Contains("2 of 3 members done") &&
                              Catch::Contains("h (mm)       2 values from 7 to 9") &&
                              Catch::Contains("v (mm/s)     8\n") && Catch::Contains("status       ok 2\n"));
  CHECK_THAT(info.output, !Catch::Contains("from 0 N"));
}

TEST_CASE("an empty shard reports no rate, never NaN", "[apps][info]") {
  const auto dir = scratch_directory("info-empty");
  write_text(dir / "two.toml", "[model]\nrows = 4\n[drive]\ng = 0.01\n[sweep]\nA = [1, 2]\n");
  const auto run = run_cli(
      "run '" + (dir / "two.toml").string() + "' --shard 3/3 -q -o '" + (dir / "empty.h5").string() + "'",
      dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("0 members in") && Catch::Contains("no members run"));
  const auto info = run_cli("info '" + (dir / "empty.h5").string() + "'", dir);
  INFO(info.output);
  CHECK_THAT(info.output, Catch::Contains("no members run"));
  for (const auto* text : {&run.output, &info.output}) {
    CHECK(text->find("nan") == std::string::npos);
    CHECK(text->find("inf ") == std::string::npos);
  }
}

TEST_CASE("a file resumed by another instruction set lists both, and info prints them",
          "[apps][info][provenance]") {
  using namespace rotorsweep;
  const auto dir = scratch_directory("writer-isa");
  const auto path = (dir / "out.h5").string();
  const auto scene =
      io::parse_scene_text("[model]\nrows = 2\n[drive]\ng = 0.1\n[sweep]\nA = [1.0]\n", "isa.toml");
  { io::ResultFile created(path, scene, {"isa.toml", "1", "r", "cpu", "avx512"}); }
  for (const char* isa : {"sse2", "avx512", "sse2"}) {  // as `run --resume` does under ROTORSWEEP_ISA
    auto file = io::ResultFile::reopen(path, scene);
    file.add_writer_isa(isa);
    file.close();
  }
  CHECK(io::Hdf5Location::open_file(path).attribute_string("isa") == "avx512, sse2");
  const auto info = run_cli("info '" + path + "'", dir);
  CHECK_THAT(info.output, Catch::Contains("instruction sets avx512, sse2"));
}

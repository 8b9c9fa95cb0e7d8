// `rotorsweep info`: the summary of a finished file, the warning and exit code 1 for an
// incomplete one, and exit code 2 for a file that is not a result file.
#include <catch2/catch.hpp>

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
  CHECK_THAT(info.output, Catch::Contains("warning      2 members whose D the integration error decides"));
  CHECK_THAT(info.output, !Catch::Contains("not resolved"));
  CHECK_THAT(run.output, Catch::Contains("warning: 2 members whose D the integration error decides") &&
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

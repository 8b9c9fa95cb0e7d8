// OutputTarget (io/output_target): refused paths, the temporary file beside the target, the
// rename on commit, and the clean-up (file and created directories) without it.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/hdf5_file.hpp"
#include "io/output_target.hpp"
#include "support/scene_text.hpp"

using namespace rotorsweep::io;
using rotorsweep::testing::scratch_directory;
using rotorsweep::testing::write_text;
namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write_hdf5(const std::string& path, double marker) {
  auto file = Hdf5Location::create_file(path);
  file.set_attribute("marker", marker);
  file.close();
}

}  // namespace

TEST_CASE("output paths that would destroy something are refused", "[io][output]") {
  const auto dir = scratch_directory("output-refused");
  const auto scene = write_text(dir / "scene.toml", "[model]\nrows = 4\n");
  fs::create_symlink(scene, dir / "link.toml");
  write_text(dir / "notes.txt", "my notes\n");
  fs::create_directory(dir / "sub");
  const auto refused = [&](const std::string& path, const std::string& reason) {
    INFO(path);
    CHECK_THROWS_WITH(OutputTarget(path, {scene.string()}, Replaceable::hdf5, false),
                      Catch::Contains(reason));
  };
  refused("", "empty");
  refused((dir / "sub").string(), "is a directory");
  refused((dir / "newdir").string() + "/", "names a directory");
  refused(scene.string(), "is the input file");
  refused((dir / "link.toml").string(), "is the input file");
  refused((dir / "notes.txt").string(), "not an HDF5 file");
  CHECK(read_text(scene) == "[model]\nrows = 4\n");
  CHECK(read_text(dir / "notes.txt") == "my notes\n");
  CHECK_FALSE(fs::exists(dir / "newdir"));
  // --force replaces a file of another kind, never the input
  CHECK_NOTHROW(OutputTarget((dir / "notes.txt").string(), {scene.string()}, Replaceable::hdf5, true));
  CHECK_THROWS(OutputTarget(scene.string(), {scene.string()}, Replaceable::hdf5, true));
  // a text writer replaces only what it wrote itself (its first line) without --force
  CHECK_THROWS_WITH(
      OutputTarget((dir / "notes.txt").string(), {}, Replaceable::text_starting_with("u,b,c"), false),
      Catch::Contains("not a table this command wrote") && Catch::Contains("--force"));
  CHECK_NOTHROW(
      OutputTarget((dir / "notes.txt").string(), {}, Replaceable::text_starting_with("my notes"), false));
  write_hdf5((dir / "result.h5").string(), 1.0);
  CHECK_THROWS(
      OutputTarget((dir / "result.h5").string(), {}, Replaceable::text_starting_with("u,b,c"), false));
  CHECK(Hdf5Location::open_file((dir / "result.h5").string()).attribute_double("marker") == 1.0);
}

TEST_CASE("a NUL byte or a name the temporary file would push past NAME_MAX is refused", "[io][output]") {
  const auto dir = scratch_directory("output-names");
  write_text(dir / "results", "an unrelated file\n");
  // "results\0_new.h5" would open "results", a different file, even with --force
  const std::string with_nul = (dir / "results").string() + std::string(1, '\0') + "_new.h5";
  CHECK_THROWS_WITH(OutputTarget(with_nul, {}, Replaceable::hdf5, true), Catch::Contains("NUL byte"));
  CHECK(read_text(dir / "results") == "an unrelated file\n");
  const std::string longest(241, 'x'), too_long(242, 'x');
  CHECK_NOTHROW(OutputTarget((dir / longest).string(), {}, Replaceable::hdf5, false));
  CHECK_THROWS_WITH(OutputTarget((dir / too_long).string(), {}, Replaceable::hdf5, false),
                    Catch::Contains("242 bytes") && Catch::Contains("at most 241"));
  CHECK_NOTHROW(OutputTarget((dir / longest).string(), {}, Replaceable::hdf5, false, true));  // .partial fits
}

TEST_CASE("the old file stays until commit, and nothing is left without it", "[io][output]") {
  const auto dir = scratch_directory("output-commit");
  const auto path = (dir / "result.h5").string();
  write_hdf5(path, 1.0);
  {
    OutputTarget target(path, {}, Replaceable::hdf5, false);
    CHECK(fs::path(target.temporary()).parent_path() == dir);
    write_hdf5(target.temporary(), 2.0);
    CHECK(Hdf5Location::open_file(path).attribute_double("marker") == 1.0);
    // no commit: a failed run
  }
  CHECK(Hdf5Location::open_file(path).attribute_double("marker") == 1.0);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
  {
    OutputTarget target(path, {}, Replaceable::hdf5, false);
    write_hdf5(target.temporary(), 3.0);
    target.claim_temporary();
    target.commit();
    CHECK(target.replaced());
  }
  CHECK(Hdf5Location::open_file(path).attribute_double("marker") == 3.0);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
}

TEST_CASE("directories created for an output are removed when it fails", "[io][output]") {
  const auto dir = scratch_directory("output-directories");
  const auto path = (dir / "a" / "b" / "out.h5").string();
  {
    OutputTarget target(path, {}, Replaceable::hdf5, false);
    CHECK(fs::is_directory(dir / "a" / "b"));
    write_hdf5(target.temporary(), 1.0);
  }
  CHECK_FALSE(fs::exists(dir / "a"));
  {
    OutputTarget target(path, {}, Replaceable::hdf5, false);
    write_hdf5(target.temporary(), 1.0);
    target.claim_temporary();
    target.commit();
    CHECK_FALSE(target.replaced());
  }
  CHECK(Hdf5Location::open_file(path).attribute_double("marker") == 1.0);
}

TEST_CASE("an output through a symbolic link replaces the link's target", "[io][output]") {
  const auto dir = scratch_directory("output-link");
  const auto real = (dir / "real.h5").string();
  write_hdf5(real, 1.0);
  fs::create_symlink(real, dir / "link.h5");
  OutputTarget target((dir / "link.h5").string(), {}, Replaceable::hdf5, false);
  write_hdf5(target.temporary(), 2.0);
  target.claim_temporary();
  target.commit();
  CHECK(fs::is_symlink(dir / "link.h5"));
  CHECK(Hdf5Location::open_file(real).attribute_double("marker") == 2.0);
  // a dangling link (relative, through a second link) gets its target written, directories included
  fs::create_symlink("sub/new.h5", dir / "dangling.h5");
  fs::create_symlink("dangling.h5", dir / "chain.h5");
  {
    OutputTarget through((dir / "chain.h5").string(), {}, Replaceable::hdf5, false);
    write_hdf5(through.temporary(), 3.0);
    through.claim_temporary();
    through.commit();
  }
  CHECK(fs::is_symlink(dir / "chain.h5"));
  CHECK(fs::is_symlink(dir / "dangling.h5"));
  CHECK(Hdf5Location::open_file((dir / "sub" / "new.h5").string()).attribute_double("marker") == 3.0);
  fs::create_symlink("loop.h5", dir / "loop.h5");
  CHECK_THROWS_WITH(OutputTarget((dir / "loop.h5").string(), {}, Replaceable::hdf5, false),
                    Catch::Contains("too many levels"));
}

TEST_CASE("a link's relative target is taken from the directory that holds the link", "[io][output]") {
  // dl → real/sub, and real/sub/out.h5 → ../x.h5: the link's target is real/x.h5, not ./x.h5
  const auto dir = scratch_directory("output-link-relative");
  fs::create_directories(dir / "real" / "sub");
  fs::create_directory_symlink("real/sub", dir / "dl");
  fs::create_symlink("../x.h5", dir / "real" / "sub" / "out.h5");
  write_hdf5((dir / "x.h5").string(), 7.0);  // an unrelated file where a lexical reading would land
  {
    OutputTarget target((dir / "dl" / "out.h5").string(), {}, Replaceable::hdf5, false);
    write_hdf5(target.temporary(), 8.0);
    target.claim_temporary();
    target.commit();
  }
  CHECK(Hdf5Location::open_file((dir / "real" / "x.h5").string()).attribute_double("marker") == 8.0);
  CHECK(Hdf5Location::open_file((dir / "x.h5").string()).attribute_double("marker") == 7.0);
  CHECK(fs::is_symlink(dir / "real" / "sub" / "out.h5"));
}

TEST_CASE("an output named as a lock file is refused", "[io][output][lock]") {
  const auto dir = scratch_directory("output-lock-name");
  for (const bool resumable : {false, true})
    CHECK_THROWS_WITH(OutputTarget((dir / ".foo.h5.lock").string(), {}, Replaceable::hdf5, true, resumable),
                      Catch::Contains("named as a lock file"));
  // also through a link
  fs::create_symlink(".foo.h5.lock", dir / "link.h5");
  CHECK_THROWS_AS(OutputTarget((dir / "link.h5").string(), {}, Replaceable::hdf5, true), OutputPathError);
  CHECK_FALSE(fs::exists(dir / ".foo.h5.lock"));
  CHECK_NOTHROW(OutputTarget((dir / "foo.h5.lock").string(), {}, Replaceable::hdf5, true));  // not hidden
}

TEST_CASE("temporary files a killed writer left are removed by the output's next writer",
          "[io][output][lock]") {
  const auto dir = scratch_directory("output-stale");
  const std::vector<std::string> stale{".w.h5.123.part", ".w.h5.partial.456.part",
                                       ".w.h5.partial.rank-1.7.part"},
      kept{".w.h5.x1.part", "w.h5.partial", ".w.h5.partial.rank-.7.part", ".v.h5.123.part",
           ".w.h5.lock.1.part"};
  for (const auto& name : stale) write_text(dir / name, "half");
  for (const auto& name : kept) write_text(dir / name, "other");
  {
    const OutputTarget target((dir / "w.h5").string(), {}, Replaceable::hdf5, false, true);
    for (const auto& name : stale) CHECK_FALSE(fs::exists(dir / name));
    for (const auto& name : kept) CHECK(fs::exists(dir / name));
  }
  // a partial file appears whole: created under creating_path, which such a clean-up removes
  CHECK(fs::path(creating_path((dir / "w.h5.partial").string())).filename().string() ==
        ".w.h5.partial." + std::to_string(::getpid()) + ".part");
}

TEST_CASE("HDF5 files are told from others by their signature", "[io][output]") {
  const auto dir = scratch_directory("output-signature");
  write_hdf5((dir / "a.h5").string(), 1.0);
  CHECK(is_hdf5_file(dir / "a.h5"));
  CHECK_FALSE(is_hdf5_file(write_text(dir / "b.h5", "\x89HDF but not really")));
  CHECK_FALSE(is_hdf5_file(write_text(dir / "empty", "")));
  CHECK_FALSE(is_hdf5_file(dir / "absent"));
}

TEST_CASE("a second writer of the same output is refused, naming the first's PID, until it is done",
          "[io][output][lock]") {
  const auto dir = scratch_directory("output-lock");
  const std::string path = (dir / "out.h5").string();
  const auto lock_file = dir / ".out.h5.lock";
  {
    const OutputTarget first(path, {}, Replaceable::hdf5, false, true);
    CHECK(fs::exists(lock_file));
    for (const bool force : {false, true}) {
      try {
        const OutputTarget second(path, {}, Replaceable::hdf5, force, true);
        FAIL("a second target on the same path was allowed");
      } catch (const OutputPathError& e) {
        // the first writer is this very process: said so (another process is the other test's case)
        CHECK_THAT(e.what(), Catch::Contains("being written by another job of this process (PID " +
                                             std::to_string(::getpid()) + ")"));
      }
    }
    // through a link to it, too
    fs::create_symlink(dir / "out.h5", dir / "link.h5");
    CHECK_THROWS_AS(OutputTarget((dir / "link.h5").string(), {}, Replaceable::hdf5, true), OutputPathError);
  }
  CHECK_FALSE(fs::exists(lock_file));  // released and removed with the first target
  // a lock file left by a process that died (SIGKILL) holds no lock: it does not block
  write_text(lock_file, "999999\n");
  const OutputTarget again(path, {}, Replaceable::hdf5, false, true);
  CHECK(fs::exists(lock_file));
}

TEST_CASE("the partial, temporary and lock files of an output belong to it", "[io][output][lock]") {
  CHECK(covering_output("w.h5.partial") == "w.h5");
  CHECK(covering_output("w.h5.partial.rank-3") == "w.h5");
  CHECK(covering_output(".w.h5.4711.part") == "w.h5");
  CHECK(covering_output(".w.h5.lock") == "w.h5");
  CHECK(covering_output(".w.h5.partial.4711.part") == "w.h5.partial");
  for (const char* own : {"w.h5", ".partial", "w.h5.part", ".w.h5.x1.part", ".w.h5..part",
                          "w.h5.partial.rank-", ".lock", "w.lock", ".part"})
    CHECK(covering_output(own).empty());
}

TEST_CASE("a writer of another output's partial, temporary or lock file waits for that output's writer",
          "[io][output][lock]") {
  const auto dir = scratch_directory("output-covered");
  const std::string out = (dir / "w.h5").string();
  const std::string pid = std::to_string(::getpid());
  {
    OutputTarget run(out, {}, Replaceable::hdf5, false, true);  // `run -o w.h5`: writes w.h5.partial
    for (const std::string name :
         {"w.h5.partial", ".w.h5.99.part", "w.h5.partial.rank-1", ".w.h5.partial.99.part"})
      for (const bool resumable : {false, true}) {
        INFO(name);
        CHECK_THROWS_WITH(OutputTarget((dir / name).string(), {}, Replaceable::hdf5, true, resumable),
                          Catch::Contains("belongs to the output") && Catch::Contains("(PID " + pid + ")"));
      }
    // through a link to the partial file, too
    fs::create_symlink(dir / "w.h5.partial", dir / "link.h5");
    CHECK_THROWS(OutputTarget((dir / "link.h5").string(), {}, Replaceable::hdf5, true));
    // the holder is this very process (two jobs of one Python session): said so, not "another process"
    CHECK_THROWS_WITH(OutputTarget(out, {}, Replaceable::hdf5, true, true),
                      Catch::Contains("another job of this process") && !Catch::Contains("another process"));
  }
  // the other way round: while w.h5.partial is written, w.h5's run waits; its locks go with it
  {
    const OutputTarget partial((dir / "w.h5.partial").string(), {}, Replaceable::hdf5, true);
    CHECK(partial.lock_files().size() == 2);
    CHECK_THROWS_WITH(OutputTarget(out, {}, Replaceable::hdf5, true, true), Catch::Contains("being written"));
  }
  CHECK_FALSE(fs::exists(dir / ".w.h5.lock"));
  CHECK_FALSE(fs::exists(dir / ".w.h5.partial.lock"));
  CHECK_NOTHROW(OutputTarget((dir / "w.h5.partial").string(), {}, Replaceable::hdf5, true));
}

TEST_CASE("a writer puts in place only the file it wrote itself", "[io][output]") {
  const auto dir = scratch_directory("output-identity");
  const auto path = (dir / "out.h5").string();
  {
    OutputTarget target(path, {}, Replaceable::hdf5, false, true);
    write_hdf5(target.temporary(), 1.0);
    target.claim_temporary();
    CHECK(target.temporary_is_ours());
    // another file renamed over the partial file (what a writer without the lock would do)
    write_hdf5((dir / "other.h5").string(), 2.0);
    fs::rename(dir / "other.h5", target.temporary());
    CHECK_FALSE(target.temporary_is_ours());
    CHECK_THROWS_WITH(target.commit(), Catch::Contains("no longer the file this process wrote"));
    target.keep();
  }
  CHECK_FALSE(fs::exists(path));
  CHECK(Hdf5Location::open_file(path + ".partial").attribute_double("marker") == 2.0);
}

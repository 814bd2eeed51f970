// Every writer refuses a target that exists and is not a regular file (check_output_target,
// lrchain/output_target.hpp) and leaves it as it was: a FIFO (mkfifo), a directory, a symbolic link
// to /dev/null (never the real /dev/null: a writer that renamed over the link would replace only
// the link). Before, write_file_atomic, the HDF5 writer (Python's to_hdf5, --format hdf5, dark
// HDF5), checkpoints and figures renamed a regular file over whatever was there: run as root,
// to_hdf5('/dev/null') replaced the system's /dev/null.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "../support/run_lrchain.hpp"
#include "../support/scratch_dir.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/output_target.hpp"
#include "lrchain/jobs/checkpoint/checkpoint_file.hpp"
#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/output_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain;

namespace {

fs::path scratch(const std::string& name) { return lrchain::test::scratch_directory("target-" + name); }

// The three kinds of non-regular target made in `dir` under `name` (a FIFO, a directory, a
// symbolic link to /dev/null), each checked by `still_there` after the writer ran.
enum class Kind { fifo, directory, link_to_dev_null };

void make(const fs::path& target, Kind kind) {
  switch (kind) {
    case Kind::fifo: REQUIRE(::mkfifo(target.c_str(), 0600) == 0); break;
    case Kind::directory: fs::create_directory(target); break;
    case Kind::link_to_dev_null: fs::create_symlink("/dev/null", target); break;
  }
}

bool still_there(const fs::path& target, Kind kind) {
  std::error_code ec;
  switch (kind) {
    case Kind::fifo: return fs::symlink_status(target, ec).type() == fs::file_type::fifo;
    case Kind::directory: return fs::symlink_status(target, ec).type() == fs::file_type::directory;
    case Kind::link_to_dev_null:
      return fs::is_symlink(target, ec) && fs::read_symlink(target, ec) == "/dev/null" &&
             fs::status(target, ec).type() == fs::file_type::character;
  }
  return false;
}

// Runs `write` (which writes dir/name) against each kind of target: an InputError naming the
// target, the target unchanged, and no temporary file left in dir.
void check_refuses_every_kind(const std::string& test, const std::string& name,
                              const std::function<void(const fs::path& dir, const std::string& name)>& write) {
  for (Kind kind : {Kind::fifo, Kind::directory, Kind::link_to_dev_null}) {
    CAPTURE(int(kind));
    const fs::path dir = scratch(test);
    const fs::path target = dir / name;
    make(target, kind);
    try {
      write(dir, name);
      FAIL("the writer replaced a non-regular file");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find(target.string()) != std::string::npos);
    }
    CHECK(still_there(target, kind));
    for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename() == name);  // no temporaries
    fs::remove_all(dir);
  }
}

}  // namespace

TEST_CASE("check_output_target: a missing path, a regular file and a dangling link may be written, nothing else") {
  const fs::path dir = scratch("check");
  CHECK_NOTHROW(check_output_target(dir / "missing.csv"));
  std::ofstream(dir / "regular.csv") << "x\n";
  CHECK_NOTHROW(check_output_target(dir / "regular.csv"));
  fs::create_symlink(dir / "nowhere", dir / "dangling");
  CHECK_NOTHROW(check_output_target(dir / "dangling"));
  REQUIRE(::mkfifo((dir / "fifo").c_str(), 0600) == 0);
  CHECK_THROWS_WITH_AS(check_output_target(dir / "fifo"), doctest::Contains("a FIFO"), InputError);
  CHECK_THROWS_WITH_AS(check_output_target(dir), doctest::Contains("a directory"), InputError);
  fs::create_symlink("/dev/null", dir / "null");
  CHECK_THROWS_WITH_AS(check_output_target(dir / "null"), doctest::Contains("a character device"), InputError);
  fs::remove_all(dir);
}

TEST_CASE("write_file_atomic, CSV and space-time writers refuse a FIFO, a directory and a link to /dev/null") {
  check_refuses_every_kind("atomic", "summary.json",
                           [](const fs::path& d, const std::string& n) { jobs::write_file_atomic(d, n, "{}\n"); });
  check_refuses_every_kind("csv", "series.csv", [](const fs::path& d, const std::string& n) {
    sim::TimeSeries ts;
    ts.names = {"t", "x"};
    ts.data = {0, 1};
    jobs::write_csv(d, n, ts);
  });
  check_refuses_every_kind("spacetime", "field.bin", [](const fs::path& d, const std::string& n) {
    sim::SpaceTime f;
    f.sites = 2;
    f.times = {0};
    f.values = {1, 2};
    jobs::write_spacetime_binary(d, n, f);
  });
}

TEST_CASE("figures refuse a FIFO, a directory and a link to /dev/null where their PNG goes") {
  check_refuses_every_kind("figure", "plot.png", [](const fs::path& d, const std::string& n) {
    jobs::Figures figures(d);
    figures.draw_written("none.gp", n);
  });
}

TEST_CASE("the HDF5 writer (to_hdf5, --format hdf5, dark HDF5) refuses a FIFO, a directory and a link to /dev/null") {
  check_refuses_every_kind("hdf5", "result.h5", [](const fs::path& d, const std::string& n) {
    jobs::Hdf5TreeFile file(d / n);
    file.commit();
  });
}

TEST_CASE("checkpoints refuse a FIFO, a directory and a link to /dev/null") {
  check_refuses_every_kind("checkpoint", "c.bin", [](const fs::path& d, const std::string& n) {
    jobs::Checkpoint c;
    c.identity = "run = test\n";
    c.next_step = 0.1;
    c.state = {1, 2};
    jobs::write_checkpoint(d / n, c, sim::RunRecord{});
  });
}

TEST_CASE("CLI: a FIFO in --out where a run writes a file is exit 2 and stays a FIFO, and --checkpoint a FIFO is exit 2 before the run") {
  using namespace lrchain::test;
  const fs::path dir = scratch("cli");
  REQUIRE(::mkfifo((dir / "series.csv").c_str(), 0600) == 0);
  const auto r = run_lrchain(words("simulate bright --branch optical --theta pi/2 --sites 101 --periods 2 --no-figures --out " +
                                   dir.string()));
  CHECK(r.exit_code == 2);
  CHECK(r.err.find((dir / "series.csv").string()) != std::string::npos);
  CHECK(fs::symlink_status(dir / "series.csv").type() == fs::file_type::fifo);

  // A FIFO where a file written after the run goes (summary.json, a snapshot) is refused before the
  // run, with nothing written: before, the run wrote series.csv and the rest, then exited 2.
  for (const std::string name : {"summary.json", "snapshot_t0.csv", "energy_density_spacetime.bin"}) {
    CAPTURE(name);
    const fs::path late = dir / ("late-" + name.substr(0, name.find('.')));
    fs::create_directories(late);
    REQUIRE(::mkfifo((late / name).c_str(), 0600) == 0);
    const auto l = run_lrchain(words("simulate bright --branch optical --theta pi/2 --sites 101 --periods 2 --no-figures --out " +
                                     late.string()));
    CHECK(l.exit_code == 2);
    CHECK(l.err.find((late / name).string()) != std::string::npos);
    CHECK(std::distance(fs::directory_iterator(late), fs::directory_iterator()) == 1);  // only the FIFO
    CHECK(fs::symlink_status(late / name).type() == fs::file_type::fifo);
  }

  const fs::path out = dir / "out";
  const auto c = run_lrchain(words("simulate bright --branch optical --theta pi/2 --sites 101 --periods 2 --checkpoint " +
                                   (dir / "series.csv").string() + " --out " + out.string()));
  CHECK(c.exit_code == 2);
  CHECK(c.err.find("checkpoint") != std::string::npos);
  CHECK(std::count(c.err.begin(), c.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(out));
  CHECK(fs::symlink_status(dir / "series.csv").type() == fs::file_type::fifo);
  fs::remove_all(dir);
}

// Where runs write and what they blame: --checkpoint in a missing directory is exit 2 naming it
// (before, the directory was created); files of an earlier run left in --out are listed in the
// summary as "stale_files" (before, nothing told them apart from this run's); a huge --sites is
// blamed on --sites (before, on --checkpoint-every or --switch-off-time); `regime intervals` on a
// branch with no real frequency is exit 2 (before, exit 0 with no intervals).
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/run_lrchain.hpp"
#include "../support/scratch_dir.hpp"

using namespace lrchain::test;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return lrchain::test::scratch_directory("out-paths-" + name); }

const std::string kSmallBright = "simulate bright --branch optical --theta pi/2 --sites 101 --periods 2 --no-figures ";

}  // namespace

TEST_CASE("--checkpoint in a directory that does not exist is exit 2 naming it, and nothing is created") {
  const fs::path dir = scratch("checkpoint");
  const fs::path missing = dir / "missing" / "deeper";
  const auto r = run_lrchain(words(kSmallBright + "--checkpoint " + (missing / "c.bin").string() + " --out " +
                                   (dir / "out").string()));
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("invalid checkpoint") != std::string::npos);
  CHECK(r.err.find(missing.string() + "' of") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(dir / "missing"));
  CHECK_FALSE(fs::exists(dir / "out"));
  // In an existing directory (and in --out itself) it is written.
  const auto ok = run_lrchain(words(kSmallBright + "--checkpoint " + (dir / "c.bin").string() + " --out " +
                                    (dir / "out").string()));
  CHECK(ok.exit_code == 0);
  CHECK(fs::exists(dir / "c.bin"));
  fs::remove_all(dir);
}

TEST_CASE("files of an earlier run in --out are kept and listed as stale_files in the summary") {
  const fs::path dir = scratch("stale");
  const fs::path out = dir / "out";
  fs::create_directories(out);
  std::ofstream(out / "snapshot_t999.csv") << "n,x\n";
  std::ofstream(out / "notes.txt") << "mine\n";
  const auto r = run_lrchain(words(kSmallBright + "--json --out " + out.string()));
  REQUIRE(r.exit_code == 0);
  const auto printed = nlohmann::json::parse(r.out);
  const std::vector<std::string> expected{"notes.txt", "snapshot_t999.csv"};
  CHECK(printed["stale_files"].get<std::vector<std::string>>() == expected);
  std::ifstream in(out / "summary.json");
  CHECK(nlohmann::json::parse(in)["stale_files"].get<std::vector<std::string>>() == expected);
  CHECK(fs::exists(out / "notes.txt"));
  // A second run into the same --out rewrites its own files: only the foreign ones are stale.
  const auto again = run_lrchain(words(kSmallBright + "--json --out " + out.string()));
  REQUIRE(again.exit_code == 0);
  CHECK(nlohmann::json::parse(again.out)["stale_files"].get<std::vector<std::string>>() == expected);
  fs::remove_all(dir);
}

TEST_CASE("regime map lists the files of an earlier run in --out as stale_files") {
  const fs::path dir = scratch("stale-map");
  std::ofstream(dir / "old_map.csv") << "x\n";
  const auto r = run_lrchain(words("regime map --nx 40 --ny 40 --no-curves --no-figures --out " + dir.string()));
  REQUIRE(r.exit_code == 0);
  CHECK(nlohmann::json::parse(r.out)["stale_files"] == nlohmann::json::array({"old_map.csv"}));
  CHECK(fs::exists(dir / "old_map.csv"));
  fs::remove_all(dir);
}

TEST_CASE("a huge --sites is blamed on --sites, not on --checkpoint-every or --switch-off-time") {
  const auto bright = run_lrchain(words("simulate bright --branch optical --theta pi/2 --sites 2000000001 --periods 200 "
                                        "--checkpoint-every 300 --max-memory 1G"));
  CHECK(bright.exit_code == 2);
  CHECK(bright.err.rfind("lrchain: invalid sites", 0) == 0);
  const auto drive = run_lrchain(words("simulate drive --sites 2000000000 --t-end 100 --switch-off-time 500 --front-fit-start 10 "
                                         "--front-fit-end 90 --max-memory 1G"));
  CHECK(drive.exit_code == 2);
  CHECK(drive.err.rfind("lrchain: invalid sites", 0) == 0);
}

TEST_CASE("regime intervals on a branch with no real frequency is exit 2 saying so") {
  const fs::path dir = scratch("regime");
  // F(r) = k r + b r^3 with k = -1 set on the command line (the file's default k = 1 loads):
  // omega^2 = 4 k sin^2(theta/2) < 0 on all of (0, pi], an unstable chain.
  std::ofstream(dir / "soft.toml") << "name = \"soft\"\ndescription = \"negative stiffness\"\n\n[parameters]\n"
                                      "k = { default = \"1\", description = \"linear stiffness\" }\n"
                                      "b = { default = \"1\", description = \"cubic coefficient\" }\n\n"
                                      "[functions.F]\nargument = \"r\"\nexpression = \"k*r + b*r^3\"\n\n"
                                      "[[field]]\nname = \"u\"\nmass = \"1\"\n"
                                      "force = \"F(u[n+1] - u[n]) - F(u[n] - u[n-1])\"\n";
  const auto r = run_lrchain(words("regime intervals --model " + (dir / "soft.toml").string() + " --set k=-1"));
  CHECK(r.exit_code == 2);
  CAPTURE(r.err);
  CHECK(r.err.find("no real positive frequency") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.out.empty());
  fs::remove_all(dir);
}

// Config keys that the command line had and the configs lacked: the branch spellings of --branch,
// and checkpoint_every of bright and drive runs.
#include <doctest/doctest.h>

#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/more_experiment_config.hpp"

using lrchain::config::Document;

TEST_CASE("config: [bright] branch takes every spelling --branch takes") {
  for (const auto& [spelling, branch] : std::vector<std::pair<std::string, lrchain::Branch>>{
           {"optical", lrchain::Branch::optical}, {"opt", lrchain::Branch::optical}, {"+", lrchain::Branch::optical},
           {"acoustic", lrchain::Branch::acoustic}, {"acs", lrchain::Branch::acoustic}, {"-", lrchain::Branch::acoustic}}) {
    CAPTURE(spelling);
    // Focusing carriers of each branch (Secs. 4.2-4.3): optical 1.2, acoustic 1.948 (exp4).
    const std::string theta = branch == lrchain::Branch::optical ? "1.2" : "1.948";
    const auto doc = Document::from_text(
        "experiment = \"bright\"\n[bright]\ntheta = " + theta + "\nbranch = \"" + spelling + "\"\n", "b.toml");
    CHECK(lrchain::jobs::load_experiment_config(doc).bright.branch == branch);
    CHECK(lrchain::parse_branch(spelling) == branch);
  }
  const auto bad = Document::from_text("experiment = \"bright\"\n[bright]\ntheta = 1.2\nbranch = \"optic\"\n", "b.toml");
  CHECK_THROWS_WITH_AS(lrchain::jobs::load_experiment_config(bad), doctest::Contains("b.toml:4"),
                       lrchain::config::ConfigError);
}

TEST_CASE("config: bright and drive runs take checkpoint_every, checked like the command line's") {
  const auto b = Document::from_text("experiment = \"bright\"\n[bright]\ntheta = 1.2\ncheckpoint_every = 0.5\n", "b.toml");
  CHECK(lrchain::jobs::load_experiment_config(b).bright.checkpoint_every == 0.5);
  const auto d = Document::from_text("experiment = \"drive\"\n[drive]\ncheckpoint_every = 100\n", "d.toml");
  CHECK(lrchain::jobs::load_drive_config(d).run.checkpoint_every == 100);
  const auto negative = Document::from_text("experiment = \"drive\"\n[drive]\ncheckpoint_every = -1\n", "d.toml");
  CHECK_THROWS_WITH_AS(lrchain::jobs::load_drive_config(negative), doctest::Contains("checkpoint_every"),
                       lrchain::config::ConfigError);
  // Below sample_every (1 by default): the cross-key check of validate(DriveRunConfig), located.
  const auto dense = Document::from_text("experiment = \"drive\"\n[drive]\ncheckpoint_every = 0.5\n", "d.toml");
  CHECK_THROWS_WITH_AS(lrchain::jobs::load_drive_config(dense),
                       doctest::Contains("'checkpoint_every' in [drive] at d.toml:3: must be 0 (none) or"),
                       lrchain::config::ConfigError);
}

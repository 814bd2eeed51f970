#pragma once
// The files a sweep writes next to its results file (the CSV views, the figures' data, scripts and
// images) never replace a file of the user's: a manifest beside the results,
// `.<results file name>.lrchain-files`, lists each file the sweep wrote with the SHA-256 of what it
// wrote ("pending" while it is being written). Before any point runs, a side file that exists and
// is not listed with its current content is refused (InputError, exit 2, naming it).
#include <filesystem>
#include <string>
#include <vector>

#include "lrchain/jobs/sweep/job.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"

namespace lrchain::jobs::sweep {

// The directory of the results file ("." for a bare name).
std::filesystem::path output_directory(const SweepConfig& c);
// The manifest's path.
std::filesystem::path side_files_manifest(const SweepConfig& c);
// Names (in output_directory) of the CSV views this sweep writes: output with .csv, and for jobs
// with rows .rows.csv; none above csv_max_points.
std::vector<std::string> csv_view_files(const SweepConfig& c, const Job& job);
// Every side file of the sweep: the CSV views and the figure's files.
std::vector<std::string> sweep_side_files(const SweepConfig& c, const Job& job);

// Refuses the first side file that exists and was not written by this sweep (or was changed
// since), and a manifest that is not one.
void check_side_files(const SweepConfig& c, const Job& job);
// Records `names` as being written (before writing them) ...
void mark_side_files_pending(const SweepConfig& c, const std::vector<std::string>& names);
// ... and then the SHA-256 of each that exists (after writing them).
void record_side_files(const SweepConfig& c, const std::vector<std::string>& names);

}  // namespace lrchain::jobs::sweep

#pragma once
// Writing run results into an output directory: every file goes to a temporary name first and is
// renamed into place, so an interrupted run never leaves a truncated file. Figures are a gnuplot
// script (.gp) next to its data files, rendered to PNG when gnuplot is installed.
#include <filesystem>
#include <string>
#include <vector>

#include "lrchain/sim/run_record.hpp"

namespace lrchain::sim {

// Creates dir (and parents); throws std::runtime_error naming it if that fails.
void ensure_directory(const std::filesystem::path& dir);
// Writes `content` to dir/name via a temporary file + rename.
void write_file_atomic(const std::filesystem::path& dir, const std::string& name,
                       const std::string& content);
// CSV with a header row (full double precision).
void write_csv(const std::filesystem::path& dir, const std::string& name, const TimeSeries& ts);
void write_snapshot_csv(const std::filesystem::path& dir, const std::string& name,
                        const Snapshot& s);
// Space-time field as gnuplot "binary matrix" (float32: [sites, n...], then [t, values...] rows).
void write_spacetime_binary(const std::filesystem::path& dir, const std::string& name,
                            const SpaceTime& f);
// Writes all series/fields/snapshots with standard names: series.csv, <quantity>_spacetime.bin,
// snapshot_<tag>.csv.
void write_record(const std::filesystem::path& dir, const RunRecord& r);
// Writes the gnuplot script dir/script (atomically) and renders it to dir/png: gnuplot runs inside
// dir with `outfile` set to a temporary name that is renamed to png on success. The script must
// start with `if (!exists("outfile")) outfile = '<png>'` and `set output outfile`.
// Returns false if gnuplot is missing or fails (the script and data stay for the user).
bool render_gnuplot(const std::filesystem::path& dir, const std::string& script,
                    const std::string& script_text, const std::string& png);

// One figure: gnuplot script name, its text, the PNG it renders (see render_gnuplot).
struct FigureScript {
  std::string script;
  std::string script_text;
  std::string png;
};
// The output directory of a run: the record (write_record), summary.json (`summary_json` + newline)
// and the figures, rendered concurrently (one gnuplot process each). Returns the PNGs rendered, in
// the order given.
std::vector<std::string> write_run_outputs(const std::filesystem::path& dir, const RunRecord& record,
                                           const std::string& summary_json,
                                           const std::vector<FigureScript>& figures);

}  // namespace lrchain::sim

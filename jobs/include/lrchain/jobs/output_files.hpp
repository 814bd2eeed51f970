#pragma once
// Writing run results into an output directory: every file goes to a temporary name first and is
// renamed into place, so an interrupted run never leaves a truncated file. Figures are a gnuplot
// script (.gp) next to its data files, drawn to PNG when gnuplot is installed.
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "lrchain/sim/run_record.hpp"

namespace lrchain::jobs {

// Creates dir (and parents); throws std::runtime_error naming it if that fails.
void ensure_directory(const std::filesystem::path& dir);
// A temporary name next to `file`, unique to this process: "<dir>/.<name>.tmp.<pid>".
std::filesystem::path temporary_name(const std::filesystem::path& file);
// Writes `content` to dir/name via a temporary file + rename. Every writer first asks
// lrchain::check_output_target (lrchain/output_target.hpp) whether it may replace its target: a
// directory, device, FIFO or socket there is refused with InputError naming it.
void write_file_atomic(const std::filesystem::path& dir, const std::string& name,
                       const std::string& content);
// CSV with a header row (full double precision).
void write_csv(const std::filesystem::path& dir, const std::string& name, const sim::TimeSeries& ts);
void write_snapshot_csv(const std::filesystem::path& dir, const std::string& name,
                        const sim::Snapshot& s);
// Space-time field as gnuplot "binary matrix" (float32: [sites, n...], then [t, values...] rows).
void write_spacetime_binary(const std::filesystem::path& dir, const std::string& name,
                            const sim::SpaceTime& f);
// Writes all series/fields/snapshots with standard names: series.csv, <quantity>_spacetime.bin,
// snapshot_<tag>.csv.
void write_record(const std::filesystem::path& dir, const sim::RunRecord& r);

// One figure: gnuplot script name, its text, the PNG it draws (the file of another format when
// set_figure_format, lrchain/jobs/figure_format.hpp, chose one). The script starts with
// `if (!exists("outfile")) outfile = '<png>'` and `set output outfile`, so that gnuplot can be
// told a temporary output name and a user can re-run the script as it is.
struct FigureScript {
  std::string script;
  std::string script_text;
  std::string png;
};

// The figures of one job in one directory. gnuplot is run with an argument vector (never a shell)
// inside dir and draws to a temporary name that is renamed to the PNG; its messages are captured,
// never left in files. A figure gnuplot cannot draw (not installed, or an error in the script) is
// skipped: its script and data stay for the user. finish() lists both kinds in the job's JSON and
// prints one warning line naming the skipped figures. draw and draw_all may be called from
// several threads.
class Figures {
 public:
  explicit Figures(std::filesystem::path dir);
  // Writes dir/<script> (atomically), then draws it; false if the figure was skipped.
  bool draw(const FigureScript& figure);
  // Draws dir/<script>, which the caller has written; false if skipped.
  bool draw_written(const std::string& script, const std::string& png);
  // Writes every script, draws them concurrently (one gnuplot each); results in the order given.
  void draw_all(const std::vector<FigureScript>& figures);
  std::vector<std::string> drawn() const;    // PNG names, in the order drawn
  std::vector<std::string> skipped() const;  // PNG names not drawn
  // j["figures"] = drawn(), j["figures_skipped"] = skipped(); prints warning() on stderr once if
  // a figure was skipped.
  void finish(nlohmann::json& j);
  // The warning line (no newline), or "" when every figure was drawn.
  std::string warning() const;

 private:
  struct Outcome {
    std::string png;
    bool drawn = false;
    std::string failure;  // why not drawn
  };
  Outcome render(const std::string& script, const std::string& png) const;
  void record(Outcome outcome);

  std::filesystem::path dir_;
  bool gnuplot_found_;
  mutable std::mutex mutex_;
  std::vector<Outcome> outcomes_;
  bool warned_ = false;
};

// The output directory of a run: the record (write_record), the figures (Figures::draw_all) and
// summary.json (`summary_json`, a JSON object, with "figures" and "figures_skipped" added).
// Without draw_figures (--no-figures) neither scripts nor PNGs are written. Returns the PNGs
// drawn, in the order given.
std::vector<std::string> write_run_outputs(const std::filesystem::path& dir, const sim::RunRecord& record,
                                           const std::string& summary_json,
                                           const std::vector<FigureScript>& figures, bool draw_figures = true);

// The regular files of an output directory before a run writes into it (name and file identity,
// device and inode), to tell afterwards which ones the run did not write.
struct OutputListing {
  struct Entry {
    std::string name;
    unsigned long long device = 0, inode = 0;
  };
  std::vector<Entry> files;
};
// The visible regular files of `dir` now (names starting with '.' are lrchain's own lock and
// temporaries); empty when dir does not exist. Throws InputError (check_output_target) for an
// entry with an output file's extension (.csv, .json, .bin, .h5, .png, .svg, .pdf, .gp, .dat) that
// is not a regular file: runs call it before they write anything.
OutputListing list_output_files(const std::filesystem::path& dir);
// The names in `before` that are still the same file in `dir` (a file the run wrote is a new one:
// every writer renames a new file into place), except those in `keep`; sorted.
std::vector<std::string> files_not_rewritten(const std::filesystem::path& dir, const OutputListing& before,
                                             const std::vector<std::string>& keep = {});
// Stale files of an earlier run: lrchain never deletes them (they may be the user's), it lists
// them as summary["stale_files"] (files_not_rewritten) in `summary` and in dir/summary.json when
// the run wrote one.
void record_stale_files(const std::filesystem::path& dir, const OutputListing& before, nlohmann::json& summary,
                        const std::vector<std::string>& keep = {});

}  // namespace lrchain::jobs

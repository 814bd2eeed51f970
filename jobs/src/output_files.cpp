// Atomic output files (temp name + rename), CSV, gnuplot binary matrices, figures drawn by gnuplot.
#include "lrchain/jobs/output_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>

#include <atomic>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <future>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "lrchain/errors.hpp"
#include "lrchain/output_target.hpp"
#include "lrchain/jobs/figure_format.hpp"
#include "lrchain/process.hpp"

namespace lrchain::jobs {

namespace fs = std::filesystem;

void ensure_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw std::runtime_error("cannot create output directory '" + dir.string() + "': " + ec.message());
}

fs::path temporary_name(const fs::path& file) {
  std::string name(1, '.');
  name += file.filename().string();
  name += ".tmp.";
  name += std::to_string(::getpid());
  return file.parent_path() / name;
}

namespace {
fs::path temp_name(const fs::path& dir, const std::string& name) {
  return dir / ("." + name + ".tmp." + std::to_string(::getpid()));
}
// Renames tmp to dir/name, unless dir/name is not a regular file (check_output_target).
void commit(const fs::path& tmp, const fs::path& dir, const std::string& name) {
  std::error_code ec;
  try {
    check_output_target(dir / name);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::rename(tmp, dir / name, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error("cannot write '" + (dir / name).string() + "'");
  }
}
}  // namespace

void write_file_atomic(const fs::path& dir, const std::string& name, const std::string& content) {
  check_output_target(dir / name);
  const fs::path tmp = temp_name(dir, name);
  {
    std::ofstream f(tmp, std::ios::binary);
    f << content;
    if (!f) throw std::runtime_error("cannot write '" + tmp.string() + "'");
  }
  commit(tmp, dir, name);
}

namespace {
std::string csv_text(const std::vector<std::string>& names, const std::vector<double>& data) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? "," : "") + names[i];
  out += '\n';
  char buf[32];
  const std::size_t cols = names.size();
  for (std::size_t k = 0; k < data.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%.17g", data[k]);
    out += buf;
    out += (k % cols + 1 == cols) ? '\n' : ',';
  }
  return out;
}
}  // namespace

void write_csv(const fs::path& dir, const std::string& name, const sim::TimeSeries& ts) {
  write_file_atomic(dir, name, csv_text(ts.names, ts.data));
}

void write_snapshot_csv(const fs::path& dir, const std::string& name, const sim::Snapshot& s) {
  write_file_atomic(dir, name, csv_text(s.names, s.data));
}

void write_spacetime_binary(const fs::path& dir, const std::string& name, const sim::SpaceTime& f) {
  check_output_target(dir / name);
  const fs::path tmp = temp_name(dir, name);
  {
    std::ofstream out(tmp, std::ios::binary);
    std::vector<float> row(f.sites + 1);
    row[0] = static_cast<float>(f.sites);
    for (Index i = 0; i < f.sites; ++i) row[static_cast<std::size_t>(i) + 1] = static_cast<float>(f.first_label + i);
    out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
    const std::size_t rows = f.sites ? f.values.size() / f.sites : 0;
    for (std::size_t k = 0; k < rows; ++k) {
      row[0] = static_cast<float>(f.times[k]);
      std::copy(f.values.begin() + long(k * f.sites), f.values.begin() + long((k + 1) * f.sites),
                row.begin() + 1);
      out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
    }
    if (!out) throw std::runtime_error("cannot write '" + tmp.string() + "'");
  }
  commit(tmp, dir, name);
}

void write_record(const fs::path& dir, const sim::RunRecord& r) {
  ensure_directory(dir);
  if (!r.series.names.empty()) write_csv(dir, "series.csv", r.series);
  for (const auto& f : r.fields) write_spacetime_binary(dir, f.quantity + "_spacetime.bin", f);
  for (const auto& s : r.snapshots) write_snapshot_csv(dir, "snapshot_" + s.tag + ".csv", s);
}

namespace {
std::atomic<FigureFormat> current_format{FigureFormat::png};

const char* extension(FigureFormat f) { return f == FigureFormat::svg ? ".svg" : f == FigureFormat::pdf ? ".pdf" : ".png"; }

// `set terminal pngcairo size W,H<rest>` for the current format (the line without its newline).
std::string terminal_line(const std::string& line) {
  const std::string head = "set terminal pngcairo size ";
  if (line.rfind(head, 0) != 0) return line;
  const char* p = line.data() + head.size();
  const char* end = line.data() + line.size();
  int width = 0, height = 0;
  auto [after_w, ew] = std::from_chars(p, end, width);
  if (ew != std::errc() || after_w == end || *after_w != ',') return line;
  auto [after_h, eh] = std::from_chars(after_w + 1, end, height);
  if (eh != std::errc()) return line;
  const std::string rest(after_h, end);
  switch (current_format.load()) {
    case FigureFormat::svg:
      return fmt::format("set terminal svg size {},{} dynamic background rgb 'white'{}", width, height, rest);
    case FigureFormat::pdf:
      return fmt::format("set terminal pdfcairo size {:.3f}in,{:.3f}in{}", width / 72.0, height / 72.0, rest);
    case FigureFormat::png: break;
  }
  return line;
}
}  // namespace

FigureFormat parse_figure_format(const std::string& text) {
  if (text == "png") return FigureFormat::png;
  if (text == "svg") return FigureFormat::svg;
  if (text == "pdf") return FigureFormat::pdf;
  throw InvalidParameter("figure-format", "must be png, svg or pdf, got '" + text + "'");
}

void set_figure_format(FigureFormat format) { current_format = format; }

FigureFormat figure_format() { return current_format.load(); }

std::string figure_format_name() { return std::string(extension(current_format.load()) + 1); }

std::string figure_file_name(const std::string& png_name) {
  const std::string png = ".png";
  if (png_name.size() < png.size() || png_name.compare(png_name.size() - png.size(), png.size(), png) != 0)
    return png_name;
  return png_name.substr(0, png_name.size() - png.size()) + extension(current_format.load());
}

std::string script_for_format(const std::string& script_text) {
  if (current_format.load() == FigureFormat::png) return script_text;
  std::string out;
  std::istringstream in(script_text);
  for (std::string line; std::getline(in, line);) {
    if (line.find("outfile = '") != std::string::npos) {
      const auto dot = line.rfind(".png'");
      if (dot != std::string::npos) line.replace(dot, 4, extension(current_format.load()));
    }
    out += terminal_line(line);
    out += '\n';
  }
  return out;
}

Figures::Figures(fs::path dir) : dir_(std::move(dir)), gnuplot_found_(program_in_path("gnuplot")) {}

namespace {
// The last non-empty line of gnuplot's messages (its error), trimmed.
std::string last_line(const std::string& text) {
  std::string line, last;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    const auto a = line.find_first_not_of(" \t\r"), b = line.find_last_not_of(" \t\r");
    if (a != std::string::npos) last = line.substr(a, b - a + 1);
  }
  return last;
}
}  // namespace

// The script as gnuplot's file argument: "./name", since gnuplot runs an argument that starts with
// '<' as a shell command and reads '-' as standard input.
namespace {
std::string script_argument(const std::string& script) {
  return fs::path(script).is_absolute() ? script : "./" + script;
}
}  // namespace

// Runs `gnuplot -e "outfile='<tmp>'" <script>` inside dir_ (argv, no shell), then renames tmp to png.
Figures::Outcome Figures::render(const std::string& script, const std::string& png) const {
  Outcome o{png, false, {}};
  check_output_target(dir_ / png);  // (refused even where gnuplot would not draw it)
  if (!gnuplot_found_) {
    o.failure = "gnuplot is not installed";
    return o;
  }
  // Names come from the program, never from the user; a quote would end gnuplot's string.
  if (png.find_first_of("'\\/\n") != std::string::npos)
    throw std::logic_error("figure name '" + png + "' is not a plain file name");
  const fs::path tmp = temp_name(dir_, png);
  ProcessOptions options;
  options.working_directory = dir_;
  options.capture_stdout = true;
  options.capture_stderr = true;
  std::error_code ec;
  try {
    const ProcessResult r =
        run_program({"gnuplot", "-e", "outfile='" + tmp.filename().string() + "'", script_argument(script)}, options);
    if (!r.ok()) {
      const std::string why = last_line(r.error_output);
      o.failure = r.exited ? "gnuplot failed on " + script + (why.empty() ? "" : ": " + why)
                           : "gnuplot was killed by signal " + std::to_string(r.signal_number);
    } else if (!fs::is_regular_file(tmp, ec) || fs::file_size(tmp, ec) == 0) {
      o.failure = "gnuplot drew nothing from " + script;
    }
  } catch (const std::exception& e) {
    o.failure = e.what();
  }
  if (!o.failure.empty()) {
    fs::remove(tmp, ec);
    return o;
  }
  commit(tmp, dir_, png);
  o.drawn = true;
  return o;
}

void Figures::record(Outcome outcome) {
  std::lock_guard<std::mutex> lock(mutex_);
  outcomes_.push_back(std::move(outcome));
}

bool Figures::draw(const FigureScript& figure) {
  write_file_atomic(dir_, figure.script, script_for_format(figure.script_text));
  Outcome o = render(figure.script, figure_file_name(figure.png));
  const bool drawn = o.drawn;
  record(std::move(o));
  return drawn;
}

namespace {
// Rewrites dir/script for the current figure format (nothing to do for png).
void convert_script(const fs::path& dir, const std::string& script) {
  if (figure_format() == FigureFormat::png) return;
  std::ifstream in(dir / script);
  std::stringstream text;
  text << in.rdbuf();
  write_file_atomic(dir, script, script_for_format(text.str()));
}
}  // namespace

bool Figures::draw_written(const std::string& script, const std::string& png) {
  convert_script(dir_, script);
  Outcome o = render(script, figure_file_name(png));
  const bool drawn = o.drawn;
  record(std::move(o));
  return drawn;
}

void Figures::draw_all(const std::vector<FigureScript>& figures) {
  for (const auto& f : figures) write_file_atomic(dir_, f.script, script_for_format(f.script_text));
  std::vector<std::future<Outcome>> pending;
  for (const auto& f : figures)
    pending.push_back(
        std::async(std::launch::async, [this, &f] { return render(f.script, figure_file_name(f.png)); }));
  for (auto& p : pending) record(p.get());
}

std::vector<std::string> Figures::drawn() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> out;
  for (const auto& o : outcomes_)
    if (o.drawn) out.push_back(o.png);
  return out;
}

std::vector<std::string> Figures::skipped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> out;
  for (const auto& o : outcomes_)
    if (!o.drawn) out.push_back(o.png);
  return out;
}

std::string Figures::warning() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string names;
  for (const auto& o : outcomes_) {
    if (o.drawn) continue;
    names += (names.empty() ? "" : ", ") + o.png;
    if (gnuplot_found_) names += " (" + o.failure + ")";
  }
  if (names.empty()) return "";
  const std::string where = "their .gp scripts and data are in '" + dir_.string() + "'";
  if (!gnuplot_found_)
    return "lrchain: warning: figures not drawn because gnuplot is not installed (Debian package "
           "gnuplot-nox): " + names + "; " + where;
  return "lrchain: warning: figures not drawn: " + names + "; " + where;
}

void Figures::finish(nlohmann::json& j) {
  j["figures"] = drawn();
  j["figures_skipped"] = skipped();
  const std::string line = warning();
  std::lock_guard<std::mutex> lock(mutex_);
  // A run that blew up ends with its one failure line (exit 3); gnuplot failing on its non-finite
  // data is expected then, and figures_skipped in the summary lists what was not drawn.
  const bool blew_up = j.is_object() && j.value("blew_up", false);
  if (!line.empty() && !warned_ && !blew_up) std::fprintf(stderr, "%s\n", line.c_str());
  warned_ = true;
}

std::vector<std::string> write_run_outputs(const fs::path& dir, const sim::RunRecord& record,
                                           const std::string& summary_json,
                                           const std::vector<FigureScript>& figures, bool draw_figures) {
  ensure_directory(dir);
  write_record(dir, record);
  Figures drawing(dir);
  if (draw_figures) drawing.draw_all(figures);
  nlohmann::json summary = nlohmann::json::parse(summary_json);
  drawing.finish(summary);
  write_file_atomic(dir, "summary.json", summary.dump(2) + "\n");
  return drawing.drawn();
}

namespace {
// Device and inode of a path (not following a final symbolic link); false if it cannot be read.
bool identity_of(const fs::path& file, OutputListing::Entry& e) {
  struct stat st {};
  if (::lstat(file.c_str(), &st) != 0) return false;
  e.device = static_cast<unsigned long long>(st.st_dev);
  e.inode = static_cast<unsigned long long>(st.st_ino);
  return true;
}
}  // namespace

namespace {
// A name with an extension lrchain writes into an output directory.
bool output_file_name(const std::string& name) {
  static const char* const extensions[] = {".csv", ".json", ".bin", ".h5", ".png", ".svg", ".pdf", ".gp", ".dat"};
  const std::string extension = fs::path(name).extension().string();
  return std::find(std::begin(extensions), std::end(extensions), extension) != std::end(extensions);
}
}  // namespace

OutputListing list_output_files(const fs::path& dir) {
  OutputListing listing;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    OutputListing::Entry e;
    e.name = it->path().filename().string();
    if (e.name.empty() || e.name[0] == '.') continue;
    if (!it->is_regular_file(ec)) {
      // A FIFO, device or directory with the name of an output file is refused before the run
      // writes anything, not when its turn comes after the run.
      if (output_file_name(e.name)) check_output_target(it->path());
      continue;
    }
    if (identity_of(it->path(), e)) listing.files.push_back(std::move(e));
  }
  return listing;
}

std::vector<std::string> files_not_rewritten(const fs::path& dir, const OutputListing& before,
                                             const std::vector<std::string>& keep) {
  std::vector<std::string> stale;
  for (const auto& old : before.files) {
    if (std::find(keep.begin(), keep.end(), old.name) != keep.end()) continue;
    OutputListing::Entry now;
    if (identity_of(dir / old.name, now) && now.device == old.device && now.inode == old.inode)
      stale.push_back(old.name);
  }
  std::sort(stale.begin(), stale.end());
  return stale;
}

void record_stale_files(const fs::path& dir, const OutputListing& before, nlohmann::json& summary,
                        const std::vector<std::string>& keep) {
  summary["stale_files"] = files_not_rewritten(dir, before, keep);
  std::error_code ec;
  if (!fs::is_regular_file(dir / "summary.json", ec)) return;
  std::ifstream in(dir / "summary.json");
  nlohmann::json written = nlohmann::json::parse(in, nullptr, false);
  if (!written.is_object()) return;
  written["stale_files"] = summary["stale_files"];
  write_file_atomic(dir, "summary.json", written.dump(2) + "\n");
}

}  // namespace lrchain::jobs

// Atomic output files (temp name + rename), CSV, gnuplot binary matrices, gnuplot rendering.
#include "lrchain/sim/output_files.hpp"

#include <future>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lrchain::sim {

namespace fs = std::filesystem;

void ensure_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw std::runtime_error("cannot create output directory '" + dir.string() + "': " + ec.message());
}

namespace {
fs::path temp_name(const fs::path& dir, const std::string& name) {
  return dir / ("." + name + ".tmp." + std::to_string(::getpid()));
}
void commit(const fs::path& tmp, const fs::path& dir, const std::string& name) {
  std::error_code ec;
  fs::rename(tmp, dir / name, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw std::runtime_error("cannot write '" + (dir / name).string() + "'");
  }
}
}  // namespace

void write_file_atomic(const fs::path& dir, const std::string& name, const std::string& content) {
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

void write_csv(const fs::path& dir, const std::string& name, const TimeSeries& ts) {
  write_file_atomic(dir, name, csv_text(ts.names, ts.data));
}

void write_snapshot_csv(const fs::path& dir, const std::string& name, const Snapshot& s) {
  write_file_atomic(dir, name, csv_text(s.names, s.data));
}

void write_spacetime_binary(const fs::path& dir, const std::string& name, const SpaceTime& f) {
  const fs::path tmp = temp_name(dir, name);
  {
    std::ofstream out(tmp, std::ios::binary);
    std::vector<float> row(f.sites + 1);
    row[0] = static_cast<float>(f.sites);
    for (std::size_t i = 0; i < f.sites; ++i) row[i + 1] = static_cast<float>(f.first_label + long(i));
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

void write_record(const fs::path& dir, const RunRecord& r) {
  ensure_directory(dir);
  if (!r.series.names.empty()) write_csv(dir, "series.csv", r.series);
  for (const auto& f : r.fields) write_spacetime_binary(dir, f.quantity + "_spacetime.bin", f);
  for (const auto& s : r.snapshots) write_snapshot_csv(dir, "snapshot_" + s.tag + ".csv", s);
}

bool render_gnuplot(const fs::path& dir, const std::string& script, const std::string& script_text,
                    const std::string& png) {
  write_file_atomic(dir, script, script_text);
  static const bool have_gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  if (!have_gnuplot) return false;
  const std::string tmp = "." + png + ".tmp." + std::to_string(::getpid());
  const std::string cmd = "cd '" + dir.string() + "' && gnuplot -e \"outfile='" + tmp + "'\" '" +
                          script + "' >'." + script + ".log' 2>&1";
  if (std::system(cmd.c_str()) != 0) {
    std::error_code ec;
    fs::remove(dir / tmp, ec);
    return false;
  }
  fs::remove(dir / ("." + script + ".log"));
  commit(dir / tmp, dir, png);
  return true;
}

std::vector<std::string> write_run_outputs(const fs::path& dir, const RunRecord& record,
                                           const std::string& summary_json,
                                           const std::vector<FigureScript>& figures) {
  ensure_directory(dir);
  write_record(dir, record);
  write_file_atomic(dir, "summary.json", summary_json + "\n");
  std::vector<std::future<bool>> rendered;
  for (const auto& f : figures)
    rendered.push_back(std::async(std::launch::async, [&dir, &f] {
      return render_gnuplot(dir, f.script, f.script_text, f.png);
    }));
  std::vector<std::string> pngs;
  for (std::size_t i = 0; i < figures.size(); ++i)
    if (rendered[i].get()) pngs.push_back(figures[i].png);
  return pngs;
}

}  // namespace lrchain::sim

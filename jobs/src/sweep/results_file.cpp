// The sweep's results file through the HDF5 C API, and its CSV view (sweep/results_file.hpp).
#include "lrchain/jobs/sweep/results_file.hpp"

#include "lrchain/output_target.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <hdf5.h>

#include "lrchain/errors.hpp"
#include "lrchain/provenance.hpp"
#include "point_checksum.hpp"

namespace lrchain::jobs::sweep {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

// An HDF5 identifier closed by `close` when it goes out of scope.
struct Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  Handle(hid_t i, herr_t (*c)(hid_t), const std::string& what) : id(i), close(c) {
    if (id < 0) throw std::runtime_error("HDF5: cannot " + what);
  }
  ~Handle() { close(id); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id; }
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: cannot " + what);
}

// Silences HDF5's own error printing: every failure is reported through an exception instead.
void quiet_hdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

Handle utf8_string_type() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose, "make a string type");
  check(H5Tset_size(t, H5T_VARIABLE), "size a string type");
  check(H5Tset_cset(t, H5T_CSET_UTF8), "set a string type's character set");
  return Handle(H5Tcopy(t), H5Tclose, "copy a string type");
}

void write_attribute(hid_t where, const std::string& name, const std::string& value) {
  const Handle type = utf8_string_type();
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "make a scalar space");
  const Handle a(H5Acreate2(where, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                 "create attribute " + name);
  const char* text = value.c_str();
  check(H5Awrite(a, type, &text), "write attribute " + name);
}

// The attribute's text; `found` false when it is absent.
std::string read_attribute(hid_t where, const std::string& name, bool& found) {
  found = H5Aexists(where, name.c_str()) > 0;
  if (!found) return {};
  const Handle a(H5Aopen(where, name.c_str(), H5P_DEFAULT), H5Aclose, "open attribute " + name);
  const Handle type = utf8_string_type();
  char* text = nullptr;
  check(H5Aread(a, type, &text), "read attribute " + name);
  std::string s = text ? text : "";
  H5free_memory(text);
  return s;
}

std::vector<hsize_t> dims_of(const std::vector<std::size_t>& shape) { return {shape.begin(), shape.end()}; }

void write_dataset(hid_t where, const std::string& name, hid_t type, const std::vector<hsize_t>& dims, const void* data) {
  const Handle space(H5Screate_simple(int(dims.size()), dims.data(), nullptr), H5Sclose, "make a data space");
  const Handle d(H5Dcreate2(where, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
                 "create dataset " + name);
  check(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write dataset " + name);
}

// Reads a whole dataset of `count` elements of `type`; false when it is absent or of another size.
bool read_dataset(hid_t where, const std::string& name, hid_t type, std::size_t count, void* data) {
  if (H5Lexists(where, name.c_str(), H5P_DEFAULT) <= 0) return false;
  const Handle d(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  const Handle space(H5Dget_space(d), H5Sclose, "get a data space");
  if (std::size_t(H5Sget_simple_extent_npoints(space)) != count) return false;
  return H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0;
}

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ",") + i;
  return s;
}

void replace_file(const std::filesystem::path& tmp, const std::filesystem::path& file) {
  std::error_code ec;
  try {
    check_output_target(file);  // never rename over a device, FIFO, socket or directory
  } catch (...) {
    std::filesystem::remove(tmp, ec);
    throw;
  }
  std::filesystem::rename(tmp, file, ec);
  if (ec) throw std::runtime_error("cannot rename '" + tmp.string() + "' to '" + file.string() + "': " + ec.message());
}

std::filesystem::path temporary_name(const std::filesystem::path& file) {
  return file.string() + ".partial-" + std::to_string(::getpid());
}

// /rows: the rows of every point in point order, with the point each belongs to.
void write_rows(hid_t f, const SweepResults& r) {
  const std::size_t columns = r.row_names.size();
  std::vector<std::uint64_t> point;
  for (std::size_t p = 0; p < r.points; ++p) point.insert(point.end(), r.rows[p].size() / columns, p);
  const Handle g(H5Gcreate2(f, "rows", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "create group rows");
  write_attribute(g, "legend", r.rows_legend);
  write_dataset(g, "point", H5T_NATIVE_UINT64, {hsize_t(point.size())}, point.data());
  std::vector<double> column(point.size());
  for (std::size_t k = 0; k < columns; ++k) {
    std::size_t at = 0;
    for (std::size_t p = 0; p < r.points; ++p)
      for (std::size_t i = k; i < r.rows[p].size(); i += columns) column[at++] = r.rows[p][i];
    write_dataset(g, r.row_names[k], H5T_NATIVE_DOUBLE, {hsize_t(column.size())}, column.data());
  }
}

// Reads /rows back into r.rows; false when it is absent or inconsistent.
bool read_rows(hid_t f, SweepResults& r) {
  if (H5Lexists(f, "rows", H5P_DEFAULT) <= 0) return false;
  const Handle d(H5Dopen2(f, "rows/point", H5P_DEFAULT), H5Dclose, "open dataset rows/point");
  const Handle space(H5Dget_space(d), H5Sclose, "get a data space");
  const auto count = std::size_t(H5Sget_simple_extent_npoints(space));
  std::vector<std::uint64_t> point(count);
  if (!read_dataset(f, "rows/point", H5T_NATIVE_UINT64, count, point.data())) return false;
  const std::size_t columns = r.row_names.size();
  std::vector<double> values(count * columns);
  for (std::size_t k = 0; k < columns; ++k)
    if (!read_dataset(f, "rows/" + r.row_names[k], H5T_NATIVE_DOUBLE, count, values.data() + k * count)) return false;
  for (auto& rows : r.rows) rows.clear();
  for (std::size_t i = 0; i < count; ++i) {
    if (point[i] >= r.points) return false;
    auto& rows = r.rows[point[i]];
    for (std::size_t k = 0; k < columns; ++k) rows.push_back(values[k * count + i]);
  }
  return true;
}

}  // namespace

SweepResults::SweepResults(std::vector<std::string> names, std::size_t n, std::vector<std::string> row_columns,
                           std::string legend)
    : scalar_names(std::move(names)),
      points(n),
      scalars(scalar_names.size() * n, std::nan("")),
      status(n, std::int8_t(PointStatus::missing)),
      wall_seconds(n, 0.0),
      reasons(n),
      row_names(std::move(row_columns)),
      rows_legend(std::move(legend)),
      rows(row_names.empty() ? 0 : n),
      checksums_(n, Sha256Digest{}) {}

SweepResults::SweepResults(const Job& job, std::size_t n)
    : SweepResults(job.scalar_names(), n, job.row_names(), job.rows_legend()) {}

void SweepResults::set(std::size_t point, const JobResult& r) {
  for (std::size_t s = 0; s < scalar_names.size(); ++s) scalars[s * points + point] = r.scalars.at(s);
  status[point] = std::int8_t(r.status);
  wall_seconds[point] = r.wall_seconds;
  reasons[point] = r.reason;
  if (!row_names.empty()) rows[point] = r.rows;
  checksums_[point] = point_checksum(*this, point);
}

const std::vector<Sha256Digest>& SweepResults::checksums() const {
  // About 1 microsecond per point, on all threads (each point's entry is its own).
  const auto n = std::int64_t(points);
#pragma omp parallel for schedule(static)
  for (std::int64_t p = 0; p < n; ++p)
    if (checksums_[std::size_t(p)] == Sha256Digest{}) checksums_[std::size_t(p)] = point_checksum(*this, std::size_t(p));
  return checksums_;
}

std::size_t SweepResults::finished() const {
  std::size_t n = 0;
  for (auto s : status) n += s != std::int8_t(PointStatus::missing);
  return n;
}

std::size_t SweepResults::failed() const {
  std::size_t n = 0;
  for (auto s : status) n += s != std::int8_t(PointStatus::missing) && s != std::int8_t(PointStatus::ok);
  return n;
}

std::vector<std::pair<std::string, std::string>> sweep_provenance() {
  const Provenance p = current_provenance();
  return {{"lrchain_version", p.build.version},
          {"git_commit", p.build.commit.empty() ? "unknown" : p.build.commit},
          {"compiler", p.build.compiler},
          {"build_type", p.build.build_type},
          {"date", p.date}};
}

std::vector<std::pair<std::string, std::string>> sweep_identity(const SweepConfig& c,
                                                                const std::vector<std::string>& scalar_names,
                                                                const std::vector<std::string>& row_names) {
  std::vector<std::pair<std::string, std::string>> id{
      {"job", c.job}, {"base config", c.base_text}, {"layout", c.grid ? "grid" : "list"}};
  std::vector<std::string> parameters;
  for (const auto& a : c.axes) parameters.push_back(a.parameter);
  id.emplace_back("axes", joined(parameters));
  for (const auto& a : c.axes) {
    std::string v;
    for (double x : a.values) v += fmt::format("{}{}", v.empty() ? "" : ",", x);
    id.emplace_back("values of axis " + a.parameter, v);
  }
  id.emplace_back("scalars", joined(scalar_names));
  if (!row_names.empty()) id.emplace_back("rows", joined(row_names));
  // A model-file base: the model file's bytes too (SHA-256), so that a sweep resumes on the same model.
  if (c.base_job && c.base_job->model_source()) id.emplace_back("model file", c.base_job->model_source()->definition()->file_sha256);
  return id;
}

void write_results(const std::filesystem::path& file, const SweepConfig& c, const SweepResults& r) {
  quiet_hdf5();
  const auto tmp = temporary_name(file);
  {
    const Handle f(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                   "create '" + tmp.string() + "'");
    for (const auto& [k, v] : sweep_provenance()) write_attribute(f, k, v);
    std::vector<std::string> parameters;
    for (const auto& a : c.axes) parameters.push_back(a.parameter);
    write_attribute(f, "name", c.name);
    write_attribute(f, "job", c.job);
    write_attribute(f, "layout", c.grid ? "grid" : "list");
    write_attribute(f, "axes", joined(parameters));
    write_attribute(f, "scalars", joined(r.scalar_names));
    write_attribute(f, "sweep_config", c.text);
    write_attribute(f, "base_config_file", c.base.string());
    write_attribute(f, "base_config", c.base_text);
    write_attribute(f, "points_finished", std::to_string(r.finished()));
    {
      const Handle axes(H5Gcreate2(f, "axes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "create group axes");
      for (const auto& a : c.axes)
        write_dataset(axes, a.parameter, H5T_NATIVE_DOUBLE, {hsize_t(a.values.size())}, a.values.data());
    }
    const auto dims = dims_of(c.shape());
    {
      const Handle scalars(H5Gcreate2(f, "scalars", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                           "create group scalars");
      for (std::size_t s = 0; s < r.scalar_names.size(); ++s)
        write_dataset(scalars, r.scalar_names[s], H5T_NATIVE_DOUBLE, dims, r.scalars.data() + s * r.points);
    }
    write_dataset(f, "status", H5T_NATIVE_INT8, dims, r.status.data());
    {
      const Handle d(H5Dopen2(f, "status", H5P_DEFAULT), H5Dclose, "open dataset status");
      write_attribute(d, "legend", status_legend());
    }
    write_dataset(f, "wall_seconds", H5T_NATIVE_DOUBLE, dims, r.wall_seconds.data());
    std::vector<const char*> reasons;
    for (const auto& s : r.reasons) reasons.push_back(s.c_str());
    write_dataset(f, "reason", utf8_string_type(), dims, reasons.data());
    if (!r.row_names.empty()) write_rows(f, r);
    write_dataset(f, "checksum", H5T_NATIVE_UINT8, {hsize_t(r.points), hsize_t(32)}, r.checksums().data());
    {
      const Handle d(H5Dopen2(f, "checksum", H5P_DEFAULT), H5Dclose, "open dataset checksum");
      write_attribute(d, "legend", "per point, SHA-256 of its record: index, status, wall time, scalars, reason, rows");
    }
    const Handle id(H5Gcreate2(f, "identity", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "create group identity");
    for (const auto& [k, v] : sweep_identity(c, r.scalar_names, r.row_names)) write_attribute(id, k, v);
    check(H5Fflush(f, H5F_SCOPE_GLOBAL), "flush '" + tmp.string() + "'");
  }
  replace_file(tmp, file);
}

namespace {

// "point 5 (bright.theta = 1.4, bright.detuning = -0.0001)".
std::string point_text(const SweepConfig& c, std::size_t point) {
  std::string values;
  for (const auto& [parameter, value] : c.overrides(point)) values += fmt::format("{}{} = {}", values.empty() ? "" : ", ", parameter, value);
  return fmt::format("point {} ({})", point, values);
}

// Refuses results whose status codes are unknown or whose records do not match their checksums,
// naming the first bad point.
void verify_records(hid_t f, const std::string& name, const SweepConfig& c, const SweepResults& r) {
  const auto refuse = [&](std::size_t p, const std::string& what) {
    return InputError(fmt::format("'{}' is damaged: {} {}; remove the file or choose another output to start over", name,
                                  point_text(c, p), what));
  };
  for (std::size_t p = 0; p < r.points; ++p)
    if (r.status[p] < std::int8_t(PointStatus::missing) || r.status[p] > std::int8_t(PointStatus::invalid))
      throw refuse(p, fmt::format("has status code {}, not one of {}", int(r.status[p]), status_legend()));
  std::vector<Sha256Digest> stored(r.points);
  if (!read_dataset(f, "checksum", H5T_NATIVE_UINT8, r.points * 32, stored.data()))
    throw InputError("'" + name + "' has no checksums of its records (written by an older lrchain, or damaged); "
                     "remove the file or choose another output to start over");
  // Checked on all threads; the first point that differs is named.
  const auto n = std::int64_t(r.points);
  std::vector<std::uint8_t> differs(r.points, 0);
#pragma omp parallel for schedule(static)
  for (std::int64_t p = 0; p < n; ++p) differs[std::size_t(p)] = point_checksum(r, std::size_t(p)) != stored[std::size_t(p)];
  for (std::size_t p = 0; p < r.points; ++p)
    if (differs[p]) throw refuse(p, "does not match its SHA-256 checksum");
}

// Fills the empty results `r` of the sweep from its file (read_results).
SweepResults read_into(const std::filesystem::path& file, const SweepConfig& c, SweepResults r) {
  const auto& scalar_names = r.scalar_names;
  quiet_hdf5();
  const std::string name = file.string();
  if (H5Fis_hdf5(name.c_str()) <= 0)
    throw InputError("'" + name + "' exists and is not an HDF5 sweep results file; remove it or choose another output");
  const Handle f(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open '" + name + "'");
  if (H5Lexists(f, "identity", H5P_DEFAULT) <= 0)
    throw InputError("'" + name + "' is not a sweep results file; remove it or choose another output");
  {
    const Handle id(H5Gopen2(f, "identity", H5P_DEFAULT), H5Gclose, "open group identity");
    for (const auto& [item, text] : sweep_identity(c, scalar_names, r.row_names)) {
      bool found = false;
      if (read_attribute(id, item, found) != text)
        throw InputError("cannot resume the sweep from '" + name + "': its " + item +
                         " changed since the file was written; remove the file or choose another output to start over");
    }
  }
  bool ok = read_dataset(f, "status", H5T_NATIVE_INT8, r.points, r.status.data()) &&
            read_dataset(f, "wall_seconds", H5T_NATIVE_DOUBLE, r.points, r.wall_seconds.data());
  for (std::size_t s = 0; ok && s < scalar_names.size(); ++s)
    ok = read_dataset(f, "scalars/" + scalar_names[s], H5T_NATIVE_DOUBLE, r.points, r.scalars.data() + s * r.points);
  std::vector<char*> reasons(r.points, nullptr);
  const Handle type = utf8_string_type();
  ok = ok && read_dataset(f, "reason", type, r.points, reasons.data());
  for (std::size_t p = 0; p < r.points; ++p) {
    if (reasons[p]) r.reasons[p] = reasons[p];
    H5free_memory(reasons[p]);
  }
  ok = ok && (r.row_names.empty() || read_rows(f, r));
  if (!ok) throw InputError("'" + name + "' is an incomplete sweep results file; remove it or choose another output");
  verify_records(f, name, c, r);
  return r;
}

// read_into, with HDF5's failures on a truncated or damaged file as InputError naming it.
SweepResults read_checked(const std::filesystem::path& file, const SweepConfig& c, SweepResults r) {
  try {
    return read_into(file, c, std::move(r));
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError("'" + file.string() + "' is truncated or damaged (" + e.what() +
                     "); remove the file or choose another output to start over");
  }
}

}  // namespace

SweepResults read_results(const std::filesystem::path& file, const SweepConfig& c,
                          const std::vector<std::string>& scalar_names) {
  return read_checked(file, c, SweepResults(scalar_names, c.points()));
}

SweepResults read_results(const std::filesystem::path& file, const SweepConfig& c, const Job& job) {
  return read_checked(file, c, SweepResults(job, c.points()));
}

void write_results_csv(const std::filesystem::path& file, const SweepConfig& c, const SweepResults& r) {
  const auto tmp = temporary_name(file);
  {
    std::ofstream out(tmp);
    if (!out) throw std::runtime_error("cannot write '" + tmp.string() + "'");
    for (const auto& a : c.axes) out << a.parameter << ',';
    out << "status";
    for (const auto& s : r.scalar_names) out << ',' << s;
    out << ",wall_seconds\n";
    for (std::size_t p = 0; p < r.points; ++p) {
      for (const auto& [parameter, value] : c.overrides(p)) out << fmt::format("{},", value);
      out << to_string(PointStatus(r.status[p]));
      for (std::size_t s = 0; s < r.scalar_names.size(); ++s) {
        const double v = r.scalars[s * r.points + p];
        out << ',' << (std::isnan(v) ? std::string() : fmt::format("{}", v));
      }
      out << fmt::format(",{}\n", r.wall_seconds[p]);
    }
    out.flush();
    if (!out) throw std::runtime_error("cannot write '" + tmp.string() + "'");
  }
  replace_file(tmp, file);
}


void write_rows_csv(const std::filesystem::path& file, const SweepConfig& c, const SweepResults& r) {
  const auto tmp = temporary_name(file);
  {
    std::ofstream out(tmp);
    if (!out) throw std::runtime_error("cannot write '" + tmp.string() + "'");
    out << "point";
    for (const auto& a : c.axes) out << ',' << a.parameter;
    for (const auto& n : r.row_names) out << ',' << n;
    out << '\n';
    const std::size_t columns = r.row_names.size();
    for (std::size_t p = 0; p < r.points; ++p) {
      const auto overrides = c.overrides(p);
      for (std::size_t i = 0; i < r.rows[p].size(); i += columns) {
        out << p;
        for (const auto& [parameter, value] : overrides) out << fmt::format(",{}", value);
        for (std::size_t k = 0; k < columns; ++k) out << fmt::format(",{}", r.rows[p][i + k]);
        out << '\n';
      }
    }
    out.flush();
    if (!out) throw std::runtime_error("cannot write '" + tmp.string() + "'");
  }
  replace_file(tmp, file);
}

}  // namespace lrchain::jobs::sweep

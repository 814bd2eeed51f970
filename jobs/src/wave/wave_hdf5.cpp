// The HDF5 file of a travelling-wave job (lrchain/jobs/wave_hdf5.hpp).
#include "lrchain/jobs/wave_hdf5.hpp"

#include <complex>
#include <string>
#include <vector>

#include "lrchain/jobs/hdf5_tree.hpp"
#include "lrchain/jobs/result_hdf5.hpp"
#include "wave_standing.hpp"

namespace lrchain::jobs::wave {

using nlohmann::json;
using jobs::Hdf5Element;

namespace {

// The numbers of `key` in every wave of the summary (null, e.g. an undefined NLS shift, as NaN).
std::vector<double> per_wave(const json& waves, const char* key) {
  std::vector<double> values;
  for (const json& w : waves) values.push_back(w.at(key).is_null() ? std::nan("") : w.at(key).get<double>());
  return values;
}

void write_vector(jobs::Hdf5TreeFile& file, const std::string& name, const std::vector<double>& v) {
  file.write_dataset(name, Hdf5Element::float64, v.data(), {v.size()});
}

// A standing wave's datasets (its "standing" object): the ramp, the orbit's coefficients c_{f,n,k}, its
// profiles at t = 0 and a quarter period (standing_profile.csv's) and the Floquet multipliers on the ring.
void write_standing(jobs::Hdf5TreeFile& file, const json& st) {
  file.write_attribute("/", "ring_sites", st.at("ring_sites").get<std::int64_t>());
  file.write_attribute("/", "period_sites", st.at("period_sites").get<std::int64_t>());
  const json& waves = st.at("waves");
  for (const char* key : {"amplitude", "omega", "omega_shift", "harmonics", "residual"})
    write_vector(file, std::string("/") + key, per_wave(waves, key));
  const json& c = st.at("coefficients");  // [field][site][k]
  if (!c.empty()) {
    const std::size_t fields = c.size(), sites = c.at(0).size(), harmonics = c.at(0).at(0).size();
    std::vector<double> values;
    sim::wave::StandingWave w;  // the last wave, for its profiles at t = 0 and a quarter period
    w.omega = st.at("omega").get<double>();
    w.sites = Index(sites);
    w.harmonics = Index(harmonics) - 1;
    w.coefficients.resize(Index(fields * sites), Index(harmonics));
    for (std::size_t f = 0; f < fields; ++f)
      for (std::size_t n = 0; n < sites; ++n)
        for (std::size_t k = 0; k < harmonics; ++k) {
          values.push_back(c[f][n][k].get<double>());
          w.coefficients(Index(f * sites + n), Index(k)) = values.back();
        }
    file.write_dataset("/coefficients", Hdf5Element::float64, values.data(), {fields, sites, harmonics});
    const auto [at0, at_quarter] = standing_profiles(w);
    file.write_dataset("/profile", Hdf5Element::float64, at0.data(), {fields, sites});
    file.write_dataset("/profile_quarter_period", Hdf5Element::float64, at_quarter.data(), {fields, sites});
  }
  if (st.at("floquet").is_object()) {
    const json& f = st["floquet"];
    const auto re = f.at("re").get<std::vector<double>>(), im = f.at("im").get<std::vector<double>>();
    std::vector<std::complex<double>> m;
    for (std::size_t i = 0; i < re.size(); ++i) m.emplace_back(re[i], im[i]);
    file.write_dataset("/floquet_multipliers", Hdf5Element::complex128, m.data(), {m.size()});
  }
}

// A travelling wave's or branch's datasets: per wave, the profile, the growth rates, the fate's series.
void write_travelling(jobs::Hdf5TreeFile& file, const json& s) {
  const json& waves = s.at("waves");
  for (const char* key : {"amplitude", "omega", "omega_shift", "nls_omega_shift", "harmonics"})
    write_vector(file, std::string("/") + key, per_wave(waves, key));
  if (s.contains("profile")) {
    const json& p = s["profile"];
    const std::vector<double> xi = p.at("xi").get<std::vector<double>>();
    std::vector<double> profile;
    const std::size_t fields = p.at("fields").size();
    for (std::size_t f = 0; f < fields; ++f) {
      const auto values = p["fields"].at("u" + std::to_string(f)).get<std::vector<double>>();
      profile.insert(profile.end(), values.begin(), values.end());
    }
    write_vector(file, "/xi", xi);
    file.write_dataset("/profile", Hdf5Element::float64, profile.data(), {fields, xi.size()});
  }
  if (s.contains("stability") && s["stability"].is_object()) {
    const json& st = s["stability"];
    write_vector(file, "/K", st.at("k").get<std::vector<double>>());
    write_vector(file, "/growth_rate", st.at("growth_rate").get<std::vector<double>>());
    write_vector(file, "/nls_growth_rate", st.at("nls_growth_rate").get<std::vector<double>>());
  }
  if (s.contains("fate") && s["fate"].is_object()) {  // the ring run: one sample per carrier period
    const json& f = s["fate"];
    file.write_attribute("/", "fate", f.at("fate").get<std::string>());
    for (const char* key : {"t", "deviation", "participation", "entropy", "dark", "bright", "energy_density"})
      write_vector(file, std::string("/fate_") + key, f.at(key).get<std::vector<double>>());
  }
}

}  // namespace

void write_wave_hdf5(const std::filesystem::path& path, const json& s) {
  jobs::Hdf5TreeFile file(path);
  const bool branch = s.at("step") == "continue", standing = s.at("step") == "standing";
  file.write_attribute("/", "lrchain_result",
                       std::string(standing ? "StandingWave" : branch ? "WaveBranch" : "TravellingWave"));
  jobs::write_provenance_attributes(file, s);
  file.write_attribute("/", "branch", s.at("branch").get<std::string>());
  file.write_attribute("/", "theta", s.at("theta").get<double>());
  file.write_attribute("/", "summary_json", s.dump());
  if (standing) write_standing(file, s.at("standing"));
  else write_travelling(file, s);
  file.create_group("/summary");
  jobs::write_json_tree(file, "/summary", s);
  file.commit();
}

}  // namespace lrchain::jobs::wave

#pragma once
// The HDF5 file of a wave job: `lrchain wave solve|continue|stability|fate|standing --out DIR --format
// hdf5` (DIR/result.h5 beside the CSV files) and Python's TravellingWave.to_hdf5, WaveBranch.to_hdf5 and
// StandingWave.to_hdf5 (the same file); lrchain.load reads it back. Everything comes from the job's JSON summary (to_json of
// wave_job.hpp). Layout:
//   root attributes  lrchain_result ("TravellingWave" for solve, stability and fate, "WaveBranch" for continue,
//                    "StandingWave" for standing),
//                    lrchain_version, git_commit, model (JSON text: name, file_hash, parameters), branch,
//                    theta, summary_json (the summary as text: nulls and booleans kept)
//   datasets         amplitude, omega, omega_shift, nls_omega_shift, harmonics (one entry per wave: the
//                    ramp, or the branch); a single wave also xi (2H+1 phases) and profile (fields x phases);
//                    after stability K, growth_rate and nls_growth_rate; after fate fate_t, fate_deviation,
//                    fate_participation, fate_entropy, fate_dark, fate_energy_density and the root attribute fate
//   standing         instead: amplitude, omega, omega_shift, harmonics, residual (one entry per wave of the
//                    ramp), coefficients c_{f,n,k} of the last wave's orbit u_f[n](t) = sum_k c_{f,n,k}
//                    cos(k omega t) (fields x period_sites x (H+1)), profile and profile_quarter_period (u_f[n]
//                    at t = 0 and pi / (2 omega), fields x period_sites), floquet_multipliers (complex, by
//                    decreasing modulus, on the ring) and the root attributes ring_sites, period_sites
//   /summary         the summary as a tree (objects groups, numbers and strings attributes, null left out)
#include <filesystem>

#include <nlohmann/json.hpp>

namespace lrchain::jobs::wave {

// Writes `summary` (to_json of a WaveResult, or the same JSON a front end kept) to `path`.
void write_wave_hdf5(const std::filesystem::path& path, const nlohmann::json& summary);

}  // namespace lrchain::jobs::wave

#pragma once
// The steps of the dark job shared by the resonant chain's and the models' runs (dark_run.cpp) and
// its writers (dark_write*.cpp).
#include <string>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/jobs/output_files.hpp"

namespace lrchain::jobs::dark {

// Continues the solved breather q0 (unknowns of `shooting`) away from the edge r.edge.omega into r.branch.
void continue_from(const sim::dark::DarkShootingProblem& shooting, const Eigen::VectorXd& q0, const DarkConfig& c,
                   const DarkRunHooks& hooks, DarkResult& r);

// The lattice's name in figure titles: "ρ = 0.3333" for the chain, the model's name for a model file.
std::string lattice_label(const DarkResult& r);

// profile.csv/.gp and (floquet) multipliers.csv/.gp of a solved breather.
void write_profile(const DarkResult& r, const std::string& dir, jobs::Figures& figures);
void write_multipliers(const std::string& dir, const std::string& stem, const sim::dark::FloquetResult& f,
                       double omega_b, jobs::Figures& figures);
// branch.csv, floquet_moduli.csv and their figures.
void write_branch(const DarkResult& r, const std::string& dir, jobs::Figures& figures);
// The evolution's space-time files, evolution.csv, snapshots.csv, figures and summary.json (`summary`).
void write_evolution(const DarkResult& r, const std::string& dir, jobs::Figures& figures, nlohmann::json& summary);

}  // namespace lrchain::jobs::dark

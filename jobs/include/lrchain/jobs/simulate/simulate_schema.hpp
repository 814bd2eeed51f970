#pragma once
// The simulate jobs' options once (option_schema.hpp): each key of BrightRunConfig, DriveRunConfig,
// ModulatedRunConfig, RingRunConfig and ModelBrightConfig that a front end offers, with its default
// (read from a default-constructed config), range, one-line documentation and the help `lrchain
// simulate <job> --help` shows. Keys are the config file's ([bright] sites, [drive] switch_off_time).
#include <vector>

#include "lrchain/jobs/option_schema.hpp"

namespace lrchain::jobs {

const std::vector<JobOption>& bright_options();        // `simulate bright`, lrchain.simulate.bright
const std::vector<JobOption>& model_bright_options();  // `simulate bright --model`, bright(model=...)
const std::vector<JobOption>& drive_options();         // `simulate drive`, lrchain.simulate.drive
const std::vector<JobOption>& modulated_options();     // `simulate modulated`, lrchain.simulate.modulated
const std::vector<JobOption>& ring_options();          // `simulate ring`, lrchain.simulate.ring

}  // namespace lrchain::jobs

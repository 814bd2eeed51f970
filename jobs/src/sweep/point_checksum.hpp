#pragma once
// The SHA-256 checksum of one point's record in a sweep's results file (/checksum), written with
// the data and verified when a sweep resumes, so that a damaged record is never taken as a result.
#include <cstddef>

#include "lrchain/sha256.hpp"
#include "lrchain/jobs/sweep/results_file.hpp"

namespace lrchain::jobs::sweep {

using namespace lrchain::sim;  // the numerics this job layer runs

// SHA-256 over the point's index, status, wall time, scalars, reason and rows (length-prefixed
// fields; numbers as their little-endian bytes).
Sha256Digest point_checksum(const SweepResults& r, std::size_t point);

}  // namespace lrchain::jobs::sweep

#pragma once
// The speed/accuracy front of `volren bench`: which rows no other row beats, and which rows
// beat the default configuration (so the default is not on the front).
#include "BenchReport.h"

#include <vector>

namespace volren::app {

/// Marks the Pareto front per dataset, size and picture (the truth: rows drawing the same
/// lighting model): volren rows no other such row matches or beats on both time and RMSE.
void markPareto(std::vector<BenchRow>& rows);

/// Marks the rows that beat the "default" row of their dataset, size and picture on both axes by
/// more than the run's noise: faster by more than twice the two rows' frame-time deviations (and
/// 2 % of the default's time), and an RMSE lower by more than 5 %. Returns them.
std::vector<const BenchRow*> markRowsBeatingTheDefault(std::vector<BenchRow>& rows);

}  // namespace volren::app

#pragma once
// The speed/accuracy front of `volren bench`: which rows no other row beats, and which rows
// beat the default configuration (so the default is not on the front).
#include "BenchReport.h"

#include <vector>

namespace volren::app {

/// Marks the Pareto front per dataset, size and picture (the truth: rows drawing the same
/// lighting model): volren rows no other such row matches or beats on both time and RMSE.
void markPareto(std::vector<BenchRow>& rows);

/// Marks the rows that beat the "default" row of their dataset, size and picture: better on one
/// axis beyond the run's noise and not worse beyond it on the other. Time: faster by more than
/// twice the two rows' frame-time deviations (and 2 % of the default's time), not slower when
/// within that margin. Error: an RMSE lower by more than 5 %, as accurate when within 1 %.
/// Marks too the rows the default beats by the same rule (BenchRow::beatenByDefault). Returns
/// the rows that beat it.
std::vector<const BenchRow*> markRowsBeatingTheDefault(std::vector<BenchRow>& rows);

}  // namespace volren::app

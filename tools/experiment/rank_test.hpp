// Whether two sets of repeats (Mrays/s of two variants) differ by more than their noise: the
// Mann-Whitney U test, exact for the small repeat counts experiments use. It assumes nothing of
// the timings' distribution, which on a shared machine is anything but normal.
#pragma once

#include <vector>

namespace clrt::experiment {

// The two-sided p-value of the Mann-Whitney U test of `a` against `b`: the chance, were both
// drawn from one distribution, of a rank sum at least as far from its mean as theirs. Exact
// (every split of the pooled ranks) up to 20 values in all, the normal approximation beyond;
// ties share their mean rank. 1 when either set is empty.
double mann_whitney_p(const std::vector<double>& a, const std::vector<double>& b);

// The smallest p the test can give for sets of `n` and `m` values: 2 / C(n + m, n). With 3
// repeats each it is 0.1, so no difference can show at 0.05 (4 repeats: 0.029).
double smallest_mann_whitney_p(int n, int m);

}  // namespace clrt::experiment

// How far the discretisation may have moved a number, from the run and its
// coarser twins (lib/run/error_estimate.hpp runs them). For a number whose
// run gave f and whose K coarse twins, at spacings about r times the run's,
// gave c_1..c_K:
//
//   error = S |mean(c) - f| + sd(c)
//
// - The first term is the systematic part (Richardson): a method of order p
//   that moved by |mean(c) - f| between h and r h has an error of that
//   change over r^p - 1 at h, so S = 1 / (r^p - 1) (0.8 at r = 1.5, p = 2).
//   It is used only where every twin moved the number the same way, at
//   every time the number is read (a series: the snapshots of the wall, the
//   rows of a sensor's record). Where the signs disagree, the change is not
//   a trend that shrinks with the spacing: S = 1, the change itself.
// - The second term is the scatter: the sample standard deviation of the
//   twins, which differ only by where the particle rows fall against the
//   pipes and faces. A run at the finer spacing carries a scatter of its own
//   of this size or less (bench/README.md: the closure day scatters by about
//   1 % at 2-3 cm, 0.03 % from 1.5 cm down).
//
// Any missing value (null, NaN) in f or the twins gives a missing error.
#pragma once

#include <vector>

namespace frostwall::run {

// The method's order in the spacing: SPH heat conduction with the
// renormalised Laplacian and PD bonds are second order, as the Neumann and
// plate refinements show (docs/freezing.md, docs/mechanics.md).
inline constexpr double method_order = 2.0;

// The errors of a series read at the same times in the run and in every
// twin: fine[t], coarse[k][t]; ratio: the twins' mean spacing over the run's.
// One Richardson decision (the signs) for the whole series.
std::vector<double> series_errors(const std::vector<double>& fine, const std::vector<std::vector<double>>& coarse,
                                  double ratio, double order = method_order);

// One number: a series of one.
double number_error(double fine, const std::vector<double>& coarse, double ratio, double order = method_order);

}  // namespace frostwall::run

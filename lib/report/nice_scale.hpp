// Axis ends and ticks at round numbers (1, 2, 5 x 10^k), and tick labels
// written the way a journal figure writes them (true minus sign, no
// trailing zeros beyond the step's precision).
#pragma once

#include <string>
#include <vector>

namespace frostwall::report {

struct NiceScale {
  double lo = 0.0, hi = 1.0;  // the axis ends, on ticks
  double step = 0.2;
  std::vector<double> ticks;  // lo, lo + step, ..., hi
  int decimals = 1;           // enough to tell neighbouring ticks apart
};

// About `target` intervals covering [lo, hi]; a degenerate range is widened.
NiceScale nice_scale(double lo, double hi, int target = 5);

// Of the nice scales with 4 to 8 intervals, the one that pads [lo, hi]
// least (ties: fewer ticks): a time axis of 12 days ends at 12, not 15.
NiceScale tight_scale(double lo, double hi);

// Ticks of `step`'s scale that fall inside [lo, hi], without widening the
// range (a colour bar whose ends are the data's).
NiceScale ticks_within(double lo, double hi, int target = 5);

// v with `decimals` digits after the point, "−" for minus, "0" not "−0".
std::string tick_label(double v, int decimals);
// A number with its estimated error, "13.88 ± 0.16": the error to one
// significant digit (two when it starts with 1), the value to the same
// place; without a positive error, tick_label(value, decimals).
std::string with_error(double value, double error, int decimals);

}  // namespace frostwall::report

// The flanks of a single bump in a profile f(x) (a crater's settlement, a
// heap's height), measured from the profile's lowest value, its base (the
// surrounding ground, which may itself have settled): the peak's height
// over the base, and on each side the straight flank between 10 % and 90 %
// of it, read from where the profile first falls through those levels
// walking out from the peak (linear between samples). A flank's slope is
// the rise 0.8 height over its run; its foot is where the line through
// those two points meets the base (a crater's rim, a heap's toe).
#pragma once

#include <optional>
#include <vector>

namespace frostwall::post {

struct Flank {
  double x10 = 0.0, x90 = 0.0;  // where the profile falls through 10 % and 90 % of the peak
  double foot = 0.0;            // the flank's line at f = 0
  double slope_deg = 0.0;       // from the horizontal
};

struct Bump {
  double peak = 0.0, peak_x = 0.0;           // the height over the base, and where
  double base = 0.0;                         // the profile's lowest value
  std::optional<Flank> low_side, high_side;  // towards smaller and larger x; none where the profile ends first
  // Both feet apart (only with both flanks), and the mean slope of those found.
  std::optional<double> width() const;
  std::optional<double> mean_slope_deg() const;
};

// x ascending, same length as f; an empty or flat profile gives peak 0 and no flanks.
Bump bump_flanks(const std::vector<double>& x, const std::vector<double>& f, double low = 0.1, double high = 0.9);

}  // namespace frostwall::post

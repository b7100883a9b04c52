// A smooth freezing curve (project::FreezingCurve, exponential or power):
// the share of the pore water still liquid at a temperature, where
// freezing begins and where its table ends.
//   exponential: f = S_r + (1 - S_r) exp(-((T - Tf)/W)^2) below Tf
//   power:       f = min(1, alpha theta^beta / w), theta = Tf - T (K),
//                w the water content when unfrozen (beta < 0): freezing
//                begins at theta* = (w / alpha)^(1/beta) below Tf.
#pragma once

#include "project/project.hpp"

namespace frostwall::thermal {

struct SmoothCurve {
  project::FreezingCurve curve;
  double freezing_point = 0.0;  // Tf of the soil, degC

  // The liquid share at T (1 at and above the onset).
  double liquid_fraction(double T) const;
  // Where the water begins to freeze, degC.
  double onset() const;
  // Where the table of the phase law ends, degC: the exponential's share
  // within 1e-6 of S_r; the power law 60 K below its onset (colder than
  // any brine). Colder ground keeps this share liquid.
  double bottom() const;
};

}  // namespace frostwall::thermal

// A coaxial freeze pipe in cross-section: the brine goes down one channel
// (the annulus between the inner supply pipe and the freeze pipe, or the
// inner pipe) and returns up the other, turning at the bottom. Per metre of
// pipe, two thermal resistances join the channels to each other and the
// annulus to the freeze pipe's outer wall, where the ground begins:
//
//   R_channels = 1 / (pi d_ii h_i) + ln(d_io / d_ii) / (2 pi k_i) + 1 / (pi d_io h_a)
//   R_ground   = 1 / (pi d_oi h_a) + ln(d_oo / d_oi) / (2 pi k_o)
//
// (d_ii, d_io the inner pipe's inside and outside diameters, d_oi, d_oo the
// freeze pipe's; k_i, k_o their walls' conductivities.) The films come from
// the flow, as OpenGeoSys's coaxial borehole heat exchangers take them
// (after Diersch et al. 2011), fully developed:
//  - inner pipe, hydraulic diameter d_ii: Nu = 4.364 laminar (Re < 2300,
//    uniform heat flux); Gnielinski above 1e4,
//      Nu = (xi/8) Re Pr / (1 + 12.7 sqrt(xi/8) (Pr^(2/3) - 1)) (1 + (D/L)^(2/3)),
//      xi = (1.8 log10 Re - 1.5)^-2;
//    linear in Re between the laminar value and that at 1e4 (xi = 0.0308);
//  - annulus, hydraulic diameter d_oi - d_io, diameter ratio a = d_io / d_oi:
//    laminar Nu = 3.66 + (4 - 0.102 / (a + 0.02)) a^0.04 (Gnielinski's
//    annulus, VDI Heat Atlas); turbulent the pipe's times
//    (0.86 a^0.84 + 1 - 0.14 a^0.6) / (1 + a); the same blend between.
#pragma once

#include <string_view>

namespace frostwall::design {

struct CoaxialPipe {
  double outer_diameter = 0.0;  // the freeze pipe's outside, m
  double outer_wall = 0.0;      // its wall's thickness, m
  double outer_conductivity = 0.0;
  double inner_diameter = 0.0;  // the inner pipe's outside, m
  double inner_wall = 0.0;
  double inner_conductivity = 0.0;
  double length = 0.0;  // m, for the entrance term (D/L)^(2/3)
};

struct Brine {                 // at the temperature the films are taken at
  double density = 0.0;        // kg/m3
  double viscosity = 0.0;      // Pa s
  double conductivity = 0.0;   // W/(m K)
  double heat_capacity = 0.0;  // J/(kg K)
};

struct ChannelFilm {
  double reynolds = 0.0, prandtl = 0.0, nusselt = 0.0;
  double h = 0.0;  // W/(m2 K), on the channel's hydraulic diameter
};

struct CoaxialResistances {
  ChannelFilm inner, annulus;
  double channels = 0.0;  // R between the two channels, m K / W
  double ground = 0.0;    // R from the annulus to the freeze pipe's outer wall, m K / W
};

// The films and resistances at a flow of `flow` m3/s per pipe.
CoaxialResistances coaxial_resistances(const CoaxialPipe& pipe, const Brine& brine, double flow);

double pipe_nusselt(double reynolds, double prandtl, double diameter_over_length);
double annulus_nusselt(double reynolds, double prandtl, double diameter_ratio, double diameter_over_length);

}  // namespace frostwall::design

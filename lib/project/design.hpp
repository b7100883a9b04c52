// The designer's inputs of a shaft project, as given: the brine's film
// (a coefficient, or the annulus flow it follows from), the frozen soil's
// strength against temperature and the wall check (lib/design evaluates
// the formulas; lib/freezing applies them to the run's walls).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace frostwall::project {

struct BrineProperties {
  double density = 0.0;        // kg/m3
  double viscosity = 0.0;      // Pa s (dynamic)
  double conductivity = 0.0;   // W/(m K)
  double heat_capacity = 0.0;  // J/(kg K)
};

struct Annulus {
  double inner_diameter = 0.0;  // m: the supply pipe's outer diameter
  double outer_diameter = 0.0;  // m: the freeze pipe's inner diameter
  double flow = 0.0;            // m3/s through the annulus
  BrineProperties brine;
};

// The thick-cylinder formulas of the wall check (design/wall_strength.hpp).
enum class WallFormula { lame_tresca, lame_mises, domke, plastic_tresca, plastic_mohr_coulomb };
std::string_view name(WallFormula f);  // as written in the project file

// The frozen soil's uniaxial compressive strength against temperature, MPa
// (T in degC, below 0): a table interpolated linearly (held at its ends),
// a + b |T|, or sigma_0 + k |T|^m.
class StrengthLaw {
 public:
  static StrengthLaw table(std::vector<std::pair<double, double>> points);  // [T, sigma_c], any order
  static StrengthLaw linear(double a, double b);
  static StrengthLaw power(double sigma_0, double k, double m);
  double at(double T) const;

 private:
  enum class Kind { table, linear, power } kind_ = Kind::linear;
  std::vector<std::pair<double, double>> points_;  // by rising T
  double p0_ = 0.0, p1_ = 0.0, p2_ = 1.0;
};

// Why a strength table is not usable (empty when it is): the strength
// must not fall as the soil gets colder, and every value must be positive.
std::string table_problem(const std::vector<std::pair<double, double>>& points);

// The wall check: a target thickness typed in, or the thickness
// the ground pressure needs from the frozen soil's strength at the wall's
// mean temperature (design/wall_strength.hpp).
struct Design {
  std::optional<double> required_thickness;    // m
  std::optional<double> max_mean_temperature;  // degC
  std::optional<StrengthLaw> strength;         // uniaxial compressive, MPa
  double allowable_factor = 0.5;
  std::optional<double> depth;               // m
  std::optional<double> pressure;            // lateral, MPa, at the depth
  WallFormula formula = WallFormula::domke;  // the governing one
  std::optional<double> friction_angle;      // degrees: Mohr-Coulomb's plastic limit
  // The design isotherm (degC): the wall is also measured on the part of
  // each ray colder than this, and the check then uses that wall.
  std::optional<double> isotherm;
  bool checks_strength() const { return strength && pressure; }
};

}  // namespace frostwall::project

// The "mechanics" block of a plain-geometry project: the solid's elastic
// and fracture properties, how each side is supported, and how the
// quasi-static deformation follows the temperature (lib/pd/).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace frostwall::project {

enum class Plane { strain, stress };

// A side of the rectangle: free (traction-free), roller (normal
// displacement 0, a symmetry plane), fixed (displacement 0), or held at a
// prescribed displacement.
struct Support {
  enum class Kind { free, roller, fixed, displacement } kind = Kind::free;
  double ux = 0.0, uy = 0.0;  // m, for Kind::displacement
};

struct SolidMaterial {
  double elastic_modulus = 0.0;           // Pa
  double poisson_ratio = 0.25;            // bond-based PD fixes it (1/4 plane strain, 1/3 plane stress)
  double thermal_expansion = 0.0;         // 1/K, linear
  std::optional<double> fracture_energy;  // J/m2; none: bonds never break
  double reference_temperature = 0.0;     // degC: stress-free
};

// How pore water that freezes loads the solid around it
// (mechanics.freezing_expansion; only with pores).
struct FreezingExpansion {
  // rim_displacement (the PD paper's): each pore's rim is pushed out
  // radially so the pore gains volume_change x its volume, ramped with the
  // pore's frozen fraction. ice_eigenstrain: ice particles carry bonds
  // (ice_elastic_modulus) and a free areal expansion of volume_change x
  // their frozen fraction; liquid water carries no bonds.
  enum class Model { rim_displacement, ice_eigenstrain } model = Model::ice_eigenstrain;
  double volume_change = 0.09;       // relative, at full freezing
  double ice_elastic_modulus = 9e9;  // Pa
};

struct Mechanics {
  SolidMaterial material;
  Plane plane = Plane::strain;
  Support left, right, bottom, top;
  // Adaptive dynamic relaxation stops when the RMS of a step's displacement
  // increment falls below tolerance x the RMS displacement.
  double tolerance = 1e-7;
  // Re-equilibrate when some particle's temperature has moved this much
  // (K) since the last equilibrium, and at every snapshot; nullopt: 10 % of
  // the largest temperature change from the reference so far.
  std::optional<double> temperature_change;
  int max_iterations = 200000;
  // With pores: re-equilibrate also when some pore's frozen
  // fraction has moved this much since the last equilibrium.
  double frozen_fraction_change = 0.05;
  std::optional<FreezingExpansion> freezing_expansion;  // default set by the loader when there are pores
  // "linear" (default): bond stretch and direction linearised in the
  // displacement (strains of 1e-4 make the rest 1e-8 relative), so a force
  // evaluation is a gather of fixed 2x2 bond stiffnesses; "nonlinear":
  // the exact stretch and deformed direction. Bonds break on the exact
  // stretch either way.
  bool linear_kinematics = true;
  // How each equilibrium is found: "direct" (default with linear
  // kinematics: a sparse Cholesky factor kept as the preconditioner of
  // conjugate gradients, pd/equilibrium.hpp) or "dynamic_relaxation" (the
  // only one for nonlinear kinematics).
  enum class Equilibrium { direct, dynamic_relaxation };
  Equilibrium equilibrium = Equilibrium::direct;
  // A broken bond stops carrying heat too (the crack insulates): the
  // thermal pairs between the same two particles are cut.
  bool cracks_insulate = false;
};

namespace detail {
class Node;
}
// Reads "mechanics" (problems and warnings appended; the Node reports paths).
Mechanics read_mechanics(const detail::Node& n, std::vector<std::string>& warnings);

}  // namespace frostwall::project

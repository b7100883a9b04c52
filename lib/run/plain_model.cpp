#include "run/plain_model.hpp"

#include "sph/laplacian.hpp"

namespace frostwall::run {

namespace {
double default_spacing(const project::Rectangle& r) {
  return std::min(std::max(r.width, r.height) / 200.0, std::min(r.width, r.height) / 4.0);
}
}  // namespace

PlainModel build_plain_model(const project::Project& p) {
  if (p.numerics.integrator == project::IntegratorKind::implicit)
    throw project::ProjectError({"numerics.integrator: 'implicit' is not available in this version; use 'explicit'"});
  if (!std::holds_alternative<project::Rectangle>(p.geometry))
    throw project::ProjectError({"layout: shaft sections are not available in this version; use a 'geometry'"});
  const auto& rect = std::get<project::Rectangle>(p.geometry);

  PlainModel m;
  const double spacing = p.numerics.spacing.value_or(default_spacing(rect));
  m.h = p.numerics.smoothing_ratio * spacing;
  m.scene = geometry::build_rectangle(rect, spacing, m.h);
  m.face = geometry::cooled_face(rect, m.scene);
  m.kernel = sph::make_kernel<2>(p.numerics.kernel);
  thermal::PhaseChangeLaw law(p.soil);
  sph::LaplacianPairs pairs =
      sph::build_laplacian_pairs<2>(m.scene.particles, *m.kernel, {m.h, p.numerics.laplacian, law.anisotropic()});
  m.model = std::make_unique<thermal::ThermalModel>(
      m.scene.particles.volume, m.scene.particles.boundary, std::move(pairs), law, m.scene.boundaries,
      thermal::ConductionOptions{p.numerics.conductivity_mean, p.numerics.laplacian}, p.domain.initial_temperature);
  m.integrator = std::make_unique<thermal::ExplicitEuler>(p.numerics.beta, m.h);
  return m;
}

}  // namespace frostwall::run

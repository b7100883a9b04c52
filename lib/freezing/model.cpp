#include "freezing/model.hpp"

#include "freezing/capacity.hpp"
#include "freezing/excavation_face.hpp"

#include <stdexcept>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "design/annulus_film.hpp"
#include "geometry/layout.hpp"
#include "geometry/pores.hpp"
#include "pd/conduction_bonds.hpp"
#include "pipes/pipe_exchange.hpp"
#include "geometry/symmetry.hpp"
#include "sph/laplacian.hpp"
#include "sph/wall_extrapolation.hpp"
#include "thermal/backward_euler.hpp"
#include "thermal/super_time_stepping.hpp"

namespace frostwall::freezing {

double narrowest_gap(const project::ShaftSection& s) {
  const auto pipes = geometry::pipe_positions(s.layout);
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < pipes.size(); ++a)
    for (std::size_t b = a + 1; b < pipes.size(); ++b)
      gap = std::min(gap, std::hypot(pipes[a].x - pipes[b].x, pipes[a].y - pipes[b].y));
  const double wall = project::has_wall(s.pipe.model) ? s.pipe.diameter : 0.0;
  return std::isfinite(gap) ? std::max(gap - wall, s.pipe.diameter) : std::numeric_limits<double>::infinity();
}

double default_spacing(const project::Project& p) {
  if (const auto* r = std::get_if<project::Rectangle>(&p.geometry))
    return std::min(std::max(r->width, r->height) / 200.0, std::min(r->width, r->height) / 4.0);
  // Shaft sections: a pipe disc should be several particles across.
  // Graded: 2 cm at the pipes and through the wall band; a lattice 2.5 cm.
  // Closure is decided in the narrowest gap between two pipe walls, so a
  // fixed number of particles stands across it (25) where pipes stand
  // close. How near converged each choice comes: bench/README.md,
  // "Convergence of the closure day in the spacing".
  const auto& s = std::get<project::ShaftSection>(p.geometry);
  const double gap = narrowest_gap(s);
  // Line sinks: the pipe's diameter no longer bounds it; 25 across the gap,
  // at most 5 cm.
  if (s.pipe.model == project::PipeModel::line) return std::min(0.05, gap / 25.0);
  if (p.numerics.placement == project::Placement::graded) return std::min({0.02, 0.3 * s.pipe.diameter, gap / 25.0});
  return std::min({0.025, 0.4 * s.pipe.diameter, gap / 25.0});
}

double resolved_spacing(const project::Project& p) { return p.numerics.spacing.value_or(default_spacing(p)); }

namespace {
// The share of the wall of the pipe centred at (x, y) inside the section.
double wall_share(const geometry::ShaftScene& scene, double x, double y) {
  constexpr int samples = 3600;
  int inside = 0;
  for (int k = 0; k < samples; ++k) {
    const double phi = 2.0 * M_PI * (k + 0.5) / samples;
    inside += geometry::inside_wedge(scene.wedge,
                                     {x + scene.pipe_radius * std::cos(phi), y + scene.pipe_radius * std::sin(phi)});
  }
  return double(inside) / samples;
}

// Brine behind a film at the pipe walls, or pipes held at the heat they
// draw: each pipe's wall particles form a group (the nearest pipe centre),
// with the length of its wall inside the simulated section (a pipe on a
// mirror line has half of it there). h is given, or follows from the
// annulus flow (a transitional film is uncertain: the run warns).
void attach_wall_balance(const project::Pipe& pipe, geometry::ShaftScene& scene, std::vector<std::string>& warnings) {
  if (pipe.boundary != project::PipeBoundary::brine && !pipe.heat_extraction) return;
  const auto& P = scene.particles;
  geometry::FilmWall film;
  film.heat_transfer_coefficient = pipe.heat_transfer_coefficient;
  film.drawn_heat = pipe.heat_extraction;
  film.full_perimeter = 2.0 * M_PI * scene.pipe_radius;
  if (pipe.annulus) {
    const auto annulus = design::annulus_film(*pipe.annulus, pipe.diameter);
    film.heat_transfer_coefficient = annulus.h;
    if (annulus.regime == design::FlowRegime::transitional)
      warnings.push_back(
          fmt::format("pipe.annulus: Re = {:.0f} is transitional (2300 to 10000): h = {:.0f} W/(m2 K) is "
                      "interpolated between the laminar and the turbulent film and is uncertain",
                      annulus.reynolds, annulus.h));
  }
  film.group.assign(P.size() - P.n_free, -1);
  for (std::size_t i = P.n_free; i < P.size(); ++i) {
    if (P.boundary[i] != scene.pipe_boundary) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t q = 0; q < scene.pipes.size(); ++q)
      if (const double d = (P.position[i] - particles::Vec<2>(scene.pipes[q].x, scene.pipes[q].y)).norm(); d < nearest)
        nearest = d, film.group[i - P.n_free] = int(q);
  }
  for (const auto& q : scene.pipes) film.perimeter.push_back(film.full_perimeter * wall_share(scene, q.x, q.y));
  scene.boundaries[scene.pipe_boundary].film = std::move(film);
}
// The line-sink pipes' nodes: the fixed particle at each pipe's centre in
// the section, with the share of its wall there.
std::vector<pipes::LineSinkNode> line_sink_nodes(const geometry::ShaftScene& scene) {
  std::vector<pipes::LineSinkNode> nodes;
  const auto& P = scene.particles;
  for (std::size_t i = P.n_free; i < P.size(); ++i)
    if (P.boundary[i] == scene.pipe_boundary)
      nodes.push_back({P.position[i], scene.pipe_radius, static_cast<std::uint32_t>(i),
                       wall_share(scene, P.position[i][0], P.position[i][1])});
  return nodes;
}

}  // namespace

Model build_cloud(const project::Project& p) {
  Model m;
  m.spacing = resolved_spacing(p);
  check_capacity(p, m.spacing);
  const double spacing = m.spacing;
  m.h = p.numerics.smoothing_ratio * spacing;
  // PD bonds reach a horizon: the fixed layers beyond a held face must be
  // as deep (the scene builders lay ceil(2h / spacing) of them).
  if (p.numerics.method == project::Method::pd) m.h = std::max(m.h, 0.5 * p.numerics.horizon * spacing);
  const bool graded = p.numerics.placement == project::Placement::graded;
  if (const auto* rect = std::get_if<project::Rectangle>(&p.geometry)) {
    auto scene = std::make_unique<geometry::RectangleScene>(
        graded
            ? geometry::build_graded_rectangle(
                  *rect, geometry::rectangle_size_field(*rect, spacing, p.numerics.grading), p.numerics.smoothing_ratio)
            : geometry::build_rectangle(*rect, spacing, m.h));
    m.face = geometry::cooled_face(*rect, *scene);
    m.rectangle = scene.get();
    m.scene = std::move(scene);
  } else {
    const auto& section = std::get<project::ShaftSection>(p.geometry);
    if (const auto problems = geometry::layout_problems(section); !problems.empty())
      throw project::ProjectError(problems);
    // Flowing groundwater keeps only a mirror line along the flow.
    std::string seepage_note;
    geometry::Wedge wedge = p.numerics.unsymmetric_cloud ? geometry::Wedge{} : symmetry_wedge(section);
    if (p.groundwater && p.groundwater->speed() > 0.0) {
      const auto pipes = geometry::pipe_positions(section.layout);
      const auto& q = p.groundwater->darcy_flux;
      wedge = geometry::find_flow_symmetry_wedge(pipes, std::atan2(q[1], q[0]),
                                                 geometry::default_symmetry_tolerance(pipes), seepage_note);
    }
    auto scene = std::make_unique<geometry::ShaftScene>(
        graded ? geometry::build_graded_shaft_section(
                     section, p.domain, wedge, geometry::shaft_size_field(section, wedge, spacing, p.numerics.grading),
                     p.numerics.smoothing_ratio)
               : geometry::build_shaft_section(section, p.domain, wedge, spacing, m.h));
    if (!seepage_note.empty()) scene->notes.push_back(seepage_note);
    scene->notes.push_back(geometry::describe(wedge));
    if (p.numerics.unsymmetric_cloud)
      scene->notes.push_back("symmetry: none (numerics.symmetry): the full ring placed as without symmetry");
    else if (!p.numerics.use_symmetry) {
      geometry::unfold_to_full_ring(*scene);
      scene->notes.push_back("symmetry: off (numerics.symmetry): the wedge's particles mirrored around the full ring");
    }
    attach_wall_balance(section.pipe, *scene, m.warnings);
    m.shaft = scene.get();
    m.scene = std::move(scene);
  }
  // A graded cloud: h_i = smoothing_ratio * local spacing; the explicit
  // step follows the smallest.
  m.smoothing = m.particles().graded() ? sph::SmoothingLengths::of_particles(m.particles(), p.numerics.smoothing_ratio)
                                       : sph::SmoothingLengths(m.h);
  m.h = m.smoothing.smallest();
  return m;
}

Model copy_cloud(const Model& cloud, const project::Project& p) {
  Model m;
  if (!cloud.shaft) throw std::logic_error("copy_cloud: only shaft sections");
  auto scene = std::make_unique<geometry::ShaftScene>(*cloud.shaft);
  if (scene->far_field_boundary >= 0 && p.domain.far_field_temperature)
    scene->boundaries[scene->far_field_boundary].temperature =
        project::TemperatureSchedule::fixed(*p.domain.far_field_temperature);
  m.shaft = scene.get();
  m.scene = std::move(scene);
  m.spacing = cloud.spacing;
  m.smoothing = cloud.smoothing;
  m.h = cloud.h;
  m.warnings = cloud.warnings;
  return m;
}

Model build_model(const project::Project& p) { return build_model(p, build_cloud(p)); }

namespace {
// Zones that start at their own temperature (a later one over an earlier
// one): each particle's enthalpy is the mean over its cell (a square of its
// volume, 8 x 8 points), so the heat stored at the start is the zones'
// heat to within the sampling of the cells an outline cuts.
void start_in_zones(Model& m, const project::Project& p) {
  constexpr int n = 8;
  const auto& zones = p.domain.initial_zones;
  const auto& P = m.particles();
  for (std::size_t i = 0; i < m.model->free_count(); ++i) {
    const auto& law = m.model->law_of(i);
    const double side = std::sqrt(P.volume[i]);
    double H = 0.0;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const double x = P.position[i][0] + side * ((a + 0.5) / n - 0.5);
        const double y = P.position[i][1] + side * ((b + 0.5) / n - 0.5);
        double T = p.domain.initial_temperature;
        for (auto zone = zones.rbegin(); zone != zones.rend(); ++zone)
          if (zone->contains(x, y)) {
            T = zone->temperature;
            break;
          }
        H += law.enthalpy(T);
      }
    m.model->set_enthalpy(i, H / (n * n));
  }
}

// The excavation's face: its particle added after the SPH pairs are built
// (so no pair or moment correction sees it) and the pairs it may join,
// from the lining's inner face to two of the ground's spacings beyond the
// excavation radius.
void join_face(const project::Project& p, Model& m, particles::PairWeights& pairs) {
  add_face_node(static_cast<geometry::ShaftScene&>(*m.scene), p);
  if (m.particles().graded())
    m.smoothing = sph::SmoothingLengths::of_particles(m.particles(), p.numerics.smoothing_ratio);
  const auto& P = m.particles();
  const double a = *std::get<project::ShaftSection>(p.geometry).shaft.excavation_radius;
  const double inner = a - (p.excavation->lining ? p.excavation->lining->thickness : 0.0);
  double s = P.spacing;
  for (std::size_t i = 0; i < P.n_free; ++i)
    if (std::abs(P.position[i].norm() - a) < 0.5) s = std::max(s, P.spacing_of(i));
  add_face_pairs(pairs, P, face_particle(*m.scene), inner, a + 2.0 * s);
}

// Which boundaries conduct no heat (their particles copy their reflections).
std::vector<bool> insulated_boundaries(const geometry::Scene& scene) {
  std::vector<bool> insulated;
  for (const auto& b : scene.boundaries) insulated.push_back(b.insulated);
  return insulated;
}
}  // namespace

Model build_model(const project::Project& p, Model cloud) {
  Model m = std::move(cloud);
  const double spacing = m.spacing;
  m.kernel = sph::make_kernel<2>(p.numerics.kernel);
  thermal::PhaseChangeLaw law(p.soil);
  const auto exchange = m.shaft ? pipes::make_pipe_exchange(std::get<project::ShaftSection>(p.geometry).pipe.model)
                                : nullptr;
  const bool pair_vectors = exchange && exchange->needs_pair_vectors();
  particles::PairWeights pairs =
      p.numerics.method == project::Method::pd
          ? pd::build_conduction_bonds(m.particles(), {p.numerics.horizon * spacing,
                                                       p.numerics.laplacian == project::LaplacianForm::renormalised})
          : sph::build_laplacian_pairs<2>(m.particles(), *m.kernel,
                                          {m.smoothing, p.numerics.laplacian, law.anisotropic(), m.particles().graded(),
                                           // the water's heat and the line sinks' fit need the pairs' vectors
                                           p.groundwater.has_value() || pair_vectors});
  if (exchange && exchange->couples()) exchange->couple(pairs, m.particles(), line_sink_nodes(*m.shaft));
  if (p.excavation) join_face(p, m, pairs);
  m.model = std::make_unique<thermal::ThermalModel>(
      m.particles().volume, m.particles().boundary, std::move(pairs), law, m.scene->boundaries,
      thermal::ConductionOptions{p.numerics.conductivity_mean, p.numerics.laplacian}, p.domain.initial_temperature,
      sph::build_wall_extrapolation(m.particles(), *m.kernel, m.smoothing, insulated_boundaries(*m.scene)));
  if (const auto* rect = std::get_if<project::Rectangle>(&p.geometry); rect && !rect->pores.empty()) {
    const auto& P = m.particles();
    m.pore_of = geometry::pore_membership(P.position, P.n_free, rect->pores);
    std::vector<std::uint8_t> material(P.size(), 0);
    for (std::size_t i = 0; i < P.n_free; ++i) material[i] = m.pore_of[i] >= 0 ? 1 : 0;
    m.model->set_materials({law, thermal::pore_water_law(p.pore_fluid)}, std::move(material),
                           p.domain.initial_temperature);
  }
  if (p.excavation) m.model->set_one_sided(face_boundary(*m.scene));
  if (!p.domain.initial_zones.empty()) start_in_zones(m, p);
  const double explicit_step = p.numerics.beta * m.h * m.h / m.model->max_diffusivity();
  if (p.numerics.integrator == project::IntegratorKind::implicit) {
    thermal::BackwardEulerSettings settings;
    settings.step_change = p.numerics.step_change;
    // Under flow each step moves about a latent heat (the coupled step's
    // step change): Newton stops at 1e-5 of it, still far below what the
    // step itself costs in accuracy, and is inexact, each linear solve
    // cutting the residual a hundredfold. What that changes and saves on
    // the seepage reference: bench/README.md, "Solver levers".
    if (p.groundwater && p.groundwater->flows_coupled()) {
      settings.newton_tolerance = 1e-5;
      settings.linear_tolerance = 1e-2;
    }
    m.integrator = std::make_unique<thermal::BackwardEuler>(settings, explicit_step);
  } else if (p.numerics.integrator == project::IntegratorKind::rkl2) {
    m.integrator = std::make_unique<thermal::SuperTimeStepping>(p.numerics.step_change, 5.0 * explicit_step);
  } else {
    m.integrator = std::make_unique<thermal::ExplicitEuler>(p.numerics.beta, m.h);
  }
  return m;
}

}  // namespace frostwall::freezing

#include "mechanics/engine.hpp"

#include <memory>
#include <nlohmann/json.hpp>

#include "freezing/heat_run.hpp"
#include "io/output_directory.hpp"
#include "mechanics/frost_results.hpp"
#include "mechanics/mechanics_run.hpp"
#include "post/isoline.hpp"

namespace frostwall::mechanics {

namespace {

// The solid's displacement (a vector) and damage; the thermal layers beyond
// held faces are not solid: 0 there.
void add_solid_fields(io::PointCloudFrame& frame, const MechanicsRun& mechanics) {
  const auto& u = mechanics.displacement();
  const auto damage = mechanics.damage();
  std::vector<double> vectors(3 * frame.points.size(), 0.0), phi(frame.points.size(), 0.0);
  for (std::size_t i = 0; i < damage.size(); ++i) {
    vectors[3 * i] = u[2 * i];
    vectors[3 * i + 1] = u[2 * i + 1];
    phi[i] = damage[i];
  }
  frame.vectors.emplace_back("displacement", std::move(vectors));
  frame.fields.emplace_back("damage", std::move(phi));
  const auto sigma = mechanics.stress();
  const char* names[3] = {"stress_xx", "stress_yy", "stress_xy"};
  for (int c = 0; c < 3; ++c) {
    std::vector<double> component(frame.points.size(), 0.0);
    for (std::size_t i = 0; i < sigma.size(); ++i) component[i] = sigma[i][c];
    frame.fields.emplace_back(names[c], std::move(component));
  }
}

// The length of the crack lines (the damage-0.4 isolines on the free
// particles' triangles, both faces of a crack band) of the solid now.
double crack_length(const Model& m, const MechanicsRun& mechanics) {
  const auto& P = m.particles();
  const post::IsolineMesh mesh(std::vector<particles::Vec<2>>(P.position.begin(), P.position.begin() + P.n_free),
                               2.5 * P.spacing);
  return crack_measure(mesh.isolines(mechanics.damage(), FrostResults::crack_damage), 0.0).length;
}

// The solid and the pores' frost, at their places in the heat run's loop:
// the pores' freezing is recorded before the solid re-equilibrates (each
// equilibrium then records its damage), the solid is brought to
// equilibrium at every output time before the sensors read it.
class SolidAndFrost : public freezing::RunExtension {
 public:
  SolidAndFrost(const project::Project& p, Model& m) : model_(m) {
    if (p.mechanics) mechanics_ = std::make_unique<MechanicsRun>(p, m);
    if (!m.pore_of.empty()) {
      frost_ = std::make_unique<FrostResults>(p, m, mechanics_.get());
      if (mechanics_) mechanics_->after_equilibrium = [this](double t) { frost_->after_equilibrium(t); };
    }
  }
  void after_step(const thermal::ThermalModel& m, double t) override {
    if (frost_) frost_->after_step(m, t);
    if (mechanics_) mechanics_->update(m, t, false);
  }
  void at_output(const thermal::ThermalModel& m, double t, bool is_snapshot, const std::filesystem::path& out,
                 const std::string& stem) override {
    if (mechanics_) mechanics_->update(m, t, is_snapshot);
    if (frost_ && is_snapshot) frost_->snapshot(t, out, stem);
  }
  void add_fields(io::PointCloudFrame& frame, const thermal::ThermalModel& m) const override {
    if (mechanics_) add_solid_fields(frame, *mechanics_);
    if (frost_) frost_->add_fields(frame, m);
  }
  void summarise(nlohmann::ordered_json& summary, const std::filesystem::path& out) const override {
    if (!frost_) return;
    const nlohmann::json pores = frost_->finish(out);
    for (const auto& [key, value] : pores.items()) summary[key] = value;
  }
  void run_facts(nlohmann::ordered_json& run) const override {
    if (!mechanics_) return;
    nlohmann::json facts = mechanics_->facts();
    // A plate without pores: its crack lines' length at the end (a porous plate's is in "damage" per snapshot).
    if (!frost_ && facts["critical_stretch"].is_number())
      facts["crack_length"] = facts["broken_bonds"].get<std::size_t>() > 0 ? crack_length(model_, *mechanics_) : 0.0;
    run["mechanics"] = facts;
  }
  const freezing::SolidView* solid() const override { return mechanics_.get(); }

 private:
  const Model& model_;
  std::unique_ptr<MechanicsRun> mechanics_;
  std::unique_ptr<FrostResults> frost_;
};

}  // namespace

bool runs(const project::Project& p) {
  const auto* rect = std::get_if<project::Rectangle>(&p.geometry);
  return p.numerics.method == project::Method::pd || p.mechanics || (rect && !rect->pores.empty());
}

summary::Summary run(const project::Project& p, const project::RunOptions& options) {
  io::check_output_directory(p.output.directory);
  Model built = freezing::build_model(p);
  SolidAndFrost extension(p, built);
  return freezing::run_heat(p, built, options, &extension);
}

}  // namespace frostwall::mechanics

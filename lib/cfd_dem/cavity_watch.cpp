#include "cfd_dem/cavity_watch.hpp"

#include <algorithm>
#include <mpi.h>

#include "dem/packing.hpp"

namespace frostwall::cfd_dem {

CavityWatch::CavityWatch(const project::CfdDem& c, const dem::LammpsSession& lammps) : c_(c), lammps_(lammps) {}

bool CavityWatch::inside(const double* x) const { return dem::in_cavity(c_, x); }

void CavityWatch::observe() {
  if (!c_.cavity) return;
  const int n = lammps_.local_count();
  const int* ids = lammps_.ids();
  double** x = lammps_.position();
  for (int i = 0; i < n; ++i) {
    if (!inside(x[i])) continue;
    const auto id = static_cast<std::size_t>(ids[i]);
    if (marked_.size() <= id) marked_.resize(id + 1, 0);
    marked_[id] = 1;
  }
}

double CavityWatch::count() {
  if (lammps_.ranks() > 1) {
    // Every rank's marks to the same length (ids are never reused), then joined.
    long size = static_cast<long>(marked_.size());
    MPI_Allreduce(MPI_IN_PLACE, &size, 1, MPI_LONG, MPI_MAX, MPI_COMM_WORLD);
    marked_.resize(static_cast<std::size_t>(size), 0);
    MPI_Allreduce(MPI_IN_PLACE, marked_.data(), static_cast<int>(size), MPI_UNSIGNED_CHAR, MPI_MAX, MPI_COMM_WORLD);
  }
  return static_cast<double>(std::count(marked_.begin(), marked_.end(), 1));
}

double CavityWatch::entered(int id) const {
  return static_cast<std::size_t>(id) < marked_.size() ? marked_[static_cast<std::size_t>(id)] : 0.0;
}

double CavityWatch::capacity() const {
  if (!c_.cavity) return 0.0;
  const double d = dem::mean_grain_diameter(c_.grains);
  const double r = c_.cavity->radius;
  return 0.64 * (r * r * r) / (0.125 * d * d * d);  // 0.64 (4/3 pi r^3) / (pi/6 d^3)
}

}  // namespace frostwall::cfd_dem

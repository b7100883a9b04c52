// Independent runs spread over MPI ranks. Under mpirun (Open MPI's
// OMPI_COMM_WORLD_SIZE above 1) rank r takes runs r, r + N, r + 2N, ...;
// then every rank learns every outcome, and rank 0 writes what joins them.
// A plain start never initialises MPI.
#pragma once

#include <string>
#include <vector>

namespace frostwall::study {

struct Ranks {
  int rank = 0, size = 1;
  int on_this_node = 1;  // ranks sharing this machine (they share its cores)
  bool first() const { return rank == 0; }
};

// The ranks this process runs among (MPI initialised when there are several).
Ranks world_ranks();

// Every rank's texts, in rank order, on every rank: texts[r] are rank r's.
std::vector<std::vector<std::string>> share_texts(const Ranks& ranks, const std::vector<std::string>& mine);

}  // namespace frostwall::study

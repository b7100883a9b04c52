#include "study/ranks.hpp"

#include <algorithm>
#include <cstdlib>
#include <mpi.h>
#include <string>

#include "dem/lammps_session.hpp"

namespace frostwall::study {

namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : fallback;
}

// One text from every rank, in rank order.
std::vector<std::string> all_gather(const std::string& text, int size) {
  int length = static_cast<int>(text.size());
  std::vector<int> lengths(size), offsets(size, 0);
  MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD);
  long total = 0;
  for (int r = 0; r < size; ++r) offsets[r] = static_cast<int>(total), total += lengths[r];
  std::string all(static_cast<std::size_t>(total), '\0');
  MPI_Allgatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, MPI_COMM_WORLD);
  std::vector<std::string> texts;
  for (int r = 0; r < size; ++r) texts.push_back(all.substr(offsets[r], lengths[r]));
  return texts;
}

}  // namespace

Ranks world_ranks() {
  Ranks r;
  if (env_int("OMPI_COMM_WORLD_SIZE", 1) <= 1) return r;
  dem::ensure_mpi();  // finalised at exit
  MPI_Comm_rank(MPI_COMM_WORLD, &r.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &r.size);
  r.on_this_node = std::max(1, env_int("OMPI_COMM_WORLD_LOCAL_SIZE", 1));
  return r;
}

std::vector<std::vector<std::string>> share_texts(const Ranks& ranks, const std::vector<std::string>& mine) {
  if (ranks.size <= 1) return {mine};
  // A count, then the texts one round at a time (ranks may hold different counts).
  const auto counts = all_gather(std::to_string(mine.size()), ranks.size);
  std::size_t rounds = 0;
  for (const auto& c : counts) rounds = std::max<std::size_t>(rounds, std::stoul(c));
  std::vector<std::vector<std::string>> texts(ranks.size);
  for (std::size_t k = 0; k < rounds; ++k) {
    const auto round = all_gather(k < mine.size() ? mine[k] : std::string(), ranks.size);
    for (int r = 0; r < ranks.size; ++r)
      if (k < std::stoul(counts[r])) texts[r].push_back(round[r]);
  }
  return texts;
}

}  // namespace frostwall::study

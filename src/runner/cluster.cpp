#include "runner/cluster.hpp"

#include <cstdlib>

#ifdef CREATURELAB_HAVE_MPI
#include <mpi.h>
#endif

namespace creaturelab::runner {

namespace {
bool launchedByMpirun() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE"); }
}  // namespace

Cluster::Cluster(int* argc, char*** argv) {
#ifdef CREATURELAB_HAVE_MPI
  if (!launchedByMpirun()) return;
  MPI_Init(argc, argv);
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#else
  (void)argc;
  (void)argv;
  (void)launchedByMpirun;
#endif
}

Cluster::~Cluster() {
#ifdef CREATURELAB_HAVE_MPI
  if (initialised_) MPI_Finalize();
#endif
}

void Cluster::barrier() const {
#ifdef CREATURELAB_HAVE_MPI
  if (initialised_) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

int Cluster::sumOnRoot(int value) const {
#ifdef CREATURELAB_HAVE_MPI
  if (initialised_) {
    int sum = 0;
    MPI_Reduce(&value, &sum, 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
    return rank_ == 0 ? sum : value;
  }
#endif
  return value;
}

int Cluster::broadcastFromRoot(int value) const {
#ifdef CREATURELAB_HAVE_MPI
  if (initialised_) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
#endif
  return value;
}

void Cluster::abort(int code) const {
#ifdef CREATURELAB_HAVE_MPI
  if (initialised_) MPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

bool Cluster::builtWithMpi() {
#ifdef CREATURELAB_HAVE_MPI
  return true;
#else
  return false;
#endif
}

}  // namespace creaturelab::runner

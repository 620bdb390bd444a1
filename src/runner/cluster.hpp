#pragma once
// The MPI ranks this process belongs to, if it was started by mpirun (Open MPI sets
// OMPI_COMM_WORLD_SIZE; PMI_SIZE for Slurm/Hydra). Otherwise one rank, and MPI is not touched,
// so a plain `creaturelab run` never pays for MPI start-up. RAII: finalises on destruction.
namespace creaturelab::runner {

class Cluster {
 public:
  Cluster(int* argc, char*** argv);
  ~Cluster();
  Cluster(const Cluster&) = delete;
  Cluster& operator=(const Cluster&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  void barrier() const;
  // Sum of `value` over the ranks, on rank 0 (other ranks get their own value back).
  int sumOnRoot(int value) const;
  // Rank 0's `value` on every rank: a decision rank 0 alone can take (the folder lock).
  int broadcastFromRoot(int value) const;
  // Ends every rank with `code`: an error after the ranks split the work, where waiting at the
  // next barrier would hang the others.
  [[noreturn]] void abort(int code) const;
  static bool builtWithMpi();

 private:
  int rank_ = 0, size_ = 1;
  bool initialised_ = false;
};

}  // namespace creaturelab::runner

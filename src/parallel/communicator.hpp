#pragma once
// Communicator: the ranks of a run and the few collective operations the engine needs, over Open
// MPI when built with MPDEM_MPI and MPI was initialised (MpiSession), otherwise one rank whose
// messages to itself are copies. No MPI header here, so programs linking the engine need none.
//
// Every collective is called by all ranks in the same order; reductions combine the ranks'
// values in rank order (MPI's built-in reductions on doubles are not guaranteed to), so a run
// on N ranks takes the same decisions on every rank and in every run.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace mpdem {

class Communicator {
 public:
  // The ranks of the whole run (MPI_COMM_WORLD), or one rank when MPI is absent or not initialised.
  static const Communicator& world();
  // One rank, whatever the process's MPI state: a serial run inside an MPI program (tests).
  static const Communicator& single();

  // The first n ranks of this one as a communicator of their own, on those ranks; null on the
  // others (tests: a checkpoint written on n ranks, resumed on all). Collective.
  std::shared_ptr<const Communicator> first_ranks(int n) const;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool serial() const { return size_ == 1; }

  // Element-wise reductions over the ranks (every rank passes as many values), the result on
  // every rank.
  void sum(std::span<double> v) const;
  void max(std::span<double> v) const;
  void min(std::span<double> v) const;
  double sum(double v) const;
  double max(double v) const;
  double min(double v) const;
  std::uint64_t sum(std::uint64_t v) const;
  bool any(bool v) const;  // true on every rank when it is true on some rank

  // Sends `out` to rank `to` and receives one message from rank `from` (either may be this rank;
  // -1: none, nothing sent or an empty message received). Uses tags `tag` and `tag + 1`.
  std::vector<std::byte> exchange(int to, std::span<const std::byte> out, int from, int tag) const;
  // As exchange, when this rank knows the length of the message it receives (`n_in` bytes; 0
  // when `from` is -1): the bytes alone, without their length sent ahead. A message of another
  // length is an error (std::runtime_error when shorter, MPI's truncation error when longer).
  // Uses tag `tag + 1`, as exchange's bytes.
  std::vector<std::byte> exchange_known(int to, std::span<const std::byte> out, int from, std::size_t n_in,
                                        int tag) const;
  // Several exchange_known at once: every message posted, then all waited for together (the two
  // directions of a halo stage travel at the same time instead of one after the other). The k-th
  // result is transfers[k]'s message; a transfer with this rank at both ends is a copy, as in
  // exchange_known. Tags must tell apart the transfers between the same two ranks.
  struct KnownTransfer {
    int to = -1;
    std::span<const std::byte> out;
    int from = -1;
    std::size_t n_in = 0;  // bytes
    int tag = 0;           // the message uses tag + 1, as exchange_known's
  };
  std::vector<std::vector<std::byte>> exchange_known(std::span<const KnownTransfer> transfers) const;
  // Every rank's bytes, in rank order, on every rank.
  std::vector<std::vector<std::byte>> all_gather(std::span<const std::byte> mine) const;
  // The same, when every rank gives the same number of bytes (fixed-size values): rank r's at
  // r * mine.size(), with one collective instead of all_gather's two (their lengths first).
  std::vector<std::byte> all_gather_fixed(std::span<const std::byte> mine) const;
  // Every rank's bytes, in rank order, on `root` (empty elsewhere).
  std::vector<std::vector<std::byte>> gather(std::span<const std::byte> mine, int root) const;
  // Root's bytes on every rank.
  void broadcast(std::vector<std::byte>& bytes, int root) const;
  void barrier() const;
  // Ends every rank's process with exit code `code` (after a failure that one rank alone saw).
  [[noreturn]] void abort(int code) const;

 private:
  Communicator(int rank, int size, int handle = 0) : rank_(rank), size_(size), handle_(handle) {}
  int rank_ = 0;
  int size_ = 1;
  int handle_ = 0;  // MPI communicator as a Fortran handle (MPI_Comm_c2f); unused on one rank
  friend class MpiSession;
};

// Initialises MPI for the process's lifetime (the `mpdem` command's main), when built with MPI
// and started by an MPI launcher (mpirun, srun); a no-op otherwise, so a plain `mpdem run` needs
// no MPI runtime. Threads: only the thread that called it makes MPI calls (FUNNELED).
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  static bool built_with_mpi();
  static bool launched_by_mpi();  // the environment of an MPI launcher
};

}  // namespace mpdem

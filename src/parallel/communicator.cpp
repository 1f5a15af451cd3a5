#include "parallel/communicator.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <thread>
#include <utility>

#ifdef MPDEM_HAVE_MPI
#include <mpi.h>
#endif

namespace mpdem {

namespace {
// Combines every rank's copy of v element-wise in rank order: the same bits on every rank.
// Every rank passes as many values (the callers reduce values of a fixed layout).
template <class Op>
void reduce_in_rank_order(const Communicator& c, std::span<double> v, Op op) {
  if (c.serial() || v.empty()) return;
  const auto all = c.all_gather_fixed(std::as_bytes(v));
  const std::size_t ranks = static_cast<std::size_t>(c.size()), each = v.size() * sizeof(double);
  for (std::size_t k = 0; k < v.size(); ++k) {
    double acc = 0.0;
    for (std::size_t r = 0; r < ranks; ++r) {
      double x = 0.0;
      std::memcpy(&x, all.data() + r * each + k * sizeof(double), sizeof(double));
      acc = r == 0 ? x : op(acc, x);
    }
    v[k] = acc;
  }
}

bool mpi_running() {
#ifdef MPDEM_HAVE_MPI
  int init = 0, fin = 0;
  MPI_Initialized(&init);
  MPI_Finalized(&fin);
  return init != 0 && fin == 0;
#else
  return false;
#endif
}

#ifdef MPDEM_HAVE_MPI
// The communicator of a Fortran handle (an int, so that the header needs no MPI type).
MPI_Comm mpi_comm(int handle) { return MPI_Comm_f2c(handle); }

// Waits until every request is complete (statuses: one per request, or MPI_STATUSES_IGNORE).
// MPI's own waits poll without pause, so a waiting rank holds its core for whole time slices;
// where the cores are shared (other programs, more ranks than cores) the rank it waits for may be
// waiting for a core, and a small scene crawled (docs/parallel.md, "Shared machines"). So: poll
// for kSpin, which covers the usual waits of ranks that each have a core (a shorter spin gave the
// core away too often and was slower), then sleep kNap between polls, which leaves the core to
// the others. All calls are non-blocking ones completed here.
void complete(std::span<MPI_Request> requests, MPI_Status* statuses) {
  constexpr auto kSpin = std::chrono::microseconds(200);
  constexpr auto kNap = std::chrono::microseconds(20);  // the kernel adds its timer slack (50 us)
  const int n = static_cast<int>(requests.size());
  int done = 0;
  MPI_Testall(n, requests.data(), &done, statuses);
  if (done) return;
  const auto spin_end = std::chrono::steady_clock::now() + kSpin;
  while (std::chrono::steady_clock::now() < spin_end) {
    MPI_Testall(n, requests.data(), &done, statuses);
    if (done) return;
  }
  for (;;) {
    std::this_thread::sleep_for(kNap);
    MPI_Testall(n, requests.data(), &done, statuses);
    if (done) return;
  }
}
void complete(MPI_Request& request) { complete(std::span<MPI_Request>(&request, 1), MPI_STATUSES_IGNORE); }

int checked_count(std::size_t n) {
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("an MPI message of more than 2^31 bytes");
  return static_cast<int>(n);
}
#endif
}  // namespace

const Communicator& Communicator::single() {
  static const Communicator one(0, 1);
  return one;
}

const Communicator& Communicator::world() {
  const Communicator& serial = single();
#ifdef MPDEM_HAVE_MPI
  if (mpi_running()) {
    static const Communicator world = [] {
      int rank = 0, size = 1;
      MPI_Comm_rank(MPI_COMM_WORLD, &rank);
      MPI_Comm_size(MPI_COMM_WORLD, &size);
      return Communicator(rank, size, static_cast<int>(MPI_Comm_c2f(MPI_COMM_WORLD)));
    }();
    return world;
  }
#endif
  return serial;
}

std::shared_ptr<const Communicator> Communicator::first_ranks(int n) const {
  if (n < 1 || n > size_) throw std::invalid_argument("Communicator::first_ranks: n is not in [1, size]");
  if (serial()) return std::make_shared<const Communicator>(*this);
#ifdef MPDEM_HAVE_MPI
  MPI_Comm sub = MPI_COMM_NULL;
  MPI_Comm_split(mpi_comm(handle_), rank_ < n ? 0 : MPI_UNDEFINED, rank_, &sub);
  if (sub == MPI_COMM_NULL) return nullptr;
  // Freed with the last reference (before MPI_Finalize: the callers hold it in a scope).
  return {new Communicator(rank_, n, static_cast<int>(MPI_Comm_c2f(sub))), [](const Communicator* c) {
            MPI_Comm h = MPI_Comm_f2c(c->handle_);
            if (mpi_running()) MPI_Comm_free(&h);
            delete c;
          }};
#else
  return nullptr;
#endif
}

void Communicator::sum(std::span<double> v) const {
  reduce_in_rank_order(*this, v, [](double a, double b) { return a + b; });
}
void Communicator::max(std::span<double> v) const {
  // NaN wins, so that a non-finite value on one rank is seen by all.
  reduce_in_rank_order(*this, v, [](double a, double b) { return a != a || b != b ? a + b : std::max(a, b); });
}
void Communicator::min(std::span<double> v) const {
  reduce_in_rank_order(*this, v, [](double a, double b) { return a != a || b != b ? a + b : std::min(a, b); });
}
double Communicator::sum(double v) const {
  sum(std::span<double>(&v, 1));
  return v;
}
double Communicator::max(double v) const {
  max(std::span<double>(&v, 1));
  return v;
}
double Communicator::min(double v) const {
  min(std::span<double>(&v, 1));
  return v;
}
std::uint64_t Communicator::sum(std::uint64_t v) const {
  if (serial()) return v;
  const auto all = all_gather_fixed(std::as_bytes(std::span<const std::uint64_t>(&v, 1)));
  std::uint64_t s = 0;
  for (std::size_t at = 0; at < all.size(); at += sizeof s) {
    std::uint64_t x = 0;
    std::memcpy(&x, all.data() + at, sizeof x);
    s += x;
  }
  return s;
}
bool Communicator::any(bool v) const { return sum(std::uint64_t{v ? 1u : 0u}) > 0; }

std::vector<std::byte> Communicator::exchange(int to, std::span<const std::byte> out, int from, int tag) const {
  const bool to_self = to == rank_ || to < 0, from_self = from == rank_ || from < 0;
  if (serial() || (to_self && from_self)) {
    // Without another rank, a message sent to this rank is the one received from it.
    if ((to == rank_) != (from == rank_) || (serial() && (to > 0 || from > 0)))
      throw std::logic_error("Communicator::exchange: a message to this rank must be received by it");
    if (from < 0) return {};
    return {out.begin(), out.end()};
  }
#ifdef MPDEM_HAVE_MPI
  // Sizes first, then the bytes: a receiver cannot know a message's length in advance.
  const int dest = to < 0 ? MPI_PROC_NULL : to, source = from < 0 ? MPI_PROC_NULL : from;
  std::uint64_t n_out = out.size(), n_in = 0;
  const MPI_Comm comm = mpi_comm(handle_);
  MPI_Request r[2];
  MPI_Irecv(&n_in, 1, MPI_UINT64_T, source, tag, comm, &r[0]);
  MPI_Isend(&n_out, 1, MPI_UINT64_T, dest, tag, comm, &r[1]);
  complete(r, MPI_STATUSES_IGNORE);
  if (source == MPI_PROC_NULL) n_in = 0;
  std::vector<std::byte> in(static_cast<std::size_t>(n_in));
  MPI_Irecv(in.data(), checked_count(in.size()), MPI_BYTE, source, tag + 1, comm, &r[0]);
  MPI_Isend(out.data(), checked_count(out.size()), MPI_BYTE, dest, tag + 1, comm, &r[1]);
  complete(r, MPI_STATUSES_IGNORE);
  return in;
#else
  (void)tag;
  throw std::logic_error("Communicator::exchange: built without MPI");
#endif
}

std::vector<std::byte> Communicator::exchange_known(int to, std::span<const std::byte> out, int from, std::size_t n_in,
                                                    int tag) const {
  const KnownTransfer t{to, out, from, n_in, tag};
  return std::move(exchange_known(std::span<const KnownTransfer>(&t, 1))[0]);
}

std::vector<std::vector<std::byte>> Communicator::exchange_known(std::span<const KnownTransfer> transfers) const {
  std::vector<std::vector<std::byte>> in(transfers.size());
  const auto local = [&](const KnownTransfer& t) {
    return serial() || ((t.to == rank_ || t.to < 0) && (t.from == rank_ || t.from < 0));
  };
  for (std::size_t k = 0; k < transfers.size(); ++k)
    if (const KnownTransfer& t = transfers[k]; local(t)) {
      in[k] = exchange(t.to, t.out, t.from, t.tag);  // a copy
      if (in[k].size() != t.n_in) throw std::runtime_error("Communicator::exchange_known: a message of another length");
    }
  if (serial()) return in;
#ifdef MPDEM_HAVE_MPI
  std::vector<MPI_Request> requests;
  std::vector<std::size_t> received;  // transfer of each receive request
  for (std::size_t k = 0; k < transfers.size(); ++k) {
    const KnownTransfer& t = transfers[k];
    if (local(t)) continue;
    if (t.from < 0 && t.n_in != 0) throw std::logic_error("Communicator::exchange_known: bytes expected from no rank");
    if (t.from < 0) continue;
    in[k].resize(t.n_in);
    requests.emplace_back();
    received.push_back(k);
    MPI_Irecv(in[k].data(), checked_count(t.n_in), MPI_BYTE, t.from, t.tag + 1, mpi_comm(handle_), &requests.back());
  }
  const std::size_t n_recv = requests.size();
  for (const KnownTransfer& t : transfers) {
    if (local(t) || t.to < 0) continue;
    requests.emplace_back();
    // MPI_Isend's buffer is const since MPI 3.
    MPI_Isend(t.out.data(), checked_count(t.out.size()), MPI_BYTE, t.to, t.tag + 1, mpi_comm(handle_),
              &requests.back());
  }
  std::vector<MPI_Status> status(requests.size());
  complete(requests, status.data());
  for (std::size_t r = 0; r < n_recv; ++r) {
    int got = 0;
    MPI_Get_count(&status[r], MPI_BYTE, &got);
    if (static_cast<std::size_t>(got) != transfers[received[r]].n_in)
      throw std::runtime_error("Communicator::exchange_known: a message of another length");
  }
  return in;
#else
  throw std::logic_error("Communicator::exchange_known: built without MPI");
#endif
}

std::vector<std::byte> Communicator::all_gather_fixed(std::span<const std::byte> mine) const {
  if (serial()) return {mine.begin(), mine.end()};
#ifdef MPDEM_HAVE_MPI
  const int n = checked_count(mine.size());
  std::vector<std::byte> all(mine.size() * static_cast<std::size_t>(size_));
  MPI_Request req = MPI_REQUEST_NULL;
  MPI_Iallgather(mine.data(), n, MPI_BYTE, all.data(), n, MPI_BYTE, mpi_comm(handle_), &req);
  complete(req);
  return all;
#else
  throw std::logic_error("Communicator::all_gather_fixed: built without MPI");
#endif
}

std::vector<std::vector<std::byte>> Communicator::all_gather(std::span<const std::byte> mine) const {
  if (serial()) return {std::vector<std::byte>(mine.begin(), mine.end())};
#ifdef MPDEM_HAVE_MPI
  const int n = checked_count(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(size_)), displs(static_cast<std::size_t>(size_));
  MPI_Request req = MPI_REQUEST_NULL;
  MPI_Iallgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, mpi_comm(handle_), &req);
  complete(req);
  std::size_t total = 0;
  for (int r = 0; r < size_; ++r) {
    displs[static_cast<std::size_t>(r)] = checked_count(total);
    total += static_cast<std::size_t>(counts[static_cast<std::size_t>(r)]);
  }
  std::vector<std::byte> all(total);
  MPI_Iallgatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, mpi_comm(handle_),
                  &req);
  complete(req);
  std::vector<std::vector<std::byte>> out(static_cast<std::size_t>(size_));
  for (std::size_t r = 0; r < out.size(); ++r) {
    const auto* b = all.data() + displs[r];
    out[r].assign(b, b + counts[r]);
  }
  return out;
#else
  throw std::logic_error("Communicator::all_gather: built without MPI");
#endif
}

std::vector<std::vector<std::byte>> Communicator::gather(std::span<const std::byte> mine, int root) const {
  if (serial()) return {std::vector<std::byte>(mine.begin(), mine.end())};
#ifdef MPDEM_HAVE_MPI
  const int n = checked_count(mine.size());
  const bool at_root = rank_ == root;
  std::vector<int> counts(at_root ? static_cast<std::size_t>(size_) : 0), displs(counts.size());
  MPI_Request req = MPI_REQUEST_NULL;
  MPI_Igather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, root, mpi_comm(handle_), &req);
  complete(req);
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    displs[r] = checked_count(total);
    total += static_cast<std::size_t>(counts[r]);
  }
  std::vector<std::byte> all(total);
  MPI_Igatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, root, mpi_comm(handle_),
               &req);
  complete(req);
  std::vector<std::vector<std::byte>> out(counts.size());
  for (std::size_t r = 0; r < out.size(); ++r) {
    const auto* b = all.data() + displs[r];
    out[r].assign(b, b + counts[r]);
  }
  return out;
#else
  (void)root;
  throw std::logic_error("Communicator::gather: built without MPI");
#endif
}

void Communicator::broadcast(std::vector<std::byte>& bytes, int root) const {
  if (serial()) return;
#ifdef MPDEM_HAVE_MPI
  std::uint64_t n = bytes.size();
  MPI_Request req = MPI_REQUEST_NULL;
  MPI_Ibcast(&n, 1, MPI_UINT64_T, root, mpi_comm(handle_), &req);
  complete(req);
  bytes.resize(static_cast<std::size_t>(n));
  MPI_Ibcast(bytes.data(), checked_count(bytes.size()), MPI_BYTE, root, mpi_comm(handle_), &req);
  complete(req);
#else
  (void)root;
#endif
}

void Communicator::barrier() const {
#ifdef MPDEM_HAVE_MPI
  if (serial()) return;
  MPI_Request req = MPI_REQUEST_NULL;
  MPI_Ibarrier(mpi_comm(handle_), &req);
  complete(req);
#endif
}

void Communicator::abort(int code) const {
#ifdef MPDEM_HAVE_MPI
  if (!serial()) MPI_Abort(mpi_comm(handle_), code);
#endif
  std::exit(code);
}

MpiSession::MpiSession([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
#ifdef MPDEM_HAVE_MPI
  if (!launched_by_mpi()) return;
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
#endif
}

bool MpiSession::launched_by_mpi() {
  // Open MPI's mpirun, PMIx (Slurm's srun --mpi=pmix) and PMI-1/2 launchers set these.
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

MpiSession::~MpiSession() {
#ifdef MPDEM_HAVE_MPI
  if (mpi_running()) MPI_Finalize();
#endif
}

bool MpiSession::built_with_mpi() {
#ifdef MPDEM_HAVE_MPI
  return true;
#else
  return false;
#endif
}

}  // namespace mpdem

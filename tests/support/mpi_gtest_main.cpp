// main() of the tests run under mpirun (tests/parallel/mpi_*.cpp): MPI for the process, one
// result printer (rank 0), other ranks' failures printed with their rank, and one verdict: the
// exit code is 1 on every rank when a test failed on any rank.
#include <gtest/gtest.h>

#include <cstdio>

#include "parallel/communicator.hpp"

namespace {
class RankFailurePrinter : public ::testing::EmptyTestEventListener {
 public:
  explicit RankFailurePrinter(int rank) : rank_(rank) {}
  void OnTestPartResult(const ::testing::TestPartResult& r) override {
    if (r.failed())
      std::fprintf(stderr, "[rank %d] %s:%d: %s\n", rank_, r.file_name() ? r.file_name() : "?", r.line_number(),
                   r.summary());
  }

 private:
  int rank_;
};
}  // namespace

int main(int argc, char** argv) {
  mpdem::MpiSession mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  const mpdem::Communicator& comm = mpdem::Communicator::world();
  if (comm.rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new RankFailurePrinter(comm.rank()));
  }
  const int rc = RUN_ALL_TESTS();
  return comm.any(rc != 0) ? 1 : 0;
}

#pragma once
// A temporary folder every rank of a test run under mpirun names alike (rank 0 makes it and sends
// its path to the others); removed by rank 0 when the object goes (call it on every rank).
#include <unistd.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "parallel/communicator.hpp"

namespace mpdem::test {

struct SharedTempDir {
  const Communicator& comm;
  std::filesystem::path path;
  SharedTempDir(const Communicator& c, const std::string& name) : comm(c) {
    std::string dir;
    if (comm.rank() == 0) {
      dir = (std::filesystem::temp_directory_path() / ("mpdem_" + name + "_" + std::to_string(::getpid()))).string();
      std::filesystem::remove_all(dir);
      std::filesystem::create_directories(dir);
    }
    std::vector<std::byte> bytes(reinterpret_cast<const std::byte*>(dir.data()),
                                 reinterpret_cast<const std::byte*>(dir.data()) + dir.size());
    comm.broadcast(bytes, 0);
    path = std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  }
  ~SharedTempDir() {
    comm.barrier();
    if (comm.rank() == 0) std::filesystem::remove_all(path);
  }
  SharedTempDir(const SharedTempDir&) = delete;
  SharedTempDir& operator=(const SharedTempDir&) = delete;
};

}  // namespace mpdem::test

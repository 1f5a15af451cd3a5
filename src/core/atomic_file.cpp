#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

namespace mpdem {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error("cannot write '" + path.string() + "': " + what);
}

// Forces the file's data to disk before the rename, so after a power loss the final name
// holds either the old or the new complete file. fsync works on a read-only descriptor on Linux.
void sync_file(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;  // the data is already written; syncing is best effort
  (void)::fsync(fd);
  ::close(fd);
}

}  // namespace

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  std::filesystem::path tmp = path;
  tmp += ".tmp-" + std::to_string(static_cast<long long>(::getpid()));
  return tmp;
}

void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& body,
                           Durability durability) {
  const std::filesystem::path tmp = temporary_path_for(path);
  auto discard = [&tmp] {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);  // nothing more to do if even this fails
  };
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) fail(path, "cannot create temporary file '" + tmp.string() + "' (" + std::strerror(errno) + ")");
    try {
      body(out);
    } catch (...) {
      out.close();
      discard();
      throw;
    }
    out.flush();
    const bool ok = static_cast<bool>(out);
    out.close();
    if (!ok || out.fail()) {
      discard();
      fail(path, "write error (disk full?)");
    }
  }
  if (durability == Durability::power_loss) sync_file(tmp);
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    discard();
    fail(path, "cannot rename temporary file: " + ec.message());
  }
}

void append_complete_lines(const std::filesystem::path& path, std::string_view text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, std::strerror(errno));
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      fail(path, std::strerror(err));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) fail(path, std::strerror(errno));
}

}  // namespace mpdem

#include "io/checkpoint_format.hpp"

#include <cstring>
#include <stdexcept>

#include "core/crc32.hpp"

namespace mpdem {

namespace {
constexpr char kMagic[8] = {'M', 'P', 'D', 'E', 'M', 'C', 'K', 'P'};
// Format 2 and before: "MPDEMCK" and the version as one character.
constexpr char kOldMagic[7] = {'M', 'P', 'D', 'E', 'M', 'C', 'K'};

template <class T>
void put(std::vector<char>& out, const T& v) {
  const std::size_t at = out.size();
  out.resize(at + sizeof(T));
  std::memcpy(out.data() + at, &v, sizeof(T));
}
}  // namespace

CheckpointWriter::CheckpointWriter() {
  bytes_.assign(kMagic, kMagic + sizeof(kMagic));
  put(bytes_, kCheckpointFormat);
}

void CheckpointWriter::add(std::string_view name, const std::vector<char>& payload) {
  if (name.empty() || name.size() > 0xFFFFu) throw std::logic_error("checkpoint section name");
  put(bytes_, static_cast<std::uint16_t>(name.size()));
  bytes_.insert(bytes_.end(), name.begin(), name.end());
  put(bytes_, static_cast<std::uint64_t>(payload.size()));
  bytes_.insert(bytes_.end(), payload.begin(), payload.end());
  put(bytes_, crc32(payload.data(), payload.size(), crc32(name.data(), name.size())));
}

CheckpointReader::CheckpointReader(const char* data, std::size_t size) {
  const char* p = data;
  const char* end = data + size;
  const auto left = [&] { return static_cast<std::size_t>(end - p); };
  if (size >= 8 && std::memcmp(data, kOldMagic, 7) == 0 && data[7] != 'P')
    throw std::runtime_error(std::string("it has checkpoint format ") + data[7] + ", this mpdem reads format " +
                             std::to_string(kCheckpointFormat) +
                             " only (written by another mpdem version); start the run again from its scene");
  if (size < 12 || std::memcmp(data, kMagic, 8) != 0) throw std::runtime_error("not an mpdem checkpoint");
  std::uint32_t version = 0;
  std::memcpy(&version, data + 8, sizeof(version));
  if (version != kCheckpointFormat)
    throw std::runtime_error("it has checkpoint format " + std::to_string(version) + ", this mpdem reads format " +
                             std::to_string(kCheckpointFormat) +
                             " only (written by another mpdem version); start the run again from its scene");
  p += 12;
  while (p < end) {
    std::uint16_t name_size = 0;
    std::uint64_t payload_size = 0;
    if (left() < sizeof(name_size)) throw std::runtime_error("truncated (a section is cut short)");
    std::memcpy(&name_size, p, sizeof(name_size));
    p += sizeof(name_size);
    if (left() < name_size + sizeof(payload_size)) throw std::runtime_error("truncated (a section is cut short)");
    const std::string name(p, name_size);
    p += name_size;
    std::memcpy(&payload_size, p, sizeof(payload_size));
    p += sizeof(payload_size);
    if (left() < sizeof(std::uint32_t) || payload_size > left() - sizeof(std::uint32_t))
      throw std::runtime_error("truncated (section '" + name + "' is cut short)");
    const char* payload = p;
    p += payload_size;
    std::uint32_t stored = 0;
    std::memcpy(&stored, p, sizeof(stored));
    p += sizeof(stored);
    if (crc32(payload, payload_size, crc32(name.data(), name.size())) != stored)
      throw std::runtime_error("section '" + name + "' is damaged (its checksum does not match)");
    if (!sections_.emplace(name, Section{payload, static_cast<std::size_t>(payload_size), false}).second)
      throw std::runtime_error("section '" + name + "' appears twice");
  }
}

BinaryReader CheckpointReader::open(const std::string& name) {
  const auto it = sections_.find(name);
  if (it == sections_.end()) throw std::runtime_error("the checkpoint has no section '" + name + "'");
  it->second.opened = true;
  return BinaryReader(it->second.data, it->second.size);
}

void CheckpointReader::done(const std::string& name, const BinaryReader& r) {
  if (!r.at_end()) throw std::runtime_error("section '" + name + "' holds more data than this mpdem reads");
}

void CheckpointReader::finish() {
  for (const auto& [name, s] : sections_)
    if (!s.opened) throw std::runtime_error("section '" + name + "' is not known to this mpdem");
}

}  // namespace mpdem

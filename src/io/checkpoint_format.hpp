#pragma once
// The checkpoint file format (docs/output.md "Checkpoints"): versioned and made of named
// sections, so that adding a field adds a section instead of silently shifting the bytes after
// it, and a damaged or truncated file is refused instead of resumed.
//
//   magic "MPDEMCKP" (8 bytes), format version (u32)
//   sections until the end of the file, each:
//     name length (u16), name, payload length (u64), payload, CRC-32 of name and payload (u32)
//
// The payloads are BinaryWriter streams (core/binary_stream.hpp), native byte order.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/binary_stream.hpp"

namespace mpdem {

// 13: the scene fingerprint names contact laws by their list names and keys (contact/laws/), so a
// format-12 file would fail its fingerprint with a misleading "contact laws changed".
// 14: particle arrays body and member (clumps), and the bodies' sections bodies/<array>.
// 15: PairHistory records gain the cohesion state (96 bytes); the optional "cohesion" section.
inline constexpr std::uint32_t kCheckpointFormat = 15;

class CheckpointWriter {
 public:
  CheckpointWriter();
  // Appends a section whose payload `write(BinaryWriter&)` produces.
  template <class F>
  void section(std::string_view name, F&& write) {
    BinaryWriter w;
    write(w);
    add(name, w.bytes());
  }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  void add(std::string_view name, const std::vector<char>& payload);
  std::vector<char> bytes_;
};

class CheckpointReader {
 public:
  // Checks the magic, the version and every section's framing and checksum up front; throws
  // std::runtime_error saying what is wrong (another format version, a damaged section by name,
  // a truncated file, bytes after the last section).
  CheckpointReader(const char* data, std::size_t size);
  bool has(const std::string& name) const { return sections_.count(name) > 0; }
  // The payload of a section ("the checkpoint has no section 'x'" when absent). Each section is
  // to be read once, completely.
  BinaryReader open(const std::string& name);
  // Every section was opened and read to its end: otherwise the checkpoint holds data this
  // program does not know (or misreads), and is refused naming the section.
  void finish();
  // Marks an opened section as read to its end (BinaryReader::at_end checked by the caller).
  void done(const std::string& name, const BinaryReader& r);

 private:
  struct Section {
    const char* data = nullptr;
    std::size_t size = 0;
    bool opened = false;
  };
  std::map<std::string, Section> sections_;
};

}  // namespace mpdem

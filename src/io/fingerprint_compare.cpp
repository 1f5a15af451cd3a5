// Storing a scene fingerprint in a checkpoint and comparing it with a scene's
// (io/scene_fingerprint.hpp): what differs, part by part, with the first differing item.
#include <algorithm>
#include <string>
#include <vector>

#include "io/scene_fingerprint.hpp"

namespace mpdem {

namespace {

std::size_t entry_count(const FingerprintPart& p, std::size_t items) {
  return items > p.fixed ? (items - p.fixed) / std::max<std::size_t>(p.per_entry, 1) : 0;
}

std::string part_difference(const FingerprintPart& ck, const FingerprintPart& sc) {
  if (ck.items == sc.items && ck.fixed == sc.fixed && ck.per_entry == sc.per_entry) return "";
  if (ck.fixed != sc.fixed || ck.per_entry != sc.per_entry) return sc.name + " (its layout)";
  const std::size_t n = std::min(ck.items.size(), sc.items.size());
  const std::size_t k = static_cast<std::size_t>(
      std::mismatch(ck.items.begin(), ck.items.begin() + static_cast<long>(n), sc.items.begin()).first -
      ck.items.begin());
  std::string what;
  if (k < n) what = sc.label ? sc.label(k) : "item " + std::to_string(k + 1);
  if (ck.items.size() != sc.items.size()) {
    if (!what.empty()) what += "; ";
    what += std::to_string(entry_count(sc, sc.items.size())) + " " + sc.entries + ", the checkpoint's scene had " +
            std::to_string(entry_count(ck, ck.items.size()));
  }
  return sc.name + " (" + what + ")";
}

}  // namespace

void save_fingerprint(BinaryWriter& w, const SceneFingerprint& f) {
  w.value<std::uint64_t>(f.parts.size());
  for (const FingerprintPart& p : f.parts) {
    w.string(p.name);
    w.value<std::uint64_t>(p.fixed);
    w.value<std::uint64_t>(p.per_entry);
    w.vector(p.items);
  }
}

SceneFingerprint load_fingerprint(BinaryReader& r) {
  SceneFingerprint f;
  const auto n = r.value<std::uint64_t>();
  for (std::uint64_t k = 0; k < n; ++k) {
    FingerprintPart p;
    p.name = r.string();
    p.fixed = r.value<std::uint64_t>();
    p.per_entry = r.value<std::uint64_t>();
    p.items = r.vector<std::uint64_t>();
    f.parts.push_back(std::move(p));
  }
  return f;
}

std::string fingerprint_difference(const SceneFingerprint& checkpoint, const SceneFingerprint& scene) {
  std::vector<std::string> differ;
  for (const FingerprintPart& sc : scene.parts) {
    const auto ck = std::find_if(checkpoint.parts.begin(), checkpoint.parts.end(),
                                 [&](const FingerprintPart& p) { return p.name == sc.name; });
    if (ck == checkpoint.parts.end()) differ.push_back(sc.name + " (not in the checkpoint)");
    else if (std::string d = part_difference(*ck, sc); !d.empty()) differ.push_back(std::move(d));
  }
  // Parts only some scenes have (bonds): the checkpoint's scene had one this scene lacks.
  for (const FingerprintPart& ck : checkpoint.parts)
    if (std::none_of(scene.parts.begin(), scene.parts.end(),
                     [&](const FingerprintPart& p) { return p.name == ck.name; }))
      differ.push_back(ck.name + " (in the checkpoint, not in this scene)");
  std::string s;
  for (std::size_t k = 0; k < differ.size(); ++k) {
    if (k > 0) s += k + 1 == differ.size() ? " and " : ", ";
    s += differ[k];
  }
  return s;
}

}  // namespace mpdem

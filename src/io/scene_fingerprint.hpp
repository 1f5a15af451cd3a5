#pragma once
// The fingerprint of the scene a run started from, kept in its checkpoints (section
// "scene_fingerprint", docs/output.md "Checkpoints"), so that a resume with a scene that is not
// the one the run was written for is refused naming what differs, instead of silently mixing two
// runs. Taken from the scene as loaded, before any step. One 64-bit hash per item of each part:
//   materials          each material's name and constants (one item per constant)
//   barriers           each element: id, group and rest vertices; motion law; E, nu, t_b, T
//   particle sources   each particle as loaded: id, material, radius, charge, x, v, w, q, T
//   domain             bounded or not, min, max
//   contact laws       [contact] per key, [liquid_bridge] (when given), each [[contact.pair]] entry
//   physics            [analysis], gravity, [fields], [near_field], [thermal] per key
//   time integration   time.integrator, time.phi, time.adaptive
//   inlets and sinks   each [[inlet]] and [[sink]] entry (all its keys)
//   bonds              [bonds] per key, each [[bonds.pair]] entry (only when [bonds] is given)
//   listed bonds       each bond of the bond CSV, as its two ids (only when [bonds] is given)
// What is not here (time.duration, time.dt and the step controls, [tolerance], neighbor.skin,
// domain.on_exit, [output], [checks], the command's options) may be edited on resume.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/binary_stream.hpp"
#include "model/scene.hpp"

namespace mpdem {

struct FingerprintPart {
  std::string name;                  // "materials", "barriers", ...
  std::vector<std::uint64_t> items;  // `fixed` items, then `per_entry` items per entry
  std::size_t fixed = 0;
  std::size_t per_entry = 1;
  std::string entries;  // what an entry is, plural ("materials", "particles"; "" = none)
  // Describes item k of the scene the fingerprint was taken from (empty in one read from a
  // checkpoint: messages describe the scene being resumed).
  std::function<std::string(std::size_t)> label;
};

struct SceneFingerprint {
  std::vector<FingerprintPart> parts;
};

// The fingerprint of a scene as loaded (before material variants are resolved and before any step).
SceneFingerprint fingerprint_scene(const Scene& scene);

void save_fingerprint(BinaryWriter& w, const SceneFingerprint& f);
SceneFingerprint load_fingerprint(BinaryReader& r);

// What differs between the fingerprint a checkpoint holds and the scene's: "" when nothing does;
// otherwise every differing part by name, each with its first differing item (and the entry
// counts when they differ), e.g. "barriers (element id 3 of group 'floor': rest vertices)".
std::string fingerprint_difference(const SceneFingerprint& checkpoint, const SceneFingerprint& scene);

// The parts of a scene that may be edited between a run and its resume, for messages.
inline constexpr const char* kEditableOnResume =
    "time.duration, time.dt and the other step controls, [tolerance], neighbor.skin, domain.on_exit, [output], "
    "[checks], --threads, --quiet";

}  // namespace mpdem

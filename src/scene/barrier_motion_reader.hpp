#pragma once
// Reads the motion keys of a [[barriers]] entry: `motion` (a, A, w1, B, w2 and `rotation`),
// `active` and `motion_from`, into a MotionLaw. A law whose displacement, velocity or angle
// overflows over the run (`duration`, s) is an InputError at the key to blame (docs/scene.md
// "Derived limits"), like every other bad value.
#include "io/toml_section.hpp"
#include "state/motion_law.hpp"

namespace mpdem {

MotionLaw read_barrier_motion(const TomlSection& s, double duration);

}  // namespace mpdem

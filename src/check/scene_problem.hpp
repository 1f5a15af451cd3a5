#pragma once
// SceneProblem: one finding of the pre-run scene checks (check/scene_checks.hpp), located like an
// InputError (file, line, key) and naming the particle and barrier element ids concerned.
#include <cstddef>
#include <string>
#include <vector>

namespace mpdem {

enum class Severity { Error, Warning };

struct SceneProblem {
  Severity severity = Severity::Error;
  std::string file;      // where to look ("" = none)
  std::size_t line = 0;  // line in `file` (0 = none)
  std::string key;       // TOML key or CSV column ("" = none)
  std::string message;   // what is wrong, with ids, and what to do
  // The run would certainly stop at its first step (e.g. an overlap beyond checks.max_overlap):
  // `mpdem run` refuses to start it.
  bool stops_run = false;
};

using SceneProblems = std::vector<SceneProblem>;

// "FILE:LINE: 'KEY': MESSAGE", the form of InputError (parts without a value left out).
inline std::string located_text(const SceneProblem& p) {
  std::string s = p.file;
  if (!s.empty() && p.line > 0) s.append(":").append(std::to_string(p.line));
  if (!p.key.empty()) s.append(s.empty() ? "'" : ": '").append(p.key).append("'");
  return s.empty() ? p.message : s.append(": ").append(p.message);
}

}  // namespace mpdem

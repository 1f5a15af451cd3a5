#!/usr/bin/env python3
"""scripts/check_layers.py on scratch trees: clean on a tree that follows the layer order, exit 1
naming file and line for an include of a higher layer and of the own layer, and for a
folder-level cycle, and for a listed subfolder (contact/laws) that includes its parent; exit 2 for a folder the order does not know; clean on the real src/."""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
CHECK = os.path.join(ROOT, "scripts", "check_layers.py")


def tree(files):
    d = tempfile.mkdtemp()
    for path, text in files.items():
        p = os.path.join(d, "src", path)
        os.makedirs(os.path.dirname(p), exist_ok=True)
        with open(p, "w", encoding="utf-8") as f:
            f.write(text)
    return d


def run(root):
    r = subprocess.run([sys.executable, CHECK, root], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def expect(cond, what, out):
    if not cond:
        print("FAILED:", what, "\n", out)
        sys.exit(1)


ok = {"core/a.hpp": "#pragma once\n", "sim/s.cpp": '#include "core/a.hpp"\n#include "sim/s.hpp"\n', "sim/s.hpp": ""}
rc, out = run(tree(ok))
expect(rc == 0 and "0 against the layer order, 0 cycles" in out, "a tree in layer order is clean", out)

upward = dict(ok, **{"core/b.cpp": '#include <vector>\n\n#include "sim/s.hpp"\n'})
rc, out = run(tree(upward))
expect(rc == 1 and "src/core/b.cpp:3: core/ includes sim/, a higher layer" in out, "an upward include fails", out)

same = dict(ok, **{"field/f.cpp": '#include "thermal/t.hpp"\n', "thermal/t.hpp": ""})
rc, out = run(tree(same))
expect(rc == 1 and "field/ includes thermal/, a folder of its own layer" in out, "a same-layer include fails", out)

cycle = {"io/x.cpp": '#include "model/m.hpp"\n', "model/m.hpp": '#include "io/x.hpp"\n', "io/x.hpp": ""}
rc, out = run(tree(cycle))
expect(rc == 1 and "include cycle among io, model" in out, "a cycle fails", out)

unknown = {"gadgets/g.cpp": '#include "core/a.hpp"\n', "core/a.hpp": ""}
rc, out = run(tree(unknown))
expect(rc == 2 and "gadgets" in out, "an unknown folder is named", out)

sub = {"contact/laws/l.hpp": '#include "contact/k.hpp"\n', "contact/k.hpp": '#include "contact/laws/l.hpp"\n'}
rc, out = run(tree(sub))
expect(rc == 1 and "src/contact/laws/l.hpp:1: contact/laws/ includes contact/, a higher layer" in out,
       "a listed subfolder is a layer of its own", out)

rc, out = run(ROOT)
expect(rc == 0, "the repository's src/ is clean", out)
print("check_layers: 7 cases pass")

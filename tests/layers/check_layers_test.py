#!/usr/bin/env python3
"""The layer check fails on what it must catch: an include upwards, a loop, a folder not in the list."""
import os
import subprocess
import sys
import tempfile

CHECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "check_layers.py")
DOC = """# x
<!-- layers: bottom to top -->
1. `core` — a
2. `geometry` — b
3. `scene` — c
<!-- end of layers -->
"""


def run(files, doc=DOC):
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs"))
        with open(os.path.join(root, "docs", "architecture.md"), "w") as f:
            f.write(doc)
        for path, text in files.items():
            full = os.path.join(root, "src", "glint", path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w") as f:
                f.write(text)
        result = subprocess.run([sys.executable, CHECK, "--root", root], capture_output=True, text=True)
        return result.returncode, result.stderr


def main():
    down = {"core/a.hpp": "", "geometry/b.hpp": '#include "glint/core/a.hpp"\n',
            "scene/c.cpp": '#include "glint/geometry/b.hpp"\n#include "glint/core/a.hpp"\n'}
    failures = []
    code, err = run(down)
    if code != 0:
        failures.append("downward includes were refused: " + err)
    up = dict(down, **{"geometry/b.cpp": '#include "glint/scene/c.hpp"\n'})
    code, err = run(up)
    if code != 1 or "geometry/b.cpp:1: geometry/ includes scene/" not in err:
        failures.append(f"an upward include passed (exit {code}): {err}")
    loop = dict(down, **{"core/a.cpp": '#include "glint/geometry/b.hpp"\n'})
    code, err = run(loop)
    if code != 1:
        failures.append("a loop core <-> geometry passed")
    unlisted = dict(down, **{"extra/d.hpp": ""})
    code, err = run(unlisted)
    if code != 1 or "src/glint/extra/ is not in the layer list" not in err:
        failures.append(f"an unlisted folder passed (exit {code}): {err}")
    for failure in failures:
        print("FAIL:", failure)
    print("ok" if not failures else f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Instructions each glint build runs on the three scenes of issue 13's notes, counted by valgrind's
callgrind (one thread, the whole process): exact and repeatable, where a time is noisy, so it shows
what a change removed even when bench/ab.py cannot tell its time from noise. It is not a time: work
taken off a sample's chain of dependent operations can pay more than its count, and instructions added
in parallel to it can cost nothing (docs/benchmarks.md has examples of both).

  bench/icount.py GLINT [GLINT …]
  bench/icount.py /tmp/glint-before build/release/glint

The scenes: examples/rtiow-final.yaml at 200×112, 4 spp, --max-depth 49; examples/rtiow-cornell.yaml
at 100×100, 8 spp; examples/smallpt.yaml at 128×96, 8 spp. valgrind is not one of glint's
dependencies: `apt-get install valgrind`. Each count takes about a minute.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# RTIOW's --max-depth 49 is the scene's own max_depth, spelt out as bench/peers.py and the notes do.
SCENES = [
    ('rtiow-final', ['examples/rtiow-final.yaml', '--width', '200', '--height', '112', '--spp', '4',
                     '--max-depth', '49']),
    ('rtiow-cornell', ['examples/rtiow-cornell.yaml', '--width', '100', '--height', '100', '--spp', '8']),
    ('smallpt', ['examples/smallpt.yaml', '--width', '128', '--height', '96', '--spp', '8']),
]


def count(glint, args, tmp):
    """callgrind's instruction total for one render."""
    out = os.path.join(tmp, 'callgrind.out')
    image = os.path.join(tmp, 'render.pfm')
    run = subprocess.run(['valgrind', '--tool=callgrind', f'--callgrind-out-file={out}', glint, 'render',
                          *args, '--threads', '1', '-q', '-o', image],
                         cwd=ROOT, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f'{glint} failed under valgrind:\n{run.stderr[-2000:]}')
    found = re.search(r'Collected : (\d+)', run.stderr)
    if not found:
        sys.exit(f'no instruction count in valgrind\'s output:\n{run.stderr[-2000:]}')
    return int(found.group(1))


def executable(build):
    """A build's path made absolute (the renders run from the repository's root), or a bare command
    name as found on PATH."""
    if os.sep not in build and shutil.which(build):
        return shutil.which(build)
    return os.path.abspath(build)


def main():
    builds = sys.argv[1:]
    if not builds:
        sys.exit(__doc__)
    if shutil.which('valgrind') is None:
        sys.exit('bench/icount.py needs valgrind: apt-get install valgrind')
    # Columns: each build's count, in the order given, then each later build's change against the first.
    print('builds: ' + '; '.join(f'{i + 1}. {b}' for i, b in enumerate(builds)))
    header = [f'{i + 1:>11}' for i in range(len(builds))]
    header += [f'{i + 1} vs 1' for i in range(1, len(builds))]
    print(f'{"scene":14} ' + '  '.join(header), flush=True)
    with tempfile.TemporaryDirectory() as tmp:
        for scene, args in SCENES:
            counts = [count(executable(b), args, tmp) for b in builds]
            cells = [f'{c / 1e6:9.1f} M' for c in counts]
            if len(counts) > 1:
                cells += [f'{c / counts[0] - 1:+.2%}' for c in counts[1:]]
            print(f'{scene:14} ' + '  '.join(cells), flush=True)


if __name__ == '__main__':
    main()

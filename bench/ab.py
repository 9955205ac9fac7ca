#!/usr/bin/python3
"""CPU time of two glint builds on one scene, measured in alternation (A B, B A, A B, ...) so that a
drifting machine weighs on both alike: the median user CPU seconds of each and their ratio B/A. For a
change that should keep the image and save time; compare the error per sample with bench/quality.py.

  bench/ab.py RUNS SCENE SPP GLINT_A GLINT_B [extra glint render flags]
  bench/ab.py 9 examples/rtiow-final.yaml 32 /tmp/glint-before build/release/glint \\
      --width 400 --height 225 --max-depth 49
(one thread: the flags add --threads 1 unless they set --threads.)
"""
import os
import resource
import statistics
import subprocess
import sys
import tempfile


def main():
    if len(sys.argv) < 6:
        sys.exit(__doc__)
    runs, scene, spp = int(sys.argv[1]), sys.argv[2], sys.argv[3]
    binaries = sys.argv[4:6]
    extra = sys.argv[6:]
    if not any(a == '--threads' or a.startswith('--threads=') for a in extra):
        extra += ['--threads', '1']
    # By position, so that A/A (the same binary twice, to see the noise) keeps two lists.
    times = [[], []]
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, 'render.pfm')
        for i in range(runs):
            for which in (0, 1) if i % 2 == 0 else (1, 0):
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                subprocess.run([binaries[which], 'render', scene, '--spp', spp, '-q', '-o', out] + extra,
                               check=True)
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                times[which].append(after.ru_utime - before.ru_utime)
    a, b = (statistics.median(t) for t in times)
    print(f'{scene} at {spp} spp: A {a:.3f} s, B {b:.3f} s (medians of {runs}), B/A {b / a:.4f}')


if __name__ == '__main__':
    main()

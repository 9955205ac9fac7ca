#!/usr/bin/python3
"""CPU time of two glint builds on one scene, measured in alternation (A B, B A, A B, ...) so that a
drifting machine weighs on both alike: the median user CPU seconds of each and their ratio B/A. For a
change that should keep the image and save time; compare the error per sample with bench/quality.py.

  bench/ab.py RUNS SCENE SPP GLINT_A GLINT_B [extra glint render flags]
  bench/ab.py 9 examples/rtiow-final.yaml 32 /tmp/glint-before build/release/glint \\
      --width 400 --height 225 --max-depth 49
(one thread: the flags add --threads 1 unless they set --threads.)

It also prints the spread of the ratio: each round's B/A (its two runs, back to back) and a 95 %
interval of their median, from 2000 bootstrap resamples of the rounds (a fixed seed, so the same times
give the same interval). An interval that holds 1 is a change the measurement cannot tell from noise:
the issue 13 rule is to keep such a change out. `bench/ab.py 11 SCENE SPP GLINT GLINT` (A/A) shows the
machine's own noise.
"""
import os
import random
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
    low, median, high = paired_ratio_interval(times[0], times[1])
    verdict = 'within noise' if low <= 1 <= high else ('B faster' if high < 1 else 'B slower')
    print(f'  per-round B/A: median {median:.4f}, 95 % interval {low:.4f} to {high:.4f} ({verdict})')


def paired_ratio_interval(a_times, b_times, resamples=2000, seed=13):
    """The median of the rounds' B/A and a 95 % bootstrap interval of it (percentile method)."""
    ratios = [b / a for a, b in zip(a_times, b_times) if a > 0]
    if not ratios:
        return float('nan'), float('nan'), float('nan')
    rng = random.Random(seed)
    medians = sorted(statistics.median(rng.choices(ratios, k=len(ratios))) for _ in range(resamples))
    return medians[int(0.025 * resamples)], statistics.median(ratios), medians[int(0.975 * resamples) - 1]


if __name__ == '__main__':
    main()

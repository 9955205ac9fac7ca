#!/usr/bin/python3
"""CPU time of two glint builds on one scene, measured in alternation (A B, B A, A B, ...) so that a
drifting machine weighs on both alike: the median user CPU seconds of each and their ratio B/A. For a
change that should keep the image and save time; compare the error per sample with bench/quality.py.

  bench/ab.py RUNS SCENE SPP GLINT_A GLINT_B [extra glint render flags]
  bench/ab.py 16 examples/rtiow-final.yaml 32 /tmp/glint-before build/release/glint \\
      --width 400 --height 225 --max-depth 49
(one thread: the flags add --threads 1 unless they set --threads.)

It also prints a verdict. Rounds are taken in pairs, A B then B A, so that running first or second
weighs on both builds alike. Each pair gives one ratio: its two B times over its two A times. The
script prints the median of these ratios, with a 95 % interval of that median from 2 000 bootstrap
resamples of the pairs (a fixed seed, so that the same times give the same interval). An interval that
holds 1 means the change cannot be told from noise, and the issue 13 rule is to keep such a change out.

Below 5 pairs (10 runs) it gives no verdict, because so few pairs make the interval far too narrow.
Even with more pairs, the interval is optimistic: an A/A simulation puts 1 outside it in 7 to 14 % of
runs, not 5 %. It also sees only the noise within this one invocation, not the drift between
invocations. A second run of the same comparison can land outside it, so repeat a close call.
`bench/ab.py 16 SCENE SPP GLINT GLINT` (A/A) shows the machine's own noise.
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
    ratio_of_medians = f'{b / a:.4f}' if a > 0 else 'undefined (A took no measurable time)'
    print(f'{scene} at {spp} spp: A {a:.3f} s, B {b:.3f} s (medians of {runs} runs each), '
          f'ratio of the medians B/A {ratio_of_medians}')
    ratios = pair_ratios(times[0], times[1])
    if not ratios:
        print('  no complete A B / B A pair with measurable times: no verdict')
        return
    low, median, high = median_interval(ratios)
    if len(ratios) < kFewestPairsForVerdict:
        verdict = f'too few pairs for a verdict (at least {kFewestPairsForVerdict})'
    elif low <= 1 <= high:
        verdict = 'within noise'
    else:
        verdict = 'B faster' if high < 1 else 'B slower'
    print(f'  B/A of the {len(ratios)} A B / B A pairs: median {median:.4f}, 95 % interval {low:.4f} to '
          f'{high:.4f}: {verdict}')


# Below this many pairs the bootstrap interval misses 1 far too often in A/A runs. In a simulation of A/A
# runs with independent Gaussian noise (1 000 trials each) it missed 1 in 25 % of the trials with 3
# pairs, and in 7 to 14 % with 5 to 10 pairs, against the 5 % it names: even then it is optimistic.
kFewestPairsForVerdict = 5


def pair_ratios(a_times, b_times):
    """One B/A per pair of rounds (an A B round and the B A round after it): the sum of their two B
    times over the sum of their two A times. An odd last round has no pair and is left out."""
    ratios = []
    for i in range(0, min(len(a_times), len(b_times)) - 1, 2):
        a = a_times[i] + a_times[i + 1]
        b = b_times[i] + b_times[i + 1]
        if a > 0:  # getrusage's clock can report 0 s for renders shorter than its tick
            ratios.append(b / a)
    return ratios


def median_interval(values, resamples=2000, seed=13):
    """The median of `values` and a 95 % bootstrap interval of it (percentile method). The seed is fixed
    so that the same measurements always print the same interval."""
    rng = random.Random(seed)
    medians = sorted(statistics.median(rng.choices(values, k=len(values))) for _ in range(resamples))
    return medians[int(0.025 * resamples)], statistics.median(values), medians[int(0.975 * resamples) - 1]


if __name__ == '__main__':
    main()

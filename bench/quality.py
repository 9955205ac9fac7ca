#!/usr/bin/python3
"""Error per sample and cost of one glint build on one scene: the mean squared error of K renders at S
spp (seeds 100 … 100+K−1, one thread) against a reference made of two halves by bench/peers.py, with the
reference's own noise subtracted as peers.py does, and the median CPU time. For choices that trade error
for time (samplers, Russian roulette): compare MSE × time between two builds or settings.

  bench/quality.py GLINT SCENE WIDTH HEIGHT SPP K REFERENCE_PREFIX [extra glint render flags]
  bench/quality.py build/release/glint examples/rtiow-cornell.yaml 400 400 16 4 \\
      build/peers/refs/cornell-400x400-1024spp
(REFERENCE_PREFIX-half1.pfm and -half2.pfm are the reference's halves.)
"""
import math
import os
import resource
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from peers import read_pfm  # noqa: E402


def main():
    if len(sys.argv) < 8:
        sys.exit(__doc__)
    glint, scene, width, height, spp, runs, reference = sys.argv[1:8]
    half1, half2 = read_pfm(reference + '-half1.pfm'), read_pfm(reference + '-half2.pfm')
    mean = (half1 + half2) / 2
    variance = (half1 - half2) ** 2 / 4  # of the mean of the two halves, per pixel
    mses, cpu = [], []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, 'render.pfm')
        for seed in range(100, 100 + int(runs)):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            subprocess.run([glint, 'render', scene, '--width', width, '--height', height, '--spp', spp,
                            '--seed', str(seed), '--threads', '1', '-q', '-o', out] + sys.argv[8:], check=True)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu.append(after.ru_utime - before.ru_utime)
            mses.append(float(np.mean((read_pfm(out) - mean) ** 2) - np.mean(variance)))
    mse = float(np.mean(mses))
    print(f'{spp} spp: relative RMSE {math.sqrt(max(mse, 0)) / float(np.mean(mean)):.5f}, '
          f'MSE {mse:.4g} ± {100 * np.std(mses) / math.sqrt(len(mses)) / mse:.1f} %, '
          f'CPU {np.median(cpu):.3f} s, MSE × CPU {mse * np.median(cpu):.4g}')


if __name__ == '__main__':
    main()

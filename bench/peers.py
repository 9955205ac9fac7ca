#!/usr/bin/env python3
"""glint side by side with the peer renderers' own code (smallpt, Ray Tracing in One Weekend books 1 and 2).

    make bench-peers                      # BENCH_MODE=fast: a few minutes
    make bench-peers BENCH_MODE=full      # the books' sizes and sample counts (~45 min the first time)
    /usr/bin/python3 bench/peers.py --mode fast [--runs N]

The peers are built from ../shared/peers by its build.sh into build/peers (only when a binary is missing
or older than the sources); they are never copied into the repository. For each pair it measures, in
one run, alternating the two renderers (the machine is shared and noisy; medians of the runs):
  1. the whole-process wall time at equal samples per pixel (and the CPU time, which other load
     disturbs less);
  2. the time to equal RMSE against a high-sample reference that the peer makes itself (two halves
     with different seeds, whose difference estimates the reference's own noise, subtracted from
     every measured MSE): glint's spp needed from a fit of log RMSE on log spp through its ladder, then
     the peer at its target spp and glint at the spp either side of its need, alternating in the same
     rounds as (1) (and, beside it, from fits of log RMSE on log time: a quadratic, and lines);
  3. that glint converges to the peer's image: 16x16-pixel block means, z-scores against the noise of
     both sides (each estimated from two independent halves);
  4. the shading overhead: glint's whole-render rays/s against bench/accel's kernel rays/s on the
     render's own rays, alternating the two in as many rounds as the pairs have runs.
docs/benchmarks.md explains the method. Results: build/bench-peers/results.json.
"""
import argparse
import hashlib
import json
import math
import os
import re
import shlex
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GLINT = os.path.join(ROOT, 'build/release/glint')
ACCEL = os.path.join(ROOT, 'build/release/bench/glint_bench_accel')
PEER_SOURCES = os.path.normpath(os.path.join(ROOT, '../shared/peers'))
PEERS = os.path.join(ROOT, 'build/peers')
RTIOW = os.path.join(PEERS, 'rtiow')
REFS = os.path.join(PEERS, 'refs')
OUT = os.path.join(ROOT, 'build/bench-peers')
BUNNY = os.path.normpath(os.path.join(ROOT, '../shared/data/meshes/stanford-bunny.obj'))
BLOCK = 16          # pixels per side of the blocks whose means the convergence check compares
Z_LIMIT = 4.0       # a block beyond this many standard deviations counts as a disagreement

# Per mode and scene: image size; the spp ladder each renderer renders for the RMSE fits (glint's own
# when it needs other counts to reach the same RMSE); the spp of
# the equal-spp timing (repeated `runs` times); the target spp (the peer's RMSE there is the target);
# the spp of each reference half (peer) and of each convergence half (glint). The RTIOW peers' sizes
# are fixed in their code (400x225, 400x400), so fast mode changes only their sample counts; b2bvh's
# 32 spp is fixed too. smallpt's spp must be multiples of 4 (2x2 sub-pixels).
MODES = {
    'fast': {
        'runs': 3,
        # glint's light sampling reaches smallpt's error at 16 spp in about 2: its ladder starts lower, so
        # that its time to the target is measured, not extrapolated from the fit.
        'smallpt': dict(size=(128, 96), ladder=[4, 8, 16, 32], glint_ladder=[1, 2, 4, 8, 16], equal=16, target=16,
                        ref=1024, conv=512),
        'rtiow': dict(size=(400, 225), ladder=[1, 2, 4, 8], equal=4, target=4, ref=64, conv=64),
        # glint's light sampling needs far fewer samples than the book's brute force here.
        'cornell': dict(size=(400, 400), ladder=[4, 8, 16, 32], glint_ladder=[1, 2, 4], equal=8, target=32,
                        ref=64, conv=64),
        'bunny': dict(size=(512, 128), spp=16, min_time=0.5),
    },
    'full': {
        'runs': 5,
        # smallpt at 1024x768 would need hours for a reference on 2 cores: 512x384, a quarter of the pixels.
        # (glint reaches its error at 64 spp in about 7 spp: its ladder starts lower, as in fast mode.)
        'smallpt': dict(size=(512, 384), ladder=[8, 16, 32, 64, 128], glint_ladder=[2, 4, 8, 16, 32], equal=64,
                        target=64, ref=256, conv=128),
        'rtiow': dict(size=(400, 225), ladder=[4, 8, 16, 32, 64], equal=32, target=32, ref=512, conv=256),
        'cornell': dict(size=(400, 400), ladder=[8, 16, 32, 64, 128], glint_ladder=[1, 2, 4, 8, 16], equal=64,
                        target=64, ref=1024, conv=256),
        'bunny': dict(size=(512, 128), spp=64, min_time=2),
    },
}

COMMANDS = []   # every command run, in order, for the notes that quote them


def log(msg):
    print(msg, flush=True)


# ---------------------------------------------------------------------------------------------------
# Running things

class Run:
    """One finished process: wall and CPU seconds, its stderr, and where its image went."""
    def __init__(self, wall, cpu, err, image):
        self.wall, self.cpu, self.err, self.image = wall, cpu, err, image


def describe(cmd, cwd, env):
    prefix = ' '.join(f'{k}={v}' for k, v in (env or {}).items())
    where = f'(cd {shlex.quote(os.path.relpath(cwd, ROOT))} && ' if cwd and cwd != ROOT else ''
    text = ' '.join(shlex.quote(os.path.relpath(c, ROOT) if c.startswith(ROOT + '/') else c) for c in cmd)
    text = (prefix + ' ' if prefix else '') + text
    return where + text + (')' if where else '')


def start(cmd, cwd=None, env=None, stdout_path=None):
    full_env = dict(os.environ, **(env or {}))
    out = open(stdout_path, 'wb') if stdout_path else subprocess.DEVNULL
    err = tempfile.TemporaryFile()
    shown = describe(cmd, cwd, env) + (f' > {os.path.relpath(stdout_path, ROOT)}' if stdout_path else '')
    COMMANDS.append(shown)
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, cwd=cwd or ROOT, env=full_env, stdout=out, stderr=err)
    return (proc, t0, out, err, shown)


def finish(handle):
    proc, t0, out, err, shown = handle
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    if out is not subprocess.DEVNULL:
        out.close()
    err.seek(0)
    text = err.read().decode(errors='replace')
    err.close()
    if proc.returncode != 0:
        sys.exit(f'bench-peers: failed ({proc.returncode}): {shown}\n{text}')
    return wall, usage.ru_utime + usage.ru_stime, text


def run(cmd, cwd=None, env=None, stdout_path=None):
    wall, cpu, err = finish(start(cmd, cwd, env, stdout_path))
    return Run(wall, cpu, err, None)


def read_pfm(path):
    """A PFM as float64 rows top first (the file holds the bottom row first), shape (h, w, 3)."""
    with open(path, 'rb') as f:
        assert f.readline().strip() == b'PF', path
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(w * h * 12), dtype='<f4' if scale < 0 else '>f4')
    return data.reshape(h, w, 3)[::-1].astype(np.float64)


# ---------------------------------------------------------------------------------------------------
# The renderers: each `render(spp, seed, path)` returns a Run whose .image is the linear image, or None.

class Renderer:
    def __init__(self, name, threads, command, image_from, cwd=None, env=None, scratch=False):
        self.name, self.threads = name, threads
        self.command, self.image_from, self.cwd, self.env, self.scratch = command, image_from, cwd, env, scratch

    def launch(self, spp, seed, path):
        cwd = self.cwd
        if self.scratch:       # smallpt writes image.pfm into its working folder
            cwd = tempfile.mkdtemp(prefix='smallpt-', dir=OUT)
        cmd, stdout_path = self.command(spp, seed, path)
        return start(cmd, cwd, self.env, stdout_path), cwd

    def collect(self, launched, path):
        handle, cwd = launched
        wall, cpu, err = finish(handle)
        image = None
        if self.image_from == 'cwd':
            os.replace(os.path.join(cwd, 'image.pfm'), path)
            os.rmdir(cwd)
        if self.image_from is not None and path:
            image = read_pfm(path)
        return Run(wall, cpu, err, image)

    def render(self, spp, seed, path):
        return self.collect(self.launch(spp, seed, path), path)


def glint(scene, size, threads, sample_lights=True):
    """glint on a scene; sample_lights=False switches the path tracer's light sampling off (named
    'glint Nt bsdf-only')."""
    extra = [] if sample_lights else ['--set', 'render.integrator.sample_lights=false']

    def command(spp, seed, path):
        return [GLINT, 'render', os.path.join(ROOT, scene), '--width', str(size[0]), '--height', str(size[1]),
                '--spp', str(spp), '--seed', str(seed), '--threads', str(threads), '-o', path] + extra, None
    return Renderer(f'glint {threads}t' + ('' if sample_lights else ' bsdf-only'), threads, command, 'file')


def smallpt(size, threads):
    def command(spp, seed, path):
        return [os.path.join(PEERS, 'smallpt/smallpt_lin'), str(spp), str(size[0]), str(size[1]), str(seed), '0'], None
    return Renderer('smallpt', threads, command, 'cwd', env={'OMP_NUM_THREADS': str(threads)}, scratch=True)


def rtiow(binary, takes_args=True):
    def command(spp, seed, path):
        args = [str(spp), str(seed)] if takes_args else []
        return [os.path.join(RTIOW, binary, binary + '.bin')] + args, path
    return Renderer(binary, 1, command, 'file' if takes_args else None, cwd=RTIOW)


# ---------------------------------------------------------------------------------------------------
# Peers and references

def file_digest(path):
    """The first 16 hex digits of a file's sha256."""
    h = hashlib.sha256()
    with open(path, 'rb') as f:
        for block in iter(lambda: f.read(1 << 20), b''):
            h.update(block)
    return h.hexdigest()[:16]


def newest_mtime(folder):
    return max(os.path.getmtime(os.path.join(d, f)) for d, _, files in os.walk(folder) for f in files)


def build_peers():
    binaries = [os.path.join(RTIOW, v, v + '.bin') for v in ('b1', 'b1f', 'b2bvh', 'b2cb', 'b2cbf')] + \
               [os.path.join(PEERS, 'smallpt', s) for s in ('smallpt', 'smallpt_lin')]
    sources = newest_mtime(PEER_SOURCES)
    if all(os.path.exists(b) and os.path.getmtime(b) >= sources for b in binaries):
        return
    log('building the peers from ../shared/peers ...')
    # build.sh wipes OUT/rtiow; the references live beside it, in OUT/refs.
    run([os.path.join(PEER_SOURCES, 'build.sh'), PEERS])


def reference(key, peer, spp, size):
    """The peer's own high-sample image, as two halves with different seeds rendered in parallel (one
    thread each), cached in build/peers/refs/ by scene, size and spp. Returns (mean, per-pixel variance
    of the mean estimated from the halves' difference)."""
    os.makedirs(REFS, exist_ok=True)
    paths = [os.path.join(REFS, f'{key}-{size[0]}x{size[1]}-{spp}spp-half{h}.pfm') for h in (1, 2)]
    binary_time = newest_mtime(os.path.join(PEERS, 'smallpt' if key == 'smallpt' else 'rtiow'))
    if not all(os.path.exists(p) and os.path.getmtime(p) >= binary_time for p in paths):
        log(f'  reference: {peer.name} 2 x {spp} spp at {size[0]}x{size[1]} (cached in {os.path.relpath(REFS, ROOT)}) ...')
        t0 = time.perf_counter()
        launched = [peer.launch(spp, seed, p) for seed, p in zip((9001, 9002), paths)]
        for l, p in zip(launched, paths):
            peer.collect(l, p)
        log(f'  reference made in {time.perf_counter() - t0:.0f} s')
    else:
        COMMANDS.append(f'# reference reused: {", ".join(os.path.relpath(p, ROOT) for p in paths)}')
    a, b = read_pfm(paths[0]), read_pfm(paths[1])
    return 0.5 * (a + b), 0.25 * (a - b) ** 2


# ---------------------------------------------------------------------------------------------------
# Statistics

def rmse_against(image, ref_mean, ref_var):
    """RMSE of an image against the reference, the reference's own noise taken out:
    E[(X - R)^2] = MSE(X) + Var(R), pixel by pixel."""
    mse = float(np.mean((image - ref_mean) ** 2) - np.mean(ref_var))
    return math.sqrt(max(mse, 1e-30))


def fit(times, rmses):
    """log RMSE = a + b log t: (a, b) by least squares with b free, and a with b = -1/2."""
    x, y = np.log(times), np.log(rmses)
    if len(x) >= 2 and np.ptp(x) > 0:
        b, a = np.polyfit(x, y, 1)
    else:
        b, a = -0.5, float(np.mean(y + 0.5 * x))
    return {'free': (float(a), float(b)), 'half': (float(np.mean(y + 0.5 * x)), -0.5)}


def time_for(model, target):
    a, b = model
    return math.exp((math.log(target) - a) / b)


def fit_curve(xs, rmses):
    """log RMSE = a + b log x + c (log x)^2 by least squares: (a, b, c), with c = 0 when there are fewer
    than three distinct x. The line of fit() takes the curve for a power law; the peers' curves are one,
    glint's are not (docs/benchmarks.md: its sampler's stratification pays more at low spp, so its slope
    flattens as the spp rise), and the line through them overestimated glint's time to the target."""
    x, y = np.log(xs), np.log(rmses)
    if len(set(np.round(x, 12))) < 3:
        a, b = fit(xs, rmses)['free']
        return a, b, 0.0
    c, b, a = np.polyfit(x, y, 2)
    return float(a), float(b), float(c)


def x_for_curve(model, target, near):
    """The x at which the curve reaches `target`: the root of the quadratic in log x nearest log(near)
    (the line's answer), or `near` itself when the curve never reaches the target."""
    a, b, c = model
    if abs(c) < 1e-12:
        return time_for((a, b), target)
    disc = b * b - 4 * c * (a - math.log(target))
    if disc < 0:
        return near
    roots = [(-b + sign * math.sqrt(disc)) / (2 * c) for sign in (1, -1)]
    return math.exp(min(roots, key=lambda u: abs(u - math.log(near))))


def block_stats(mean, var):
    """Block means of an image and the variance of each, from per-pixel variances of the mean."""
    h, w = mean.shape[0] // BLOCK * BLOCK, mean.shape[1] // BLOCK * BLOCK
    n = BLOCK * BLOCK

    def blocks(x):
        return x[:h, :w].reshape(h // BLOCK, BLOCK, w // BLOCK, BLOCK, 3).sum(axis=(1, 3))
    return blocks(mean) / n, blocks(var) / n ** 2


def pooled(block_var):
    """A block's variance, or the mean over it and its 8 neighbours when that is larger. A block whose
    two halves both happened to miss the rare bright paths (caustics through glass, fireflies) has a
    low mean and underestimates its own variance; its neighbours, in the same light, do not."""
    padded = np.pad(block_var, ((1, 1), (1, 1), (0, 0)), mode='edge')
    h, w = block_var.shape[:2]
    around = sum(padded[i:i + h, j:j + w] for i in range(3) for j in range(3)) / 9
    return np.maximum(block_var, around)


def convergence(glint_a, glint_b, ref_mean, ref_var):
    g_mean, g_var = 0.5 * (glint_a + glint_b), 0.25 * (glint_a - glint_b) ** 2
    gm, gv = block_stats(g_mean, g_var)
    rm, rv = block_stats(ref_mean, ref_var)
    gv, rv = pooled(gv), pooled(rv)
    sigma = np.sqrt(gv + rv)
    diff = gm - rm
    z = np.where(sigma > 0, diff / np.where(sigma > 0, sigma, 1), np.where(diff == 0, 0.0, np.inf))
    beyond = int(np.sum(np.abs(z) > Z_LIMIT))
    count = z.size
    finite = z[np.isfinite(z) & (sigma > 0)]
    # Gaussian noise puts 6e-5 of the blocks beyond 4 sigma; the noise estimates come from only two
    # halves, so allow one block per thousand (at least one) before calling it a disagreement.
    passed = beyond <= max(1, count // 1000)
    floor2 = float(np.mean((g_mean - ref_mean) ** 2) - np.mean(g_var) - np.mean(ref_var))
    worst = np.unravel_index(int(np.argmax(np.abs(z))), z.shape)
    return {
        'blocks': count, 'max_abs_z': float(np.max(np.abs(z))), 'beyond_4sigma': beyond, 'pass': passed,
        'z_std': float(np.std(finite)) if finite.size else None,
        'worst_block': {'x': int(worst[1] * BLOCK), 'y': int(worst[0] * BLOCK), 'channel': int(worst[2]),
                        'glint': float(gm[worst]), 'peer': float(rm[worst])},
        'mean_ratio_glint_over_peer': float(np.mean(g_mean) / np.mean(ref_mean)),
        'rmse_floor_relative': math.sqrt(max(floor2, 0.0)) / float(np.mean(ref_mean)),
    }


def median(values):
    return float(np.median(values))


# ---------------------------------------------------------------------------------------------------
# One pair of renderers on one scene

def alternating_rounds(wanted, runs, folder, first_seed):
    """`runs` rounds of the runs wanted, each a (renderer, spp) (one asked for twice is run once), in
    order and the order reversed on every other round; round i renders each with seed first_seed + i.
    Returns, per run_label, a list per round of the Run."""
    jobs = list(dict.fromkeys(wanted))
    results = {run_label(r, spp): [] for r, spp in jobs}
    os.makedirs(folder, exist_ok=True)
    for i in range(runs):
        for r, spp in (jobs if i % 2 == 0 else jobs[::-1]):
            label = run_label(r, spp)
            path = os.path.join(folder, f'{label}-{i}.' + ('pfm' if r.image_from else 'ppm'))
            results[label].append(r.render(spp, first_seed + i, path))
    return results


def run_label(renderer, spp):
    """A renderer at an spp, as the rounds name its runs (and their images' files)."""
    return f'{renderer.name.replace(" ", "")}-{spp}spp'


def spp_needed_curve(pts, target):
    """The spp at which the curve of log RMSE on log spp through the points reaches the target."""
    spps, rmses = [p['spp'] for p in pts], [p['rmse'] for p in pts]
    return x_for_curve(fit_curve(spps, rmses), target, time_for(fit(spps, rmses)['free'], target))


def spp_bracket(spp_needed):
    """The whole spp on either side of a (fractional) spp needed: glint renders both in the rounds, and
    its time at spp_needed is interpolated between them (its time is close to linear in spp)."""
    low = max(1, math.floor(spp_needed))
    return low, low + 1


def time_at(spp_needed, low_run, high_run, low):
    """Wall time at spp_needed, by the line through the runs at low and low + 1 spp of one round."""
    return low_run.wall + (spp_needed - low) * (high_run.wall - low_run.wall)


# glint's rungs take a fraction of a second to a few seconds, where one hiccup of the machine moves a
# single run by up to a quarter (RTIOW's 8-spp rung: 0.36 s in one run, 0.29-0.32 s in three others),
# and the free slope with it. Each of glint's rungs is rendered this many times, with the same seed (the
# same image, so the same RMSE), and its median time is the rung's. The peers' rungs, of 1 to 20 s, are
# rendered once.
GLINT_RUNG_RUNS = 3


def ladder(renderers, spps, folder, ref_mean, ref_var):
    """Each renderer at each spp of its ladder (seeds apart from the reference's), alternating; glint's
    rungs the median of GLINT_RUNG_RUNS runs."""
    points = {r.name: [] for r in renderers}
    rungs = max(len(s) for s in spps)
    for k in range(rungs):
        order = list(zip(renderers, spps)) if k % 2 == 0 else list(zip(renderers, spps))[::-1]
        for r, spp_list in order:
            if k >= len(spp_list):
                continue
            spp = spp_list[k]
            path = os.path.join(folder, f'{r.name.replace(" ", "")}-ladder{spp}.pfm')
            results = [r.render(spp, 11 + k, path)
                       for _ in range(GLINT_RUNG_RUNS if r.name.startswith('glint') else 1)]
            points[r.name].append({'spp': spp, 'wall': median([x.wall for x in results]),
                                   'cpu': median([x.cpu for x in results]),
                                   'rmse': rmse_against(results[-1].image, ref_mean, ref_var)})
    return points


def glint_rays_per_second(err):
    m = re.findall(r'([\d.]+) Mrays/s', err)
    return float(m[-1]) if m else None


def glint_ray_mix(err):
    """The shares of camera, bounce and shadow rays in glint's summary ('N M rays (C M camera, B M
    bounces, S M shadow)'), keyed as bench/accel's ray sets are; None when the summary has no kinds."""
    m = re.findall(r'([\d.]+) M camera, ([\d.]+) M bounces, ([\d.]+) M shadow', err)
    if not m:
        return None
    counts = dict(zip(('primary', 'diffuse', 'shadow'), map(float, m[-1])))
    total = sum(counts.values())
    return {k: v / total for k, v in counts.items()} if total > 0 else None


def measure_scene(key, cfg, runs, peer, glint_one, glint_all=None, bvh_peer=None, ref_peer=None, ref_key=None):
    """Everything for one scene: equal-spp times, RMSE ladders and fits, the convergence check. ref_key:
    the scene whose reference to use (default: key's own)."""
    folder = os.path.join(OUT, key)
    os.makedirs(folder, exist_ok=True)
    size = cfg['size']
    log(f'\n== {key}: {peer.name} ({peer.threads} thread{"s" if peer.threads > 1 else ""}) vs {glint_one.name}'
        + (f' and {glint_all.name}' if glint_all else '') + (f'; {bvh_peer.name}' if bvh_peer else '')
        + f', {size[0]}x{size[1]}')
    ref_mean, ref_var = reference(ref_key or key, ref_peer or peer, cfg['ref'], size)
    ref_level = float(np.mean(ref_mean))
    result = {'size': list(size), 'reference_spp': 2 * cfg['ref'], 'reference_mean': ref_level,
              'reference_rmse_relative': math.sqrt(float(np.mean(ref_var))) / ref_level, 'pairs': {}}

    # 1. RMSE ladders. They come first because the rounds below render glint at the spp it needs to reach
    # the target, which a fit through its ladder tells.
    glint_ladder = cfg.get('glint_ladder', cfg['ladder'])
    log(f'  RMSE ladder: spp {cfg["ladder"]}' + (f', glint {glint_ladder}' if 'glint_ladder' in cfg else '') + ' ...')
    points = ladder([peer, glint_one], [cfg['ladder'], glint_ladder], folder, ref_mean, ref_var)
    ladder_target = median([p['rmse'] for p in points[peer.name] if p['spp'] == cfg['target']])
    low, high = spp_bracket(spp_needed_curve(points[glint_one.name], ladder_target))

    # 2. Alternating rounds: the peer at equal spp (and at its target spp, when that differs); each glint
    # at equal spp and at the whole spp on either side of what it needs for the target RMSE. Both
    # figures the targets are read from, the ratio at equal spp and the one to equal RMSE, are then
    # ratios of runs made side by side, so a slow spell of the machine moves both renderers alike.
    others = [glint_one] + ([glint_all] if glint_all else [])
    wanted = [(peer, cfg['equal']), (peer, cfg['target'])] + \
        [(g, spp) for g in others for spp in (cfg['equal'], low, high)]
    log(f'  alternating rounds: {cfg["equal"]} spp (equal spp), glint also at {low} and {high} spp (to equal RMSE), '
        f'{runs} rounds ...')
    rounds = alternating_rounds(wanted, runs, folder, 101)
    at_equal = {r.name: rounds[run_label(r, cfg['equal'])] for r in [peer] + others}
    times = {n: [x.wall for x in rs] for n, rs in at_equal.items()}
    cpu = {n: [x.cpu for x in rs] for n, rs in at_equal.items()}
    images = {n: [(x.image, x.err) for x in rs] for n, rs in at_equal.items()}

    # Every run of the peer and of glint on one thread is a point of the fits too (seeds apart from the
    # reference's).
    for r in [peer, glint_one]:
        for spp in sorted({spp for rr, spp in wanted if rr is r}):
            for x in rounds[run_label(r, spp)]:
                points[r.name].append({'spp': spp, 'wall': x.wall, 'cpu': x.cpu,
                                       'rmse': rmse_against(x.image, ref_mean, ref_var)})
    fits = {n: fit([p['wall'] for p in pts], [p['rmse'] for p in pts]) for n, pts in points.items()}
    spp_fits = {n: fit([p['spp'] for p in pts], [p['rmse'] for p in pts]) for n, pts in points.items()}
    curves = {n: fit_curve([p['wall'] for p in pts], [p['rmse'] for p in pts]) for n, pts in points.items()}
    spp_curves = {n: fit_curve([p['spp'] for p in pts], [p['rmse'] for p in pts]) for n, pts in points.items()}
    at_target = [p['rmse'] for p in points[peer.name] if p['spp'] == cfg['target']]
    target = median(at_target)
    needed = {}
    for n, pts in points.items():
        walls = [p['wall'] for p in pts]

        def outside(t):  # beyond the measured times (with a margin): an extrapolation
            return not (0.8 * min(walls) <= t <= 1.25 * max(walls))
        t_free, t_half = time_for(fits[n]['free'], target), time_for(fits[n]['half'], target)
        spp_free = time_for(spp_fits[n]['free'], target)
        t_curve = x_for_curve(curves[n], target, t_free)
        needed[n] = {'free': t_free, 'half': t_half, 'curve': t_curve,
                     'extrapolated': outside(t_free), 'extrapolated_curve': outside(t_curve),
                     'slope_free': fits[n]['free'][1], 'curvature': curves[n][2],
                     'spp_needed': spp_free,
                     'spp_needed_half': time_for(spp_fits[n]['half'], target),
                     'spp_needed_curve': x_for_curve(spp_curves[n], target, spp_free)}
    # glint on all cores renders the same samples (same bits whatever the threads), so its RMSE at
    # each spp is glint-1-thread's: its time to the target is its time per spp x glint's spp needed.
    derived = {}
    for extra, base in ([(glint_all, glint_one)] if glint_all else []) + ([(bvh_peer, peer)] if bvh_peer else []):
        derived[extra.name] = base.name

    # To equal RMSE, round by round: the peer reaches the target at its target spp (the target is its
    # median RMSE there); glint at the spp its fit needs, its time there interpolated between its runs
    # on either side in the same round.
    glint_needs = needed[glint_one.name]['spp_needed_curve']

    def glint_at_target(runs_of, g):
        return [time_at(glint_needs, a, b, low) for a, b in zip(runs_of[run_label(g, low)], runs_of[run_label(g, high)])]
    peer_at_target = [x.wall for x in rounds[run_label(peer, cfg['target'])]]

    # 3. Convergence: glint at high spp in two halves (all cores) against the reference.
    log(f'  convergence: glint 2 x {cfg["conv"]} spp ...')
    conv_glint = glint_all or glint_one
    halves = [conv_glint.render(cfg['conv'], 7001 + h, os.path.join(folder, f'glint-conv-half{h}.pfm'))
              for h in (1, 2)]
    conv = convergence(halves[0].image, halves[1].image, ref_mean, ref_var)
    conv['glint_spp'] = 2 * cfg['conv']

    def pair(other_name, peer_name, peer_times, peer_cpu, peer_needed, peer_to_target, glint_to_target, note=''):
        p_wall, g_wall = median(peer_times), median(times[other_name])
        round_ratios = [p / g for p, g in zip(peer_to_target, glint_to_target)]
        entry = {
            'peer': peer_name, 'glint': other_name, 'spp': cfg['equal'] if peer_name != 'b2bvh' else 32,
            'peer_wall_s': p_wall, 'glint_wall_s': g_wall, 'equal_spp_ratio': p_wall / g_wall,
            'peer_cpu_s': median(peer_cpu), 'glint_cpu_s': median(cpu[other_name]),
            'equal_spp_cpu_ratio': median(peer_cpu) / median(cpu[other_name]),
            'glint_mrays_per_s': median([glint_rays_per_second(e) or 0 for _, e in images[other_name]]),
            'glint_ray_mix': glint_ray_mix(images[other_name][0][1]),
            'target_rmse_relative': target / ref_level, 'target': f'{peer.name} at {cfg["target"]} spp',
            'convergence': conv, 'note': note,
            # The ratio the targets are read from: to equal RMSE, the median over the alternating rounds
            # of the peer's time at its target spp over glint's at the spp it needs (the same round's).
            'equal_rmse_ratio_rounds': median(round_ratios),
            'equal_rmse_ratio_rounds_range': [min(round_ratios), max(round_ratios)],
            'peer_time_to_target_rounds_s': median(peer_to_target),
            'glint_time_to_target_rounds_s': median(glint_to_target),
            'glint_spp_needed_rounds': glint_needs, 'glint_spp_bracket': [low, high],
        }
        g = needed.get(other_name)
        if g is None:   # glint on all cores: glint-1's spp needed at its own time per spp
            base = needed[derived[other_name]]
            per_spp = g_wall / cfg['equal']
            g = dict(base, free=per_spp * base['spp_needed'], half=per_spp * base['spp_needed_half'],
                     curve=per_spp * base['spp_needed_curve'])
            entry['note'] += ('; ' if entry['note'] else '') + \
                f'{other_name}: RMSE per spp taken from {derived[other_name]} (same samples), time per spp its own'
        entry.update({
            # From the fits of RMSE on time (fit_curve, then the lines): the same ratio, read from curves
            # through points made at different times of the run (so a drift of the machine moves it).
            'peer_time_to_target_curve_s': peer_needed['curve'], 'glint_time_to_target_curve_s': g['curve'],
            'equal_rmse_ratio_curve': peer_needed['curve'] / g['curve'],
            'peer_spp_needed_curve': peer_needed['spp_needed_curve'],
            'glint_spp_needed_curve': g['spp_needed_curve'],
            'peer_curvature': peer_needed['curvature'], 'glint_curvature': g['curvature'],
            'extrapolated_curve': bool(peer_needed['extrapolated_curve'] or g['extrapolated_curve']),
            'peer_time_to_target_s': peer_needed['free'], 'glint_time_to_target_s': g['free'],
            'equal_rmse_ratio': peer_needed['free'] / g['free'],
            'equal_rmse_ratio_slope_half': peer_needed['half'] / g['half'],
            'peer_slope': peer_needed['slope_free'], 'glint_slope': g['slope_free'],
            'peer_spp_needed': peer_needed['spp_needed'], 'glint_spp_needed': g['spp_needed'],
            'extrapolated': bool(peer_needed['extrapolated'] or g['extrapolated']),
        })
        return entry

    for other in others:
        result['pairs'][f'{peer.name} / {other.name}'] = pair(
            other.name, peer.name, times[peer.name], cpu[peer.name], needed[peer.name],
            peer_at_target, glint_at_target(rounds, other))

    if bvh_peer:
        # b2bvh has only PPM output (gamma 2, clamped, 8 bits) at its fixed 32 spp: timed, not compared
        # by pixels. Its per-sample estimator is b1f's (see docs/benchmarks.md), so it needs b1f's spp
        # for the target: the target spp (b1f's own RMSE there is the target). Its time there is its time
        # per spp x those spp.
        log(f'  {bvh_peer.name}: 32 spp (fixed in its code), glint at 32, {low} and {high} spp, '
            f'{runs} alternating rounds ...')
        bvh_rounds = alternating_rounds([(bvh_peer, 32), (glint_one, 32), (glint_one, low), (glint_one, high)],
                                        runs, os.path.join(folder, 'b2bvh-rounds'), 201)
        bvh_times = [x.wall for x in bvh_rounds[run_label(bvh_peer, 32)]]
        bvh_cpu = [x.cpu for x in bvh_rounds[run_label(bvh_peer, 32)]]
        g32 = bvh_rounds[run_label(glint_one, 32)]
        per_spp = median(bvh_times) / 32
        base = needed[peer.name]
        bvh_needed = dict(base, free=per_spp * base['spp_needed'], half=per_spp * base['spp_needed_half'],
                          curve=per_spp * base['spp_needed_curve'])
        saved = times[glint_one.name], cpu[glint_one.name], images[glint_one.name]
        times[glint_one.name] = [x.wall for x in g32]
        cpu[glint_one.name] = [x.cpu for x in g32]
        images[glint_one.name] = [(None, x.err) for x in g32]
        bvh_to_target = [t * cfg['target'] / 32 for t in bvh_times]
        entry = pair(glint_one.name, bvh_peer.name, bvh_times, bvh_cpu, bvh_needed, bvh_to_target,
                     glint_at_target(bvh_rounds, glint_one),
                     note=f'{bvh_peer.name}: no linear output; its time to the target RMSE = its time per spp x '
                          f'{peer.name}\'s spp needed (same estimator per sample); equal spp at its fixed 32 spp')
        entry['spp'] = 32
        times[glint_one.name], cpu[glint_one.name], images[glint_one.name] = saved
        result['pairs'][f'{bvh_peer.name} / {glint_one.name}'] = entry

    result['ladder'] = points
    result['fits'] = {n: {'free': f['free'], 'slope_half': f['half']} for n, f in fits.items()}
    result['convergence'] = conv
    for name, pts in points.items():
        log(f'  {name:10s} ' + '  '.join(f'{p["spp"]}spp {p["wall"]:.2f}s rmse {p["rmse"] / ref_level:.4f}'
                                          for p in sorted(pts, key=lambda p: p['spp'])))
    for name, e in result['pairs'].items():
        lo, hi = e['equal_rmse_ratio_rounds_range']
        log(f'  to equal RMSE, {name}: {e["equal_rmse_ratio_rounds"]:.2f} ({lo:.2f}-{hi:.2f} over the rounds): '
            f'{e["peer"]} {e["peer_time_to_target_rounds_s"]:.2f} s for {cfg["target"]} spp '
            f'against glint {e["glint_time_to_target_rounds_s"]:.3f} s for {e["glint_spp_needed_rounds"]:.2f} spp; '
            f'from the curves {e["equal_rmse_ratio_curve"]:.2f}')
    log(f'  convergence: {conv["blocks"]} blocks of {BLOCK}x{BLOCK} px x channel, max |z| {conv["max_abs_z"]:.2f}, '
        f'{conv["beyond_4sigma"]} beyond {Z_LIMIT:.0f} sigma -> {"PASS" if conv["pass"] else "FAIL"}; std of z {conv["z_std"]:.2f}; '
        f'mean glint/peer {conv["mean_ratio_glint_over_peer"]:.4f}; '
        f'full-resolution RMSE floor {conv["rmse_floor_relative"]:.4f} of the mean')
    return result


# ---------------------------------------------------------------------------------------------------
# Shading overhead: bench/accel's kernel rays/s against glint's whole-render rays/s

def read_obj_bounds(path):
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    with open(path) as f:
        vs = [list(map(float, line.split()[1:4])) for line in f if line.startswith('v ')]
    v = np.array(vs)
    return v.min(axis=0), v.max(axis=0)


def kernel_rates(mesh_name, min_time, render_scene=None, sets=True):
    """bench/accel's BVH kernel Mrays/s (2 threads) for one scene: on the rays of a glint render of the
    scene replayed in the order the render traced them ('render'; the Cornell box's scene file is built
    into bench/accel, the bunny's is `render_scene`), and, with `sets`, on its ray set of each kind
    (primary, diffuse, shadow: each in pixel order)."""
    out = os.path.join(OUT, f'accel-{mesh_name}.json')
    kinds = 'primary|diffuse|shadow|render' if sets else 'render'
    run([ACCEL, f'--benchmark_filter=^Rays/{mesh_name}/({kinds})/bvh/',  # then real_time
         f'--benchmark_min_time={min_time}', f'--benchmark_out={out}', '--benchmark_out_format=json']
        + ([f'--render-scene={mesh_name}={render_scene}'] if render_scene else []))
    with open(out) as f:
        text = f.read()
    if not text.strip():
        sys.exit(f'bench-peers: {os.path.relpath(ACCEL, ROOT)} ran no {mesh_name} benchmark (renamed?)')
    data = json.loads(text)
    rates = {}
    for b in data['benchmarks']:
        if b.get('error_occurred'):
            sys.exit(f'bench-peers: {b["name"]}: {b.get("error_message", "failed")}')
        kind = b['name'].split('/')[2]
        rates[kind] = b['Mrays/s'] / 1e6 if b['Mrays/s'] > 1e3 else b['Mrays/s']
    if 'render' not in rates:
        sys.exit(f'bench-peers: {os.path.relpath(ACCEL, ROOT)} replayed no render of {mesh_name}')
    return rates


def overhead_rounds(mesh_name, rounds, min_time, render, render_scene=None):
    """The kernel's rates and the whole render's in `rounds` alternating rounds: each round runs bench/accel
    (the sets of one kind only in the first, for the older readings) and then one glint render
    (`render(i)`, a finished Run). Alternating, as the pairs are read, so that the machine's drift during a
    run falls on both sides of each round's ratio; one reading of each had the ratio move by a few per
    cent between runs of the same code. Returns the kernel's rates on its sets of one kind (the first
    round's), the rounds' replay rates, their render rates, and the first render's Run."""
    replays, wholes, sets, first = [], [], None, None
    for i in range(rounds):
        rates = kernel_rates(mesh_name, min_time, render_scene, sets=(i == 0))
        r = render(i)
        if i == 0:
            sets, first = {k: v for k, v in rates.items() if k != 'render'}, r
        replays.append(rates['render'])
        wholes.append(glint_rays_per_second(r.err))
    return sets, replays, wholes, first


def overhead_result(kinds, replays, wholes, render_label, mix=None):
    """Prints and returns one scene's shading overhead: the whole-render rate over the kernel's on the
    same rays, round by round (overhead_rounds); the target is read on the median of the rounds' ratios.
    The kernel's rate is bench/accel's replay of the render's own rays in the order the render traced
    them: the issue's "the same kind of rays" taken as the very rays.
    Also printed, as the notes before 2026-12-03 read it (on the median render rate): the kernel's ray
    sets of each kind, each in pixel order, weighed by the render's shares of the kinds (`mix`, from
    glint's summary; the time per ray of a mix is the mean of the kinds' times weighed by their shares,
    so the rate is the weighted harmonic mean), and on equal shares. Those sets run the kernel faster
    than any render's rays do: neighbouring rays of one kind take the same branches (docs/benchmarks.md,
    "What is measured", item 4)."""
    ratios = [w / r for w, r in zip(wholes, replays)]
    ratio, whole, replay = median(ratios), median(wholes), median(replays)
    equal_mix = len(kinds) / sum(1 / r for r in kinds.values())
    kinds_mix = 1 / sum(mix[k] / kinds[k] for k in kinds) if mix else equal_mix
    log(f'  kernel (glint BVH, 2 threads) on the render\'s own rays, replayed in its order: {replay:.2f} Mrays/s '
        f'(rounds: ' + ', '.join(f'{r:.2f}' for r in replays) + ')')
    log(f'  kernel on its sets of one kind each: ' + ', '.join(f'{k} {v:.2f}' for k, v in kinds.items())
        + f' Mrays/s; on the render\'s mix of kinds {kinds_mix:.2f}'
        + (' (' + ', '.join(f'{k} {100 * v:.1f} %' for k, v in mix.items()) + ')' if mix else ' (equal shares)')
        + f'; on equal shares {equal_mix:.2f}')
    log(f'  glint render ({render_label}): {whole:.2f} Mrays/s (rounds: ' + ', '.join(f'{w:.2f}' for w in wholes) + ')')
    log(f'  whole-render / kernel on the same rays: {ratio:.2f} ({min(ratios):.2f}-{max(ratios):.2f} over '
        f'{len(ratios)} rounds; target >= 0.6); on the sets of one kind: {whole / kinds_mix:.2f} with the '
        f'render\'s mix, {whole / equal_mix:.2f} on equal shares')
    return {'kernel_mrays_per_s': kinds, 'kernel_render_rays_mrays_per_s': replay, 'render_ray_mix': mix,
            'kernel_mix_mrays_per_s': kinds_mix, 'kernel_equal_shares_mrays_per_s': equal_mix,
            'whole_render_mrays_per_s': whole, 'ratio': ratio, 'ratio_rounds': ratios,
            'ratio_range': [min(ratios), max(ratios)], 'kernel_render_rays_rounds': replays,
            'whole_render_rounds': wholes, 'ratio_kinds_mix': whole / kinds_mix,
            'ratio_equal_shares': whole / equal_mix, 'target': 0.6}


def shading_overhead(cfg, cornell_cfg, rounds):
    result = {}
    if not os.path.exists(ACCEL):
        log(f'\n== shading overhead: {ACCEL} is not built: skipped')
        return {'skipped': 'glint_bench_accel not built'}
    if not os.path.exists(BUNNY):
        log(f'\n== shading overhead: {BUNNY} is absent: the bunny is skipped')
        result['bunny'] = {'skipped': f'{BUNNY} absent'}
    else:
        log(f'\n== shading overhead: the bunny (bench/accel kernel vs glint render, 2 threads, {rounds} rounds)')
        # bench/accel's rays: a camera at centre + (0.3, 0.4, 1) x 1.1 |extent| looking at the centre,
        # 512 x 128 rays over +-0.275 horizontally; diffuse bounces from the primary hits; shadow rays
        # to a point light at centre + (-0.5, 1.5, 0.5) |extent|. glint renders the same view with the
        # path tracer at max_depth 2 (primary, one bounce, a shadow ray at each hit), matte 0.5.
        lo, hi = read_obj_bounds(BUNNY)
        c, size = 0.5 * (lo + hi), float(np.linalg.norm(hi - lo))
        eye = c + np.array([0.3, 0.4, 1.0]) * 1.1 * size
        light = c + np.array([-0.5, 1.5, 0.5]) * size
        w, h = cfg['size']
        fov = math.degrees(2 * math.atan(0.275 * h / w))
        scene = os.path.join(OUT, 'bunny.yaml')
        with open(scene, 'w') as f:
            f.write('# Written by bench/peers.py: bench/accel\'s bunny rays, as a glint render.\n'
                    f'render: {{width: {w}, height: {h}, samples: {cfg["spp"]}, integrator: path, max_depth: 2}}\n'
                    f'camera: {{type: pinhole, eye: {list(map(float, eye))}, look_at: {list(map(float, c))}, '
                    f'up: [0, 1, 0], fov: {fov}}}\n'
                    f'objects:\n  - {{type: mesh, file: {BUNNY}, material: {{type: matte, albedo: 0.5}}}}\n'
                    f'lights:\n  - {{type: point, position: {list(map(float, light))}, intensity: {size * size}}}\n')
        sets, replays, wholes, first = overhead_rounds(
            'bunny', rounds, cfg['min_time'],
            lambda i: run([GLINT, 'render', scene, '--threads', '2', '--seed', str(1 + i), '-o',
                           os.path.join(OUT, 'bunny.pfm')]), render_scene=scene)
        result['bunny'] = overhead_result(sets, replays, wholes,
                                          f'path, max_depth 2, {w}x{h}, {cfg["spp"]} spp, 2 threads',
                                          mix=glint_ray_mix(first.err))
    # Cornell: bench/accel replays the rays of a render of rtiow-cornell.yaml (its 400x400 at 16 spp,
    # one thread) and has sets of its camera rays, a cosine bounce from each hit and shadow rays to
    # uniform points of its light; the whole render is glint's on that scene at the Cornell pair's size
    # and equal spp, 2 threads. Read as for the bunny (overhead_result).
    log(f'\n== shading overhead: the Cornell box (bench/accel kernel vs glint render, 2 threads, {rounds} rounds)')
    renderer = glint('examples/rtiow-cornell.yaml', cornell_cfg['size'], 2)
    spp = cornell_cfg['equal']
    sets, replays, wholes, first = overhead_rounds(
        'cornell', rounds, cfg['min_time'],
        lambda i: renderer.render(spp, 1 + i, os.path.join(OUT, 'cornell-overhead.pfm')))
    result['cornell'] = overhead_result(sets, replays, wholes,
                                        f'rtiow-cornell.yaml, {cornell_cfg["size"][0]}x{cornell_cfg["size"][1]}, '
                                        f'{spp} spp, 2 threads', mix=glint_ray_mix(first.err))
    return result


# ---------------------------------------------------------------------------------------------------

def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--mode', choices=sorted(MODES), default=os.environ.get('BENCH_MODE', 'fast'))
    parser.add_argument('--runs', type=int, help='alternating runs at equal spp (default: 3 fast, 5 full)')
    parser.add_argument('--only', nargs='*', choices=['smallpt', 'smallpt-bsdf-only', 'rtiow', 'cornell', 'overhead'],
                        help='measure only these (default: all)')
    parser.add_argument('--glint', help='the glint binary to measure (default: build/release/glint), e.g. '
                        'an older build for a before/after comparison on the same peers and references')
    parser.add_argument('--out', help='where images and results.json go (default: build/bench-peers)')
    args = parser.parse_args()
    global GLINT, OUT
    GLINT = os.path.abspath(args.glint) if args.glint else GLINT
    OUT = os.path.abspath(args.out) if args.out else OUT
    mode = MODES[args.mode]
    runs = args.runs or mode['runs']
    only = set(args.only or ['smallpt', 'smallpt-bsdf-only', 'rtiow', 'cornell', 'overhead'])
    if not os.path.exists(GLINT):
        sys.exit(f'bench-peers: {GLINT} is missing: make build first')
    os.makedirs(OUT, exist_ok=True)
    t_start = time.perf_counter()
    build_peers()
    # Which binaries ran, by content: a copy made before a rebuild finished (or an experiment's build
    # left in build/release) looks like any other glint, and once a note's figures came from one.
    binaries = {name: file_digest(path) for name, path in (('glint', GLINT), ('glint_bench_accel', ACCEL))
                if os.path.exists(path)}
    log('binaries (sha256, first 16 hex digits): '
        + ', '.join(f'{name} {digest}' for name, digest in binaries.items()))
    results = {'mode': args.mode, 'runs': runs, 'glint': GLINT, 'binaries_sha256': binaries, 'scenes': {}}

    if 'smallpt' in only:
        cfg = mode['smallpt']
        results['scenes']['smallpt'] = measure_scene(
            'smallpt', cfg, runs, smallpt(cfg['size'], 2), glint('examples/smallpt.yaml', cfg['size'], 2),
            ref_peer=smallpt(cfg['size'], 1))
    if 'smallpt-bsdf-only' in only:
        # smallpt's own estimator in glint: no light sample, light found only by BSDF samples (the path
        # integrator's sample_lights: false). Not glint's default, so no target is read from it: it
        # tells what of the equal-spp ratio above is the cost of next-event estimation's shadow rays and
        # what is glint's machinery. Its noise per sample is smallpt's kind, so its ladder is smallpt's.
        cfg = {k: v for k, v in mode['smallpt'].items() if k != 'glint_ladder'}
        results['scenes']['smallpt-bsdf-only'] = measure_scene(
            'smallpt-bsdf-only', cfg, runs, smallpt(cfg['size'], 2),
            glint('examples/smallpt.yaml', cfg['size'], 2, sample_lights=False),
            ref_peer=smallpt(cfg['size'], 1), ref_key='smallpt')
    if 'rtiow' in only:
        cfg = mode['rtiow']
        results['scenes']['rtiow-final'] = measure_scene(
            'rtiow', cfg, runs, rtiow('b1f'), glint('examples/rtiow-final.yaml', cfg['size'], 1),
            glint('examples/rtiow-final.yaml', cfg['size'], 2), bvh_peer=rtiow('b2bvh', takes_args=False))
    if 'cornell' in only:
        cfg = mode['cornell']
        results['scenes']['rtiow-cornell'] = measure_scene(
            'cornell', cfg, runs, rtiow('b2cbf'), glint('examples/rtiow-cornell.yaml', cfg['size'], 1),
            glint('examples/rtiow-cornell.yaml', cfg['size'], 2))
    if 'overhead' in only:
        results['shading_overhead'] = shading_overhead(mode['bunny'], mode['cornell'], runs)

    results['seconds'] = time.perf_counter() - t_start
    results['commands'] = COMMANDS
    with open(os.path.join(OUT, 'results.json'), 'w') as f:
        json.dump(results, f, indent=1)

    log('\ncommands run (cwd: the repository unless shown):')
    for c in COMMANDS:
        log('  ' + c)
    log(f'\n== bench-peers ({args.mode} mode, medians of {runs} alternating runs; ratios peer/glint: > 1 means '
        'glint is faster)')
    log(f'{"pair":24s} {"scene":14s} {"spp":>4s} {"eq-spp wall":>11s} {"(cpu)":>6s} {"eq-RMSE":>8s} '
        f'{"(rounds)":>13s} {"(curve)":>8s} {"(line)":>8s} {"(slope -1/2)":>12s} {"slopes peer/glint":>17s}  convergence')
    for scene, r in results['scenes'].items():
        for name, p in r['pairs'].items():
            c = p['convergence']
            lo, hi = p['equal_rmse_ratio_rounds_range']
            log(f'{name:24s} {scene:14s} {p["spp"]:4d} {p["equal_spp_ratio"]:11.2f} {p["equal_spp_cpu_ratio"]:6.2f} '
                f'{p["equal_rmse_ratio_rounds"]:8.2f} {f"{lo:.2f}-{hi:.2f}":>13s} '
                f'{p["equal_rmse_ratio_curve"]:7.2f}{"*" if p["extrapolated_curve"] else " "} '
                f'{p["equal_rmse_ratio"]:7.2f}{"*" if p["extrapolated"] else " "} '
                f'{p["equal_rmse_ratio_slope_half"]:12.2f} {p["peer_slope"]:8.2f}/{p["glint_slope"]:<8.2f}  '
                f'{"PASS" if c["pass"] else "FAIL"} (max|z| {c["max_abs_z"]:.1f}, {c["beyond_4sigma"]}/{c["blocks"]} > 4σ)')
    log('eq-RMSE: the median over the alternating rounds of the peer\'s time at its target spp (its RMSE there is '
        'the target) over glint\'s at the spp it needs for that RMSE (from a quadratic fit of log RMSE on log spp; its '
        'time interpolated between its runs at the whole spp either side, in the same round); rounds: the lowest and '
        'highest round. curve: the same ratio read from quadratics of log RMSE on log wall time through all the '
        'points (* = outside the measured times); line: from a straight line (free slope); slope -1/2: a line of '
        'slope fixed at -1/2. cpu: the CPU-time ratio at equal spp.')
    for name, p in [(n, p) for r in results['scenes'].values() for n, p in r['pairs'].items() if p['note']]:
        log(f'note ({name}): {p["note"]}')
    log(f'results: {os.path.relpath(os.path.join(OUT, "results.json"), ROOT)}; '
        f'{results["seconds"]:.0f} s in all')


if __name__ == '__main__':
    main()

"""The Python module glint (python/glint_module.cpp), run by ctest as python.pytest.

It must render exactly what `glint render -o x.pfm` writes, raise glint.SceneError with the position of a
mistake, honour its keywords as the command's flags, and run examples/python/render.py. The environment
gives the module (PYTHONPATH), the command (GLINT_CLI) and the sources (GLINT_SOURCE_DIR).
"""
import os
import pathlib
import subprocess
import sys
import time

import numpy as np
import pytest

import glint

CLI = os.environ["GLINT_CLI"]
SOURCE = pathlib.Path(os.environ["GLINT_SOURCE_DIR"])
SPHERES = SOURCE / "examples" / "spheres.yaml"

# A matte floor of albedo (0.2, 0.4, 0.6) seen from above, under a sun of irradiance π straight above:
# every pixel shows ρ/π · E cos 0 = ρ (docs/scene-format.md, `directional`), whatever the samples.
FLOOR = """\
render: {width: 8, height: 6, samples: 2}
camera: {type: orthographic, eye: [0, 5, 0], look_at: [0, 0, 0], height: 4}
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: [0.2, 0.4, 0.6]}}
lights:
  - {type: directional, direction: [0, -1, 0], irradiance: 3.14159265358979}
"""


def read_pfm(path):
    """A colour PFM as glint writes it: 'PF', width, height, a negative scale (little-endian), rows bottom
    to top. Returned top row first, as glint.render returns the film."""
    data = pathlib.Path(path).read_bytes()
    magic, width, height, scale, pixels = data.split(maxsplit=4)
    assert magic == b"PF" and float(scale) < 0
    width, height = int(width), int(height)
    image = np.frombuffer(pixels, dtype="<f4", count=width * height * 3).reshape(height, width, 3)
    return image[::-1]


def cli_render(scene, tmp_path, *flags):
    output = tmp_path / "cli.pfm"
    subprocess.run([CLI, "render", str(scene), "-q", "-o", str(output), *flags], check=True)
    return read_pfm(output)


def same_bits(a, b):
    return a.shape == b.shape and np.array_equal(a.view(np.uint32), b.view(np.uint32))


def test_render_is_the_command_s_pfm_bit_for_bit(tmp_path):
    image = glint.render(str(SPHERES), width=96, height=54, spp=4, seed=7)
    assert image.dtype == np.float32 and image.shape == (54, 96, 3)
    assert image.flags["C_CONTIGUOUS"]
    cli = cli_render(SPHERES, tmp_path, "--width", "96", "--height", "54", "--spp", "4", "--seed", "7")
    assert same_bits(image, cli)
    assert image.mean() > 0.01  # the scene is lit: equal images of nothing would prove nothing


def test_keywords_are_the_command_s_flags(tmp_path):
    keywords = dict(width=40, height=30, spp=8, seed=3, integrator="path", sampler="halton", max_depth=3)
    flags = ["--width", "40", "--height", "30", "--spp", "8", "--seed", "3", "--integrator", "path",
             "--sampler", "halton", "--max-depth", "3", "--set", "camera.fov=30"]
    image = glint.render(SPHERES, sets=["camera.fov=30"], **keywords)  # a pathlib.Path, too
    assert same_bits(image, cli_render(SPHERES, tmp_path, *flags))
    # each keyword changes the image: without it (or with another value) the bits differ
    assert not same_bits(image, glint.render(SPHERES, **keywords))
    assert not same_bits(image, glint.render(SPHERES, sets=["camera.fov=30"], **{**keywords, "seed": 4}))
    assert not same_bits(image, glint.render(SPHERES, sets=["camera.fov=30"], **{**keywords, "spp": 4}))


def test_threads_do_not_change_the_bits():
    one = glint.render(SPHERES, width=48, height=32, spp=4, threads=1)
    assert same_bits(one, glint.render(SPHERES, width=48, height=32, spp=4, threads=2))
    assert same_bits(one, glint.render(SPHERES, width=48, height=32, spp=4, threads=0))


def test_scene_text_renders_its_known_radiance():
    image = glint.render(FLOOR)
    assert image.shape == (6, 8, 3)
    np.testing.assert_allclose(image, np.broadcast_to([0.2, 0.4, 0.6], image.shape), rtol=1e-6)
    assert glint.render(FLOOR, width=5, height=3).shape == (3, 5, 3)


def test_no_scene_is_the_built_in_default_scene(tmp_path):
    image = glint.render(width=32, height=18, spp=1)
    output = tmp_path / "default.pfm"
    subprocess.run([CLI, "render", "-q", "-o", str(output), "--width", "32", "--height", "18", "--spp", "1"],
                   check=True)
    assert same_bits(image, read_pfm(output))


def test_crop_returns_the_window_of_the_full_render():
    full = glint.render(SPHERES, width=40, height=30, spp=2)
    window = glint.render(SPHERES, width=40, height=30, spp=2, sets=["render.crop=[5, 10, 25, 20]"])
    assert same_bits(window, np.ascontiguousarray(full[10:20, 5:25]))


def test_a_mistake_in_a_file_raises_its_position(tmp_path):
    scene = tmp_path / "broken.yaml"
    scene.write_text("render: {width: 8, height: 8}\n"
                     "objects:\n"
                     "  - {type: sphere, radious: 1}\n")
    with pytest.raises(glint.SceneError) as raised:
        glint.render(str(scene))
    error = raised.value
    assert isinstance(error, ValueError)
    assert (error.file, error.line, error.column) == (str(scene), 3, 20)  # 'radious' starts in column 20
    assert "did you mean 'radius'" in error.message
    assert str(error).startswith(f"{scene}:3:20: error: unknown key 'radious'")
    assert "  - {type: sphere, radious: 1}" in str(error)  # the line, quoted, with a caret below


def test_a_mistake_in_text_and_in_a_keyword_is_positioned():
    with pytest.raises(glint.SceneError) as raised:
        glint.render("render: {width: 8, height: 8}\nobjects: [}\n")
    assert (raised.value.file, raised.value.line) == ("<scene text>", 2)
    with pytest.raises(glint.SceneError) as raised:
        glint.render(FLOOR, sets=["render.samplse=4"])
    assert (raised.value.file, raised.value.line, raised.value.column) == ("--set", 1, 8)
    assert "did you mean 'samples'" in raised.value.message
    with pytest.raises(glint.SceneError):
        glint.render(FLOOR, spp=0)
    with pytest.raises(ValueError):
        glint.render(FLOOR, threads=-1)


def test_a_missing_file_is_a_scene_error_without_a_line(tmp_path):
    with pytest.raises(glint.SceneError) as raised:
        glint.render(str(tmp_path / "missing.yaml"))
    assert raised.value.file == str(tmp_path / "missing.yaml")
    assert raised.value.line is None and raised.value.column is None
    assert "does not exist" in str(raised.value)


def test_a_scene_that_would_render_black_warns():
    with pytest.warns(glint.SceneWarning, match="no light"):
        glint.render("objects: [{type: sphere, radius: 1}]\nrender: {width: 4, height: 4, samples: 1}\n")


def test_ctrl_c_stops_a_render_with_keyboard_interrupt():
    # A render of minutes, interrupted by SIGINT after half a second: KeyboardInterrupt, within seconds.
    script = (
        "import os, signal, threading, glint\n"
        "threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT)).start()\n"
        f"glint.render({str(SPHERES)!r}, width=1920, height=1080, spp=4096, integrator='path')\n"
    )
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    assert done.returncode != 0 and "KeyboardInterrupt" in done.stderr, done.stderr
    assert time.monotonic() - start < 30


def test_the_example_script_runs_and_saves_the_film(tmp_path):
    output = tmp_path / "cornell.npy"
    done = subprocess.run([sys.executable, str(SOURCE / "examples" / "python" / "render.py"), "-o", str(output),
                           "--spp", "4", "--size", "32"], capture_output=True, text=True, check=True)
    assert "mean radiance (r, g, b):" in done.stdout and "noise" in done.stdout
    saved = np.load(output)
    cornell = SOURCE / "examples" / "cornell-box.yaml"
    assert same_bits(saved, glint.render(str(cornell), spp=4, width=32, height=32, seed=1))
    assert (tmp_path / "cornell.ppm").read_bytes().startswith(b"P6\n32 32\n255\n")

# The two commands of the README, over the CMake presets.
#   make render   install dependencies, build (Release), render the built-in default scene to default.png
#   make test     install dependencies, build, run the whole test suite
# Also: make sanitize (tests under ASan + UBSan), make bench, make format, make examples,
#       make fuzz (the libFuzzer harnesses, FUZZ_SECONDS each; fuzz/README.md),
#       make bench-peers (glint against smallpt's and the RTIOW books' own code; BENCH_MODE=fast or full;
#       docs/benchmarks.md).
WERROR ?= $(if $(CI),ON,OFF)
CMAKE_FLAGS = -DGLINT_WERROR=$(WERROR)
FUZZ_SECONDS ?= 60
FUZZ_HARNESSES ?=
BENCH_MODE ?= fast
# Debian's python3, where install-deps puts python3-numpy (a python3 earlier on PATH may lack it).
PYTHON ?= $(if $(wildcard /usr/bin/python3),/usr/bin/python3,python3)

.PHONY: deps build render test sanitize fuzz bench bench-peers format examples clean

deps:
	./scripts/install-deps.sh

build: deps
	cmake --preset release $(CMAKE_FLAGS) >/dev/null
	cmake --build --preset release

render: build
	./build/release/glint render -o default.png

test: build
	ctest --preset release

sanitize: deps
	cmake --preset sanitize $(CMAKE_FLAGS) >/dev/null
	cmake --build --preset sanitize
	ctest --preset sanitize

fuzz: deps
	cmake --preset fuzz $(CMAKE_FLAGS) >/dev/null
	cmake --build --preset fuzz
	FUZZ_SECONDS=$(FUZZ_SECONDS) ./fuzz/run.sh $(FUZZ_HARNESSES)

bench: build
	./build/release/bench/glint_bench_scene --benchmark_min_time=2

bench-peers: build
	$(PYTHON) bench/peers.py --mode $(BENCH_MODE)

format:
	find src apps tests bench fuzz python examples/library -name '*.cpp' -o -name '*.hpp' | xargs clang-format -i

examples: build
	./scripts/render-examples.sh build/examples

clean:
	rm -rf build

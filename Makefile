# make run   : install what the demo needs (the package and its light dependencies, no dev/3D extras), build,
#              run the demo on the built-in cross-section
# make test  : install what is missing (the dev extra: 3D backends, test tools), build, run the C++ tests
#              (ctest) and the Python tests (pytest)
# make dev   : incremental developer build (through ccache when installed); puts _core next to the sources
#              (use PYTHONPATH=src)
# make stubs : regenerate src/nonobtuse/_core.pyi from the built _core (after make dev; commit the result)
# make mypy  : type-check src/nonobtuse against those stubs
# make sanitize : the C++ tests and a Python smoke run (.ci/sanitize-smoke) under AddressSanitizer and
#              UndefinedBehaviorSanitizer, built in build/sanitize; any report stops the run with an error
SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
APT_PACKAGES := libcgal-dev libgmp-dev libmpfr-dev libboost-dev libgtest-dev cmake ninja-build
BUILD := build/pkg

.PHONY: run test dev sanitize deps install install-demo clean stubs mypy

run: install-demo
	$(VENV)/bin/nonobtuse demo

test: install
	ctest --test-dir $(BUILD) --output-on-failure -j2
	$(PY) -m pytest -q -n 2

deps:
	@missing=$$(for p in $(APT_PACKAGES); do dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q "install ok installed" || echo $$p; done); \
	if [ -n "$$missing" ]; then \
	  echo "Installing system packages:" $$missing; \
	  if [ "$$(id -u)" != 0 ]; then echo "Run as root, or install: $$missing" >&2; exit 1; fi; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing; \
	fi

$(PY):
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip

install-demo: deps $(PY)
	$(PY) -m pip install -q ".[demo]" -Cbuild-dir=$(BUILD)

install: deps $(PY)
	$(PY) -m pip install -q ".[dev]" -Cbuild-dir=$(BUILD) -Ccmake.define.NONOBTUSE_BUILD_TESTS=ON

dev: deps $(PY)
	$(PY) -m pip install -q scikit-build-core pybind11 ninja
	cmake -S . -B build/dev -G Ninja -DCMAKE_BUILD_TYPE=$${BUILD_TYPE:-Release} -DNONOBTUSE_BUILD_TESTS=ON \
	  -DPython_EXECUTABLE=$(abspath $(PY)) -Dpybind11_DIR=$$($(PY) -m pybind11 --cmakedir) \
	  $$(command -v ccache >/dev/null && echo -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
	cmake --build build/dev
	cp build/dev/_core*.so src/nonobtuse/

stubs:
	PYTHONPATH=src $(PY) -m pybind11_stubgen nonobtuse._core -o src --exit-code

mypy:
	$(PY) -m mypy

SANITIZE := build/sanitize
# exitcode=86: a sanitizer report never passes for one of the CLI's exit codes. Leaks are checked in the C++
# tests only: CPython keeps its interned objects alive, so every Python run would report them.
SANITIZER_ENV = ASAN_OPTIONS=halt_on_error=1:detect_leaks=$(1):exitcode=86 \
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:exitcode=86

# -O1 -g: readable reports at a fraction of -O2's compile time. Python runs preload the ASan runtime (it must
# come first) and libstdc++: the python binary does not link libstdc++, so without it ASan's __cxa_throw
# interceptor finds no real __cxa_throw and aborts at the first C++ exception (CGAL's interval filters throw).
sanitize: deps $(PY)
	$(PY) -m pip install -q scikit-build-core pybind11 ninja
	cmake -S . -B $(SANITIZE) -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
	  -DNONOBTUSE_SANITIZE=address,undefined -DNONOBTUSE_BUILD_TESTS=ON \
	  -DPython_EXECUTABLE=$(abspath $(PY)) -Dpybind11_DIR=$$($(PY) -m pybind11 --cmakedir) \
	  $$(command -v ccache >/dev/null && echo -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
	cmake --build $(SANITIZE)
	$(call SANITIZER_ENV,1) $(SANITIZE)/nonobtuse_tests --gtest_brief=1
	rm -rf $(SANITIZE)/py && mkdir -p $(SANITIZE)/py && cp -r src/nonobtuse $(SANITIZE)/py/
	rm -f $(SANITIZE)/py/nonobtuse/_core*.so && cp $(SANITIZE)/_core*.so $(SANITIZE)/py/nonobtuse/
	$(call SANITIZER_ENV,0) LD_PRELOAD="$$($(CXX) -print-file-name=libasan.so) $$($(CXX) -print-file-name=libstdc++.so)" \
	  PYTHONPATH=$(SANITIZE)/py \
	  .ci/sanitize-smoke $(abspath $(PY)) $(SANITIZE)/smoke

clean:
	rm -rf build src/nonobtuse/_core*.so

# make run   : install what is missing, build, run the demo on the built-in cross-section
# make test  : install what is missing, build, run the C++ tests (ctest) and the Python tests (pytest)
# make dev   : incremental developer build (through ccache when installed); puts _core next to the sources
#              (use PYTHONPATH=src)
# make stubs : regenerate src/nonobtuse/_core.pyi from the built _core (after make dev; commit the result)
# make mypy  : type-check src/nonobtuse against those stubs
SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
APT_PACKAGES := libcgal-dev libgmp-dev libmpfr-dev libboost-dev libgtest-dev cmake ninja-build \
                libusb-1.0-0 libvulkan1 mesa-vulkan-drivers
BUILD := build/pkg

.PHONY: run test dev deps install clean stubs mypy

run: install
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

clean:
	rm -rf build src/nonobtuse/_core*.so

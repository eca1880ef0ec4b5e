# Scout: every target does its own set-up (Debian packages, configure, build).
#   make run    install, build, run the main job on the built-in default world
#   make test   install, build, run the whole test suite
# PRESET=release|debug|asan selects the CMake preset (default release).

PRESET ?= release
JOBS ?= 2
BUILD_DIR := build/$(PRESET)
SCOUT := $(BUILD_DIR)/apps/scout/scout

.PHONY: all setup configure build run test test-asan bench format clean

all: build

setup:
	bash scripts/setup

configure: setup
	cmake --preset $(PRESET)

build: configure
	cmake --build --preset $(PRESET) -j $(JOBS)

run: build
	$(SCOUT) explore --world office --seed 1 --out out/explore

test: build
	ctest --preset $(PRESET)

test-asan:
	$(MAKE) test PRESET=asan

bench: build
	$(BUILD_DIR)/bench/scout_bench

format:
	find src apps bench -name '*.h' -o -name '*.cc' | xargs clang-format -i

clean:
	rm -rf build out

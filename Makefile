# Scout: every target does its own set-up (Debian packages, configure, build).
#   make run    install, build, run the main job on the built-in default world
#   make test   install, build, run the whole test suite
#   make results / results-quick   the evaluation behind docs/RESULTS.md (full / small)
# PRESET=release|debug|asan|tsan selects the CMake preset (default release).

PRESET ?= release
JOBS ?= 2
BUILD_DIR := build/$(PRESET)
SCOUT := $(BUILD_DIR)/apps/scout/scout

.PHONY: all setup configure build run test test-asan test-tsan bench results results-quick format clean

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

# ThreadSanitizer (11 minutes on 2 cores from scratch before the unity builds, not measured since;
# not in CI, whose three steps take about 17 minutes).
test-tsan:
	$(MAKE) test PRESET=tsan

bench: build
	$(BUILD_DIR)/bench/scout_bench
	$(BUILD_DIR)/bench/scout_report_bench

# The whole evaluation (hours; resumable): out/results/, docs/RESULTS.md, docs/figures/.
# RESULTS_ARGS: options of scripts/results, e.g. RESULTS_ARGS="--only 'explore-museum-*'".
results: build
	SCOUT=$(SCOUT) bash scripts/results $(RESULTS_ARGS)

# A few minutes: small worlds and prefixes into out/results-quick/, checked for tables and figures.
results-quick: build
	SCOUT=$(SCOUT) bash scripts/results --quick

format:
	find src apps bench -name '*.h' -o -name '*.cc' | xargs clang-format -i

clean:
	rm -rf build out

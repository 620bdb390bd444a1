# creaturelab: `make reproduce` runs the default experiments; `make test` builds and runs every test.
BUILD      ?= build
ASAN_BUILD ?= build-asan
JOBS       ?= $(shell nproc)
CMAKE_ARGS ?=
# New build trees use Ninja (scripts/deps.sh installs it); an existing tree keeps its generator.
generator = $(if $(wildcard $(1)/CMakeCache.txt),,-G Ninja)
# The sanitizer tree at -O1 with line tables (-g1: file and line in reports): it compiles in about
# half the time of RelWithDebInfo's -O2 -g. Its test programs and bookkeeping libraries go down to -O0
# (CMakeLists.txt, CREATURELAB_TEST_OPT).
ASAN_FLAGS = -O1 -g1 -DNDEBUG
REPRO_LOG  = $(BUILD)/reproduce-build.log

.PHONY: all deps configure build test test-asan test-asan-build test-asan-run test-quick reproduce-build reproduce reproduce-full bench clean

all: build

deps:
	@scripts/deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(call generator,$(BUILD)) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS) >/dev/null

# The libraries, the binary and the test programs (the benchmarks: make bench).
build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Release tests (unit, physics, cli, regression baselines), then the unit tests under ASan+UBSan.
test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory test-asan

# The sanitizer tree builds only the unit-test programs and the libraries they link. It is compiled
# by clang, which instruments for ASan+UBSan in about half of gcc's time; a tree configured with
# another compiler starts afresh.
ASAN_CONFIG = -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$(ASAN_FLAGS)" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=$(ASAN_FLAGS)" \
  -DCREATURELAB_SANITIZE=ON -DCREATURELAB_BUILD_BENCH=OFF -DCREATURELAB_WITH_MPI=OFF
test-asan: test-asan-build
	@$(MAKE) --no-print-directory test-asan-run

test-asan-build: deps
	@if [ -f $(ASAN_BUILD)/CMakeCache.txt ] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang++$$' $(ASAN_BUILD)/CMakeCache.txt; then \
	  echo "test-asan: $(ASAN_BUILD) was configured with another compiler: configuring it afresh with clang++"; \
	  rm -rf $(ASAN_BUILD); fi
	@gen=; [ -f $(ASAN_BUILD)/CMakeCache.txt ] || gen="-G Ninja"; \
	  cmake -S . -B $(ASAN_BUILD) $$gen $(ASAN_CONFIG) $(CMAKE_ARGS) >/dev/null
	@cmake --build $(ASAN_BUILD) -j $(JOBS) --target unit_tests

# Each unit-test program is one test in the sanitizer tree (tests/CMakeLists.txt).
test-asan-run:
	ASAN_OPTIONS=detect_leaks=0 ctest --test-dir $(ASAN_BUILD) -L unit --output-on-failure -j $(JOBS)

# One module's unit tests in the Release tree, for the edit-compile-test loop: builds what they
# need and runs them, e.g. make test-quick MODULE=fluid (the modules: tests/unit/*.cmake).
test-quick: $(if $(wildcard $(BUILD)/CMakeCache.txt),,configure)
	@[ -n "$(MODULE)" ] && [ -f tests/unit/$(MODULE).cmake ] || { echo "usage: make test-quick MODULE=<$$(cd tests/unit && ls *.cmake | sed 's/\.cmake$$//' | paste -sd'|')>" >&2; exit 2; }
	@cmake --build $(BUILD) -j $(JOBS) --target quick_$(MODULE)

# The binary alone, for the runs; the dependency check's and the compiler's output go to REPRO_LOG.
reproduce-build:
	@mkdir -p $(BUILD); echo "reproduce: building creaturelab (log: $(REPRO_LOG))"; \
	  { scripts/deps.sh && cmake -S . -B $(BUILD) $(call generator,$(BUILD)) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS) \
	    && cmake --build $(BUILD) -j $(JOBS) --target creaturelab; } >$(REPRO_LOG) 2>&1 \
	  || { tail -n 40 $(REPRO_LOG) >&2; echo "reproduce: the build failed (whole log: $(REPRO_LOG))" >&2; exit 1; }

# The runs; the contraction spline fitted to the reproduced bell; the 3-D creatures' controlled
# points as .glb (creature-glb: geoms, and flesh when recorded); every figure drawn from the HDF5
# alone (analysis/draw_runs.py); report.html + REPORT.md (analysis/report.py), whose paths are the
# last lines printed. The runs' exit code stands (4 when only drawing or the report failed).
REPRO_OUT ?= results/runs/reproduce
# The Hermite contraction curve (Rudolf & Mould §3.3) fitted to the staggered bell's diameter over
# the cycles after its warm-up at 0.65 Hz: point 0 of the Fig. 4 claim's run (stagger), the pulse
# released from the apex first (analysis/figures/catalog.py repeats this command).
FIT_SPLINE = fit spline
FIT_SPLINE_ARGS = --point 0 --knots 4 --from 1.5384615384615385
define reproduce_in
	@$(BUILD)/creaturelab reproduce --list $(1) --out $(2); status=$$?; \
	  if [ -f $(2)/stagger/index.h5 ]; then rm -rf $(2)/fit_spline; \
	    $(BUILD)/creaturelab $(FIT_SPLINE) $(2)/stagger $(FIT_SPLINE_ARGS) --out $(2)/fit_spline >/dev/null \
	      || status=$$((status ? status : 4)); fi; \
	  for run in flyer3d flyer3d_twist flyer3d_flesh; do if [ -f $(2)/$$run/index.h5 ]; then \
	    $(BUILD)/creaturelab creature-glb $(2)/$$run --point 0 >/dev/null || status=$$((status ? status : 4)); fi; done; \
	  /usr/bin/python3 analysis/draw_runs.py $(2) >/dev/null || status=$$((status ? status : 4)); \
	  /usr/bin/python3 analysis/report.py $(2) || status=$$((status ? status : 4)); \
	  exit $$status
endef

reproduce: reproduce-build
	$(call reproduce_in,experiments/reproduce.toml,$(REPRO_OUT))

# The resolved (long) versions; the list says how long it takes before it starts.
reproduce-full: reproduce-build
	$(call reproduce_in,experiments/reproduce_full.toml,results/runs/reproduce_full)

bench: configure
	@cmake --build $(BUILD) -j $(JOBS) --target benches
	@for b in $(BUILD)/tests/bench_*; do [ -x "$$b" ] && "$$b"; done

clean:
	rm -rf $(BUILD) $(ASAN_BUILD)

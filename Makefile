# creaturelab: `make reproduce` runs the default experiments; `make test` builds and runs every test.
BUILD      ?= build
ASAN_BUILD ?= build-asan
JOBS       ?= $(shell nproc)
CMAKE_ARGS ?=

.PHONY: all deps configure build test test-asan reproduce bench clean

all: build

deps:
	@scripts/deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Release tests (unit, physics, cli, regression baselines), then the unit tests under ASan+UBSan.
test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory test-asan

test-asan: deps
	@cmake -S . -B $(ASAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCREATURELAB_SANITIZE=ON \
	  -DCREATURELAB_BUILD_BENCH=OFF -DCREATURELAB_WITH_MPI=OFF $(CMAKE_ARGS) >/dev/null
	@cmake --build $(ASAN_BUILD) -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=0 ctest --test-dir $(ASAN_BUILD) -L unit --output-on-failure -j $(JOBS)

# The runs, then their figures from the HDF5 alone (analysis/draw_runs.py); the runs' exit code stands.
reproduce: build
	@$(BUILD)/creaturelab reproduce; status=$$?; \
	  /usr/bin/python3 analysis/draw_runs.py results/runs/reproduce || status=$$((status ? status : 4)); \
	  echo "figures: results/runs/reproduce/*/figures/ (Figs. 7, 9, 10 and the 3-D swim: results/runs/reproduce/render_swim/render_point_000000/)"; \
	  exit $$status

bench: build
	@for b in $(BUILD)/tests/bench_*; do [ -x "$$b" ] && "$$b"; done

clean:
	rm -rf $(BUILD) $(ASAN_BUILD)

# PERIDYNAMICS_EXT front door. `make demo` and `make test` work on a fresh
# Debian machine: they install missing packages and fetch LAMMPS's source.

PDEXT_CACHE       ?= $(HOME)/.cache/pdext
# LAMMPS=2026: LAMMPS 4 Jul 2026 (Debian unstable), built in build/;
# LAMMPS=2021: LAMMPS 29 Sep 2021 (Debian bookworm), the oldest tested tree,
# built in build/lammps-2021. LAMMPS_SOURCE_DIR=<tree> builds another tree.
LAMMPS            ?= 2026
ifeq ($(LAMMPS),2026)
BUILD_DIR         ?= build
else
BUILD_DIR         ?= build/lammps-$(LAMMPS)
endif
JOBS              ?= $(shell nproc)
LAMMPS_SOURCE_DIR ?=
# PORTABLE=1: the C core for any CPU of this architecture (no -march=native),
# for binaries and plugins copied to other machines
PORTABLE          ?= 0
FULL              ?= 0
# make bench PASSES=N: passes over the block's styles (bench/report.py's
# default, 3, when empty; more on a noisy machine)
PASSES            ?=

# ccache keeps compiled LAMMPS objects outside the work tree, so a fresh clone
# recompiles nothing that did not change.
export CCACHE_DIR      ?= $(PDEXT_CACHE)/ccache
export CCACHE_BASEDIR  := $(CURDIR)
export CCACHE_NOHASHDIR := 1

LMP := $(BUILD_DIR)/lmp
STAMP_SETUP := $(PDEXT_CACHE)/.setup-ok

.PHONY: all setup configure build plugin test demo bench accuracy validate clean

all: build

setup: $(STAMP_SETUP)
$(STAMP_SETUP): tools/setup-deps.sh
	./tools/setup-deps.sh
	mkdir -p $(PDEXT_CACHE) && touch $@

# Configure every time (a few seconds): new style files are registered with
# LAMMPS at configure time; unchanged style headers cause no recompilation.
configure: | $(STAMP_SETUP)
	src="$(LAMMPS_SOURCE_DIR)"; \
	[ -n "$$src" ] || src=$$(./tools/fetch-lammps.sh $(PDEXT_CACHE) $(LAMMPS)); \
	old=$$(sed -n 's/^LAMMPS_SOURCE_DIR:PATH=//p' $(BUILD_DIR)/CMakeCache.txt 2>/dev/null); \
	if [ -n "$$old" ] && [ "$$old" != "$$src" ]; then \
	  echo "build: $(BUILD_DIR) was configured for $$old; starting it afresh for $$src"; \
	  find $(BUILD_DIR) -mindepth 1 -maxdepth 1 ! -name 'lammps-*' -exec rm -rf {} +; fi; \
	cmake -S . -B $(BUILD_DIR) -DLAMMPS_SOURCE_DIR="$$src" \
	  -DPDEXT_PORTABLE=$(if $(filter 1,$(PORTABLE)),ON,OFF) \
	  -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >/dev/null

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The plugin alone (build/pdext.so), for 'plugin load' into another LAMMPS
plugin: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target pdext
	@echo "plugin: $(BUILD_DIR)/pdext.so ('plugin load' it in a LAMMPS with the PLUGIN package)"

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# the demo needs lmp alone (not the plugin and its plain LAMMPS)
demo: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target lmp
	./examples/impact-demo/run.sh $(LMP)

# The benchmark block's tables (1-3 minutes); FULL=1 adds the size sweep,
# family build, memory per bond and 2 ranks (5-13 minutes). bench/README.md
bench: build
	FULL=$(FULL) PASSES=$(PASSES) ./bench/run.sh $(LMP)

# Accuracy against cost: the full sweeps (two LAMMPS runs side by side, one
# on each core: about 100 minutes), the report with its Pareto plots and, at its end, the
# recommendation table (deck lines per quantity and target) in
# build/accuracy/report.md
accuracy: build
	python3 tools/accuracy/run.py --mode full --jobs 2 --lmp $(LMP) --exact $(BUILD_DIR)/pd_exact --out $(BUILD_DIR)/accuracy

# Long runs at the papers' resolutions, with their reference numbers printed;
# the short accuracy sweeps (under 10 minutes: build/accuracy-short/report.md)
validate: build
	python3 tools/accuracy/run.py --mode short --lmp $(LMP) --exact $(BUILD_DIR)/pd_exact --out $(BUILD_DIR)/accuracy-short
	PDEXT_LMP=$(LMP) PDEXT_VALIDATE=1 python3 unittest/lammps/test_fracture.py
	PDEXT_LMP=$(LMP) PDEXT_VALIDATE=1 python3 unittest/lammps/test_examples.py
	for t in unittest/stability/test_*.py; do PDEXT_LMP=$(LMP) PDEXT_VALIDATE=1 python3 $$t || exit 1; done
	./examples/fragmentation-tube/run.sh $(LMP)
	@# valgrind runs no AVX-512 code: its decks take a portable build of the same sources
	$(MAKE) build BUILD_DIR=$(BUILD_DIR)/portable PORTABLE=1
	./unittest/valgrind/run.sh $(BUILD_DIR)/portable/lmp

clean:
	rm -rf $(BUILD_DIR)

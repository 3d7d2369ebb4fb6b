# dpd reproducibility package. `make figures`, `make check`, `make test`,
# `make reproduce`, `make paper`, `make bench`. See README.md.
SHELL := /bin/bash
TIER ?= quick
CC ?= gcc
# The simulator's version, compiled into every run's provenance (git_commit): the last commit that
# changed its source (src/ or this Makefile), "-dirty" while these have uncommitted changes. Commits
# of experiments, results or documents leave the binary, its version and its sha256 unchanged.
SRC_COMMIT := $(shell git log -1 --format=%h -- src Makefile 2>/dev/null)
GIT_DESCRIBE := $(if $(SRC_COMMIT),$(SRC_COMMIT)$(shell git diff --quiet HEAD -- src Makefile 2>/dev/null || echo -dirty),unknown)
OPT ?= -O2
WARN := -std=c11 -Wall -Wextra -Werror
PKGS := gsl hdf5 libconfig
# (-g1: the line tables a sanitizer's backtrace names file and line from, without the full debug
# information that costs a quarter of the compile time; make SANITIZE=1 ASAN_G=-g for a debugger)
ASAN_G ?= -g1
ifeq ($(SANITIZE),1)
  OPT := -O1 $(ASAN_G) -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
  BUILD := build/asan
else
  BUILD := build/release
endif
CFLAGS_ALL := $(WARN) $(OPT) -fopenmp -D_DEFAULT_SOURCE
DEPS_STAMP := build/.deps-ok

# The simulator's folders, lowest layer first (README.md, "The simulator"): a
# file includes only from its own layer and those before it (tests/layers.sh).
LAYERS := core pair dynamics bodies measure simd analysis io app
SRC_DIRS := $(addprefix src/,$(LAYERS))
INCLUDES := $(addprefix -I,$(SRC_DIRS))
HDRS := $(wildcard $(addsuffix /*.h,$(SRC_DIRS)))
SRC := $(filter-out src/app/main.c,$(wildcard $(addsuffix /*.c,$(SRC_DIRS))))
OBJ := $(patsubst %.c,$(BUILD)/%.o,$(notdir $(SRC)))
vpath %.c $(SRC_DIRS)
BIN := bin/dpd
ANALYSE_CLIENT := build/analyse-client

.PHONY: all deps test test-slurm test-paper figures check reproduce paper paper-pdf bench bench-peer clean
all: $(BIN)

# Install any missing Debian package (idempotent, fast when all present).
deps:
	@tools/deps

$(DEPS_STAMP): tools/deps
	@tools/deps && mkdir -p build && touch $@

PKG_CFLAGS = $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
# HDF5 from its static archive when there is one (Debian's libhdf5-dev ships it): the shared
# libhdf5_serial needs libcurl and about 30 more libraries (its ROS3 driver, which dpd never
# uses), and every start of dpd loads them, about 20 ms of CPU each time on the CI machines
# against about 2000 starts per CI run (analysis subcommands, tests). The archive brings in only
# the objects dpd calls; their own needs are szip, zlib and dl. The same HDF5 version and code.
HDF5_A = $(wildcard $(addsuffix /libhdf5.a,$(patsubst -L%,%,$(shell pkg-config --libs-only-L hdf5 2>/dev/null))))
PKG_LIBS = $(if $(HDF5_A),$(shell pkg-config --libs gsl libconfig 2>/dev/null) $(HDF5_A) -lsz -lz -ldl,$(shell pkg-config --libs $(PKGS) 2>/dev/null))

$(BUILD)/%.o: %.c $(HDRS) | $(DEPS_STAMP)
	@mkdir -p $(BUILD)
	@echo "CC $<"
	@$(CC) $(CFLAGS_ALL) $(INCLUDES) $(PKG_CFLAGS) -DDPD_GIT='"$(GIT_DESCRIBE)"' -DDPD_CFLAGS='"$(CFLAGS_ALL) (forces.c, pair_*.c and pan_lanes_x86.c: $(PAIR_DRIVER_FLAGS))"' -c $< -o $@

# the pair driver and the pair styles without errno from sqrt (an argument never negative
# there), so that the lane-wise pair loops vectorise (pan_lanes.h, in pair_pan2008.c and the
# backend's pan_lanes_x86.c and pair_avx512.c); the same IEEE results
PAIR_DRIVER_FLAGS := -fno-math-errno
PAIR_DRIVER_OBJ := forces.o pair_dpd.o pair_pan2008.o pair_avx512.o pan_lanes_x86.o pair_styles.o
$(addprefix $(BUILD)/,$(PAIR_DRIVER_OBJ)) $(addprefix $(BUILD)/bare/,$(PAIR_DRIVER_OBJ)): CFLAGS_ALL += $(PAIR_DRIVER_FLAGS)

# the objects that print the version are rebuilt when it changes, not only when their source does
# (an edit compiled before its commit would otherwise keep the older commit's name). They are the
# sources that name DPD_GIT or DPD_CFLAGS, found, not listed: a list written by hand missed
# run_output.c when the provenance moved there, and runs recorded an older commit than --version
VERSION_FILE := $(BUILD)/version
$(shell mkdir -p $(BUILD) && { [ "$$(cat $(VERSION_FILE) 2>/dev/null)" = '$(GIT_DESCRIBE)' ] || echo '$(GIT_DESCRIBE)' > $(VERSION_FILE); })
VERSIONED_OBJ := $(patsubst %.c,%.o,$(notdir $(shell grep -l -e DPD_GIT -e DPD_CFLAGS $(SRC) src/app/main.c)))
$(addprefix $(BUILD)/,$(VERSIONED_OBJ)) $(addprefix $(BUILD)/bare/,$(VERSIONED_OBJ)): $(VERSION_FILE)

$(BUILD)/libdpd.a: $(OBJ)
	ar rcs $@ $^

$(BIN): $(BUILD)/main.o $(BUILD)/libdpd.a | $(ANALYSE_CLIENT)
	@mkdir -p bin
	$(CC) $(CFLAGS_ALL) -o $@ $^ $(PKG_LIBS) -lm

# the client of the analysis server (tools/analysis_server.py): "$ANALYSE" in an experiment's
# analysis once exp.sh has started the server. Static, so that each of its hundreds of starts
# maps no shared library; not sanitized (ASan does not link statically). Built with every
# bin/dpd (order-only: it does not relink the simulator).
$(ANALYSE_CLIENT): tools/lib/analyse-client.c | $(DEPS_STAMP)
	@mkdir -p build
	$(CC) $(WARN) -O2 -D_DEFAULT_SOURCE -static -o $@ $<

# The bare build (src/core/modules.h): the same sources with every optional module
# compiled out (-DDPD_BARE); it refuses scenes that switch one on. make bench
# runs it beside bin/dpd (what unused modules cost); tests/bare.sh checks that
# it gives bin/dpd's numbers bit for bit.
# (SANITIZE=1: a sanitized one under build/asan, for make test)
ifeq ($(SANITIZE),1)
  BARE := $(BUILD)/dpd-bare
else
  BARE := build/dpd-bare
endif
BARE_OBJ := $(patsubst %.c,$(BUILD)/bare/%.o,$(notdir $(SRC) src/app/main.c))
$(BUILD)/bare/%.o: %.c $(HDRS) | $(DEPS_STAMP)
	@mkdir -p $(BUILD)/bare
	@echo "CC $< (bare)"
	@$(CC) $(CFLAGS_ALL) $(INCLUDES) -DDPD_BARE $(PKG_CFLAGS) -DDPD_GIT='"$(GIT_DESCRIBE)"' -DDPD_CFLAGS='"$(CFLAGS_ALL) -DDPD_BARE (forces.c, pair_*.c and pan_lanes_x86.c: $(PAIR_DRIVER_FLAGS))"' -c $< -o $@

$(BARE): $(BARE_OBJ)
	$(CC) $(CFLAGS_ALL) -o $@ $^ $(PKG_LIBS) -lm

include tests/tests.mk
include tests/reliability.mk
include experiments/experiments.mk

# the rendered paper printed to PDF by WeasyPrint (installed on first use: tools/deps pdf)
paper-pdf: paper
	@tools/deps pdf
	@weasyprint -q build/paper.html build/paper.pdf && echo "paper-pdf: wrote build/paper.pdf"

# build/paper.html (make paper) in headless Chromium, at a phone's and a laptop's width, with
# screenshots into build/ (tests/browser.sh; Chromium installed on first use: tools/deps browser)
test-paper:
	@tools/deps browser
	@tests/browser.sh

# the Slurm engine against a real Slurm: a one-node cluster started here (tools/slurm-local)
test-slurm: $(BIN)
	@tools/deps slurm
	@tests/slurm.sh

bench: $(BIN) $(BARE)
	@bench/bench.sh

bench-peer: $(BIN) $(BARE)
	@PEER=1 bench/bench.sh

clean:
	rm -rf build bin

# tests.mk - `make test` (included by the top Makefile). Builds every
# tests/test_*.c against $(BUILD)/libdpd.a with cmocka, runs them and the
# script suites, prints one "N passed, M failed" line and fails if M > 0.
# `make test SANITIZE=1` does the same under ASan + UBSan (build/asan); the
# scene-error script then runs a sanitized dpd linked in $(BUILD)/tests/ so
# that bin/dpd is left alone.
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BINS := $(patsubst tests/%.c,$(BUILD)/tests/%,$(TEST_SRC))
CMOCKA_FLAGS = $(shell pkg-config --cflags --libs cmocka 2>/dev/null || echo -lcmocka)
ifeq ($(SANITIZE),1)
  TEST_DPD := $(BUILD)/tests/dpd
else
  TEST_DPD := $(BIN)
endif

$(BUILD)/tests/test_%: tests/test_%.c tests/testutil.h tests/runutil.h tests/pairutil.h $(BUILD)/libdpd.a $(HDRS)
	@mkdir -p $(BUILD)/tests
	@echo "CC $<"
	@$(CC) $(CFLAGS_ALL) $(PKG_CFLAGS) $(INCLUDES) -o $@ $< $(BUILD)/libdpd.a $(PKG_LIBS) $(CMOCKA_FLAGS) -lm $(TEST_LDFLAGS)

# test_output fails HDF5 calls on purpose: its H5Gcreate2 is a wrapper that calls the real one
$(BUILD)/tests/test_output: TEST_LDFLAGS = -Wl,--wrap=H5Gcreate2

$(BUILD)/tests/dpd: $(BUILD)/main.o $(BUILD)/libdpd.a
	@mkdir -p $(BUILD)/tests
	$(CC) $(CFLAGS_ALL) -o $@ $^ $(PKG_LIBS) -lm

# The suites, the longest first (measured: make test prints each one's time), so that under
# make -j2 the two cores finish together; each writes its log to $(SUITE_LOGS) (tests/run-tests.sh
# --one) and the last step prints the logs in this order and adds up their checks (--sum).
TEST_SCRIPTS := tests/checkpoint.sh tests/io_errors.sh tests/scene_errors.sh tests/blowup.sh \
  tests/h5md.sh tests/layers.sh tests/tcaf_fit.sh tests/precision.sh tests/bare.sh tests/skips.sh \
  tests/analysis.py tests/bands_diff.sh tests/fit_line.sh tests/claim_groups.sh tests/library_exits.sh \
  tests/in_flight.sh tests/version.sh tests/analyse_server.sh tests/stage2_plan.sh
SLOW_BINS := test_transverse_relaxation test_thermostat test_bonds test_msd test_rotation test_forces
SUITES := $(SLOW_BINS) $(notdir $(TEST_SCRIPTS)) $(filter-out $(SLOW_BINS),$(notdir $(TEST_BINS)))
# the suites that run no code a sanitizer instruments: source checks (layers, library_exits), the
# python and shell tools, the analysis server and its static client (never sanitized), and
# version.sh, which builds a release binary of its own. make test runs them; make test SANITIZE=1
# (the same suites again under ASan and UBSan) leaves them out and says so.
UNSANITIZED_SUITES := layers.sh library_exits.sh version.sh precision.sh analyse_server.sh analysis.py \
  bands_diff.sh claim_groups.sh stage2_plan.sh
ifeq ($(SANITIZE),1)
  SUITES := $(filter-out $(UNSANITIZED_SUITES),$(SUITES))
endif
SUITE_LOGS := $(BUILD)/tests/logs
suite_path = $(if $(filter test_%,$(1)),$(BUILD)/tests/$(1),tests/$(1))

.PHONY: test $(addprefix suite/,$(SUITES))
$(addprefix suite/,$(SUITES)): suite/%: $(TEST_BINS) $(TEST_DPD) $(BARE) $(ANALYSE_CLIENT)
	@DPD=$(TEST_DPD) BARE=$(BARE) SANITIZE=$(SANITIZE) tests/run-tests.sh --one $(call suite_path,$*) $(SUITE_LOGS)/$*.log
	@echo "test: $* done"
test: $(addprefix suite/,$(SUITES))
	@tests/run-tests.sh --sum $(patsubst %,$(SUITE_LOGS)/%.log,$(SUITES))
	@$(if $(filter 1,$(SANITIZE)),echo "test: not run again under the sanitizers (no instrumented code; make test runs them): $(UNSANITIZED_SUITES)")

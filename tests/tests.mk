# tests.mk - `make test` (included by the top Makefile). Builds every
# tests/test_*.c against $(BUILD)/libdpd.a with cmocka, runs them and the
# scene-error script, prints one "N passed, M failed" line and fails if M > 0.
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

.PHONY: test
test: $(TEST_BINS) $(TEST_DPD) $(BARE)
	@DPD=$(TEST_DPD) BARE=$(BARE) SANITIZE=$(SANITIZE) tests/run-tests.sh $(TEST_BINS)

# reliability.mk - `make fuzz` and `make valgrind` (included by the top Makefile).
# make fuzz: libFuzzer (clang) on
# the scene parser and validator, tests/fuzz/fuzz_scene.c, under ASan+UBSan
# (linked with every source but main.c: the set-up reaches into most modules).
# Seeds: tests/fuzz/corpus (kept in the repository), every scene of
# tests/ and experiments/; new inputs go to build/fuzz/corpus and are merged
# (minimised) back into tests/fuzz/corpus at the end. FUZZ_SECONDS (default
# 900) of wall time on one core at nice 19; the log is build/fuzz/fuzz.log.
# Needs clang and llvm-symbolizer: `tools/deps fuzz`. First a control: libconfig's known leak
# (tests/fuzz/lsan-control.cfg) must be reported without tests/lsan.supp and suppressed with it;
# LeakSanitizer names the library's frames only through llvm-symbolizer (Debian's llvm, llvm-14),
# without which the suppression cannot match and every such input would count as a bug.
FUZZ_SECONDS ?= 900
FUZZ_DIR := build/fuzz
FUZZ_SRC = $(SRC)
FUZZ_FLAGS := -std=c11 -Wall -Wextra -Werror -D_DEFAULT_SOURCE -DDPD_GIT='"fuzz"' -DDPD_CFLAGS='"fuzz"' -g -O1 -fno-omit-frame-pointer \
              -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all

$(FUZZ_DIR)/fuzz_scene: tests/fuzz/fuzz_scene.c $(FUZZ_SRC) $(HDRS)
	@tools/deps fuzz
	@mkdir -p $(FUZZ_DIR)
	clang $(FUZZ_FLAGS) $(PKG_CFLAGS) $(INCLUDES) -o $@ tests/fuzz/fuzz_scene.c $(FUZZ_SRC) $(PKG_LIBS) -lm

.PHONY: fuzz
fuzz: $(FUZZ_DIR)/fuzz_scene
	@mkdir -p $(FUZZ_DIR)/corpus $(FUZZ_DIR)/artifacts $(FUZZ_DIR)/seeds
	@if LSAN_OPTIONS=print_suppressions=0 $(FUZZ_DIR)/fuzz_scene tests/fuzz/lsan-control.cfg >$(FUZZ_DIR)/lsan-control.log 2>&1; then \
	    echo "fuzz: tests/fuzz/lsan-control.cfg no longer leaks in libconfig: review tests/lsan.supp" >&2; exit 1; fi
	@LSAN_OPTIONS=suppressions=tests/lsan.supp:print_suppressions=0 $(FUZZ_DIR)/fuzz_scene tests/fuzz/lsan-control.cfg \
	    >$(FUZZ_DIR)/lsan-control.log 2>&1 || { echo "fuzz: libconfig's known leak (tests/fuzz/lsan-control.cfg) is not" \
	    "suppressed: LeakSanitizer did not name its frames (no llvm-symbolizer? tools/deps fuzz installs it, Debian's llvm)," \
	    "so tests/lsan.supp cannot match; see $(FUZZ_DIR)/lsan-control.log" >&2; exit 1; }
	@echo "fuzz: control: libconfig's known leak found, and suppressed by tests/lsan.supp"
	@cp tests/good-scene.cfg tests/bad-scenes/*.cfg $(FUZZ_DIR)/seeds/
	@for f in experiments/*/*/*.cfg; do cp "$$f" "$(FUZZ_DIR)/seeds/$$(echo $$f | tr / _)"; done
	LSAN_OPTIONS=suppressions=tests/lsan.supp:print_suppressions=0 nice -n 19 $(FUZZ_DIR)/fuzz_scene -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=2048 \
	    -max_len=8192 -dict=tests/fuzz/scene.dict -artifact_prefix=$(FUZZ_DIR)/artifacts/ \
	    -print_final_stats=1 $(FUZZ_DIR)/corpus tests/fuzz/corpus $(FUZZ_DIR)/seeds </dev/null 2>&1 | tee $(FUZZ_DIR)/fuzz.log | grep -v '^#[0-9]*.*\(NEW\|REDUCE\|pulse\)' ; \
	    test $${PIPESTATUS[0]} -eq 0
	LSAN_OPTIONS=suppressions=tests/lsan.supp:print_suppressions=0 nice -n 19 $(FUZZ_DIR)/fuzz_scene -merge=1 -artifact_prefix=$(FUZZ_DIR)/artifacts/ -dict=tests/fuzz/scene.dict tests/fuzz/corpus $(FUZZ_DIR)/corpus 2>&1 | tail -2
	@grep -aE '^(stat::number_of_executed_units|Done|fuzz_scene: )' $(FUZZ_DIR)/fuzz.log; \
	    if ls $(FUZZ_DIR)/artifacts/* >/dev/null 2>&1; then echo "fuzz: crashes in $(FUZZ_DIR)/artifacts"; exit 1; fi; \
	    echo "fuzz: no crash, no sanitizer report"

# make valgrind: memcheck (no error, no definite leak) on small scenes, a
# checkpointing run and a resume; see tests/valgrind.sh.
.PHONY: valgrind
valgrind: $(BIN)
	@tests/valgrind.sh

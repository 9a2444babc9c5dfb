# The scene fuzzer (not part of any assignment): libFuzzer through Debian's clang, with ASan + UBSan.
#   make fuzz [FUZZ_SECONDS=60]   fuzz from the seed corpus (fuzz/corpus) with the dictionary; a crash
#                                 is saved under build/fuzz/crashes/: fix it, then move it to fuzz/crashes/
#   make fuzz-regress             run every saved crash and the seed corpus once (CI runs both)
FUZZ_CC      ?= clang
FUZZ_SECONDS ?= 60
FUZZ_BUILD   := build/fuzz
FUZZ_FLAGS   := -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -O1 -g
FUZZ_SRC     := $(FRAMEWORK_SRC) $(PARTS_SRC) $(THIRD_SRC) fuzz/fuzz_scene.c
FUZZ_OBJ     := $(patsubst %.c,$(FUZZ_BUILD)/%.o,$(FUZZ_SRC))

.PHONY: fuzz fuzz-regress

$(FUZZ_BUILD)/%.o: %.c $(BUILD)/gen/version.h
	$(say) FUZZCC $<
	@mkdir -p $(dir $@)
	$(Q)$(FUZZ_CC) $(filter-out -MMD -MP,$(CPPFLAGS)) -std=c11 $(FUZZ_FLAGS) -pthread -c -o $@ $<

bin/fuzz/fuzz_scene: $(FUZZ_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(FUZZ_CC) -fsanitize=fuzzer,address,undefined -o $@ $^ $(LDLIBS)

fuzz: bin/fuzz/fuzz_scene  ## fuzz the scene loader (FUZZ_SECONDS=60); crashes under build/fuzz/crashes/
	@mkdir -p $(FUZZ_BUILD)/corpus $(FUZZ_BUILD)/crashes
	bin/fuzz/fuzz_scene $(FUZZ_BUILD)/corpus fuzz/corpus -dict=fuzz/dae.dict -max_len=65536 -timeout=10 \
	    -rss_limit_mb=2048 -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	    -artifact_prefix=$(FUZZ_BUILD)/crashes/

fuzz-regress: bin/fuzz/fuzz_scene  ## replay every saved crash and the seed corpus once
	bin/fuzz/fuzz_scene -rss_limit_mb=2048 $(wildcard fuzz/crashes/*) fuzz/corpus/*

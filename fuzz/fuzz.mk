# The fuzzers (not part of any assignment): libFuzzer through Debian's clang, with ASan + UBSan, one
# per reader of files pathlab did not write itself:
#   scene  the scene loader (fuzz_scene.c; seeds fuzz/corpus, dictionary fuzz/dae.dict)
#   film   the film reader, --merge and the environment map reader (fuzz_film.c; seeds:
#          tests/data/make_hostile_films.py's films, a real render's two ranges, a small sky map)
#   json   the grader's cases and reference JSON readers (fuzz_json.c; seeds grading/ and
#          reference_images/ JSON)
#   suite  the grader's test-results reader (fuzz_suite.c; seeds: part 1's suite's own XML)
#   make fuzz [FUZZ_SECONDS=120] [FUZZ_TARGET=film]   FUZZ_SECONDS shared by the targets (or all to the
#                                one named); a crash is saved under build/fuzz/crashes/<target>/: fix
#                                it, then move it to fuzz/crashes/<target>/
#   make fuzz-regress            run every saved crash and every seed once (CI runs both)
# Every run caps a single allocation at 1 GB (-malloc_limit_mb) and the process at 2 GB of RSS
# (-rss_limit_mb; ASan's own memory counts there).
FUZZ_CC      ?= clang
FUZZ_SECONDS ?= 60
FUZZ_TARGETS := scene film json suite
FUZZ_TARGET  ?= $(FUZZ_TARGETS)
FUZZ_BUILD   := build/fuzz
FUZZ_FLAGS   := -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -O1 -g
FUZZ_LIB_SRC := $(FRAMEWORK_SRC) $(PARTS_SRC) $(THIRD_SRC) $(GRADER_SRC)  # grader.mk: the library, no main
FUZZ_LIB_OBJ := $(patsubst %.c,$(FUZZ_BUILD)/%.o,$(FUZZ_LIB_SRC))
FUZZ_LIMITS  := -malloc_limit_mb=1024 -rss_limit_mb=2048 -timeout=10
# Per target: its options and its seed folders (built by fuzz-seeds).
FUZZ_OPTS_scene := -dict=fuzz/dae.dict -max_len=65536
FUZZ_OPTS_film  := -max_len=65536
FUZZ_OPTS_json  := -max_len=16384
FUZZ_OPTS_suite := -max_len=16384
FUZZ_SEEDS_scene := fuzz/corpus
FUZZ_SEEDS_film  := $(FUZZ_BUILD)/seeds/film
FUZZ_SEEDS_json  := $(FUZZ_BUILD)/seeds/json
FUZZ_SEEDS_suite := $(FUZZ_BUILD)/seeds/suite

.PHONY: fuzz fuzz-regress fuzz-seeds
# The objects of the pattern rules below are kept (make would delete them as intermediates).
.SECONDARY: $(FUZZ_LIB_OBJ) $(patsubst %,$(FUZZ_BUILD)/fuzz/fuzz_%.o,$(FUZZ_TARGETS))

$(FUZZ_BUILD)/%.o: %.c $(BUILD)/gen/version.h
	$(say) FUZZCC $<
	@mkdir -p $(dir $@)
	$(Q)$(FUZZ_CC) $(filter-out -MMD -MP,$(CPPFLAGS)) -std=c11 $(FUZZ_FLAGS) -pthread -c -o $@ $<

bin/fuzz/fuzz_%: $(FUZZ_BUILD)/fuzz/fuzz_%.o $(FUZZ_LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(FUZZ_CC) -fsanitize=fuzzer,address,undefined -o $@ $^ $(LDLIBS) $(GRADER_LIBS)

# The seeds are the project's own files, made fresh: what pathlab writes and reads.
fuzz-seeds: $(BIN)/pathtracer $(BIN)/imgtool $(BIN)/test-part1
	@rm -rf $(FUZZ_BUILD)/seeds && mkdir -p $(FUZZ_SEEDS_film) $(FUZZ_SEEDS_json) $(FUZZ_SEEDS_suite)
	$(Q)python3 tests/data/make_hostile_films.py $(FUZZ_SEEDS_film) >/dev/null && rm $(FUZZ_SEEDS_film)/manifest.txt
	$(Q)for r in 0:1 1:2; do $(BIN)/pathtracer -q -r 8 6 -s 2 --samples $$r -f $(FUZZ_SEEDS_film)/render$${r%:*}.exr \
	      scenes/cornell_spheres.dae || exit 1; rm $(FUZZ_SEEDS_film)/render$${r%:*}.json; done
	$(Q)cat $(FUZZ_SEEDS_film)/render0.exr $(FUZZ_SEEDS_film)/render1.exr > $(FUZZ_SEEDS_film)/render_pair.exr
	$(Q)$(BIN)/imgtool sky $(FUZZ_SEEDS_film)/sky.exr 16 8
	$(Q)n=0; for f in grading/cases.json $(wildcard grading/hidden/cases.json) reference_images/*/*.json; do \
	      n=$$((n + 1)); cp $$f $(FUZZ_SEEDS_json)/$$n.json; done
	$(Q)CMOCKA_MESSAGE_OUTPUT=xml CMOCKA_XML_FILE='$(FUZZ_SEEDS_suite)/%g.xml' $(BIN)/test-part1 >/dev/null 2>&1 || true

fuzz: fuzz-seeds $(addprefix bin/fuzz/fuzz_,$(FUZZ_TARGET))  ## fuzz every reader (FUZZ_SECONDS=60 in all, FUZZ_TARGET=film: one); crashes under build/fuzz/crashes/
	$(Q)set -e; count=$(words $(FUZZ_TARGET)); for t in $(FUZZ_TARGET); do \
	  mkdir -p $(FUZZ_BUILD)/corpus/$$t $(FUZZ_BUILD)/crashes/$$t; \
	  case $$t in scene) seeds='$(FUZZ_SEEDS_scene)'; opts='$(FUZZ_OPTS_scene)';; film) seeds='$(FUZZ_SEEDS_film)'; \
	    opts='$(FUZZ_OPTS_film)';; json) seeds='$(FUZZ_SEEDS_json)'; opts='$(FUZZ_OPTS_json)';; \
	    suite) seeds='$(FUZZ_SEEDS_suite)'; opts='$(FUZZ_OPTS_suite)';; esac; \
	  echo "== fuzz $$t: $$(($(FUZZ_SECONDS) / count)) s"; \
	  bin/fuzz/fuzz_$$t $(FUZZ_BUILD)/corpus/$$t $$seeds $$opts $(FUZZ_LIMITS) -max_total_time=$$(($(FUZZ_SECONDS) / count)) \
	      -print_final_stats=1 -artifact_prefix=$(FUZZ_BUILD)/crashes/$$t/; done

fuzz-regress: fuzz-seeds $(addprefix bin/fuzz/fuzz_,$(FUZZ_TARGETS))  ## replay every saved crash and every seed once
	$(Q)set -e; for t in $(FUZZ_TARGETS); do \
	  case $$t in scene) seeds='$(FUZZ_SEEDS_scene)';; film) seeds='$(FUZZ_SEEDS_film)';; json) seeds='$(FUZZ_SEEDS_json)';; \
	    suite) seeds='$(FUZZ_SEEDS_suite)';; esac; \
	  echo "== fuzz-regress $$t"; \
	  bin/fuzz/fuzz_$$t $(FUZZ_LIMITS) $$(ls -d fuzz/crashes/$$t/* 2>/dev/null) $$seeds/*; done

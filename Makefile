# pathlab: build, test, bench. `make help` says which target you want first.
#
# Layout of this file: settings, flags, sources, the core rules (the renderer and the test suites),
# then one fragment per folder that has targets of its own, included by name below. Each target's
# recipe lives in the fragment of the folder it concerns; `make help` lists every target from the
# `## ` comment beside it.

# ---- settings ---------------------------------------------------------------------------------
CC      ?= cc
OPT     ?= -O2
SAN     ?= 0   # 1: AddressSanitizer + UndefinedBehaviorSanitizer build, in build/san and bin/san
WERROR  ?= 0   # 1: warnings are errors (CI sets it)
V       ?= 0   # 1: print whole commands instead of "CC file.c"
LTO     ?= 1   # 0: no link-time optimisation (the grader's builds: objects hold machine code it can inspect)
PKGS    := libxml-2.0 stb jansson zlib OpenEXR
TPKGS   := cmocka
# The test suites: tests/<suite>/ each, plus the course's own (course/) where the tree has it.
SUITES  := framework grader part1 part2 part3 part4 part5 $(if $(wildcard course/course.mk),course)

# ---- flags ------------------------------------------------------------------------------------
WARN     := -Wall -Wextra -Wpedantic -Wshadow -Wno-unused-parameter
CPPFLAGS += -D_GNU_SOURCE -MMD -MP $(shell pkg-config --cflags $(PKGS))
CFLAGS   += -std=c11 $(OPT) -g $(WARN) -pthread
LDLIBS   += $(shell pkg-config --libs $(PKGS)) -lm -pthread
ifeq ($(WERROR),1)
  CFLAGS  += -Werror
  LDFLAGS += -Werror  # with LTO, some warnings appear only at link time
endif
ifeq ($(SAN),1)
  OPT      := -O1
  CFLAGS   += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
  LDFLAGS  += -fsanitize=address,undefined
  BUILD    := build/san
  BIN      := bin/san
else
  # Link-time optimisation lets the BVH inline part 1's triangle test across files: ~9% faster renders.
  ifneq ($(strip $(LTO)),0)
    CFLAGS   += -flto=auto
    LDFLAGS  += -flto=auto $(OPT) $(WARN)
  endif
  BUILD    := build/release
  BIN      := bin
endif
ifeq ($(V),1)
  Q :=
  say = @true
else
  Q := @
  say = @printf '  %-6s %s\n'
endif

# ---- sources: every .c under these folders is built; no list to keep in sync -------------------
FRAMEWORK_SRC := $(filter-out framework/main.c,$(wildcard framework/*.c))
PARTS_SRC     := $(wildcard parts/*/*.c)
COMMON_SRC    := $(wildcard tests/common/*.c)
THIRD_SRC     := third_party/lodepng/lodepng.c
LIB_OBJ       := $(patsubst %.c,$(BUILD)/%.o,$(FRAMEWORK_SRC) $(PARTS_SRC) $(THIRD_SRC))
COMMON_OBJ    := $(patsubst %.c,$(BUILD)/%.o,$(COMMON_SRC))
# A suite's sources: tests/<suite>/*.c; the course suite's are the test_*.c files under course/.
suite_src      = $(if $(filter course,$(1)),$(wildcard course/*/test_*.c),$(wildcard tests/$(1)/*.c))
suite_obj      = $(patsubst %.c,$(BUILD)/%.o,$(call suite_src,$(1)))

.PHONY: all help test $(addprefix test-,$(SUITES)) clean FORCE
.DEFAULT_GOAL := all

# ---- the renderer -----------------------------------------------------------------------------
all: $(BIN)/pathtracer  ## build bin/pathtracer (start here)

$(BIN)/pathtracer: $(BUILD)/framework/main.o $(LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/%.o: %.c
	$(say) CC $<
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

# The code version for the JSON sidecar and the EXR provenance (a student release has no git: its
# VERSION file); the header changes only when the version does.
VERSION := $(shell git describe --always --dirty 2>/dev/null || cat VERSION 2>/dev/null || echo unknown)
CPPFLAGS += -I$(BUILD)/gen
$(BUILD)/gen/version.h: FORCE
	@mkdir -p $(dir $@)
	@echo '#define PL_VERSION "$(VERSION)"' > $@.tmp
	@cmp -s $@.tmp $@ || mv $@.tmp $@; rm -f $@.tmp
$(BUILD)/framework/sidecar.o $(BUILD)/framework/range.o: $(BUILD)/gen/version.h

# ---- tests: one binary per suite, so a crash in one part costs no other -----------------------
$(BUILD)/tests/%.o $(BUILD)/course/%.o: CPPFLAGS += $(shell pkg-config --cflags $(TPKGS))

## test-<suite>: run one suite: test-part1 .. test-part5, test-framework, test-grader, test-course
## test-part3 FILTER='*hemisphere*': run only the tests whose names match (LIST=1: list them)
define suite_rules
$(BIN)/test-$(1): $(call suite_obj,$(1)) $(COMMON_OBJ) $(LIB_OBJ)
	$$(say) LD $$@
	@mkdir -p $$(dir $$@)
	$$(Q)$$(CC) $$(LDFLAGS) -o $$@ $$^ $$(LDLIBS) $$(shell pkg-config --libs $(TPKGS))

test-$(1): $(BIN)/test-$(1) $(BIN)/pathtracer
	@echo "== test-$(1)"
	$$(Q)PL_TEST_FILTER='$$(FILTER)' PL_TEST_LIST='$$(LIST)' $(BIN)/test-$(1)
endef
$(foreach s,$(SUITES),$(eval $(call suite_rules,$(s))))

# Every suite runs even when one fails; the target fails if any did. A FILTER need match in one
# suite only: a suite with a match creates $(BUILD)/filter-matched, and the target fails without one.
test:  ## run every suite (SAN=1: under AddressSanitizer + UBSan)
	@fail=0; matched=$(BUILD)/filter-matched; mkdir -p $(BUILD); rm -f $$matched; \
	 for s in $(SUITES); do PL_TEST_MATCHED=$$matched $(MAKE) --no-print-directory test-$$s || fail=1; done; \
	 if [ -n '$(FILTER)' ] && [ ! -f $$matched ]; then \
	   echo "ERROR: no test of any suite matches FILTER='$(FILTER)' (the tests are listed by \`make test LIST=1\`)"; exit 1; fi; \
	 if [ $$fail = 0 ]; then echo "all suites passed"; else echo "some suites FAILED"; exit 1; fi

clean:  ## remove build/, bin/ and release/
	rm -rf build bin release

# `make help`: every `target: ... ## text` line and every `## target: text` line of the makefiles
# read, in the order read, so a new target documents itself where it is defined.
help:  ## this list
	@echo "pathlab targets (settings: V=1 full commands, WERROR=1, SAN=1, OPT=-O0):"
	@awk -F'## ' '/^[$$()A-Za-z0-9_.%<>\/-]+:[^=]*## / { split($$1, t, ":"); sub(/^\$$\(BIN\)/, "$(BIN)", t[1]); \
	                                                     printf "  make %-22s %s\n", t[1], $$2; next } \
	              /^## [^:]+: / { s = $$2; i = index(s, ": "); printf "  make %-22s %s\n", substr(s, 1, i - 1), substr(s, i + 2) }' \
	     $(MAKEFILE_LIST)

# ---- the folders' own targets -----------------------------------------------------------------
# One fragment per folder that has targets. A tree may lack a folder, and then its targets: the
# student release has no course/ (the course's own tools), a part's grading tree holds only what the part's
# build and tests need.
-include grader/grader.mk
-include tools/tools.mk
-include handout/handout.mk
-include bench/bench.mk
-include fuzz/fuzz.mk
-include course/course.mk
-include $(shell find build -name '*.d' 2>/dev/null)

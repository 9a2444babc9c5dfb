# pathlab: build, test, bench. `make help` says which target you want first.

# ---- settings ---------------------------------------------------------------------------------
CC      ?= cc
OPT     ?= -O2
SAN     ?= 0   # 1: AddressSanitizer + UndefinedBehaviorSanitizer build, in build/san and bin/san
WERROR  ?= 0   # 1: warnings are errors (CI sets it)
V       ?= 0   # 1: print whole commands instead of "CC file.c"
LTO     ?= 1   # 0: no link-time optimisation (the grader's builds: objects hold machine code it can inspect)
PKGS    := libxml-2.0 stb jansson zlib OpenEXR
TPKGS   := cmocka
SUITES  := framework grader part1 part2 part3 part4 part5

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
suite_obj      = $(patsubst %.c,$(BUILD)/%.o,$(wildcard tests/$(1)/*.c))

.PHONY: all help test $(addprefix test-,$(SUITES)) clean bench
.DEFAULT_GOAL := all

all: $(BIN)/pathtracer

# The code version for the JSON sidecar (a student release has no git: its VERSION file); the
# header changes only when the version does.
VERSION := $(shell git describe --always --dirty 2>/dev/null || cat VERSION 2>/dev/null || echo unknown)
CPPFLAGS += -I$(BUILD)/gen
$(BUILD)/gen/version.h: FORCE
	@mkdir -p $(dir $@)
	@echo '#define PL_VERSION "$(VERSION)"' > $@.tmp
	@cmp -s $@.tmp $@ || mv $@.tmp $@; rm -f $@.tmp
$(BUILD)/framework/sidecar.o: $(BUILD)/gen/version.h
.PHONY: FORCE

# Double-colon: other makefiles included below may add lines of their own.
help::
	@echo "pathlab targets:"
	@echo "  make                  build bin/pathtracer (start here)"
	@echo "  make test-part1       run part 1's tests (likewise test-part2 .. test-part5)"
	@echo "  make test-part3 FILTER='*hemisphere*'  run only the tests whose names match"
	@echo "  make test-part3 LIST=1                  list the suite's tests (with FILTER: those that match)"
	@echo "  make test-framework   run the framework's tests"
	@echo "  make test             run every suite"
	@echo "  make test SAN=1       the same under AddressSanitizer + UBSan"
	@echo "  make bench            speed figures, not a test (bench-bvh, bench-transport; see bench/RESULTS.md)"
	@echo "  make figures          every figure the handout asks for (parts 1-5), into out/figures/"
	@echo "  make grade            grade your parts on the public cases (PARTS=3: one part); report in out/grade/"
	@echo "  make fuzz             fuzz the scene loader (FUZZ_SECONDS=60)"
	@echo "  make clean            remove build/, bin/ and release/"
	@echo "settings: V=1 (full commands), WERROR=1, SAN=1, OPT=-O0"

$(BIN)/pathtracer: $(BUILD)/framework/main.o $(LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/%.o: %.c
	$(say) CC $<
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

# Tests: tests/<suite>/*.c link into one binary per suite, so a crash in one part costs no other.
$(BUILD)/tests/%.o: CPPFLAGS += $(shell pkg-config --cflags $(TPKGS))

define suite_rules
$(BIN)/test-$(1): $(call suite_obj,$(1)) $(COMMON_OBJ) $(LIB_OBJ)
	$$(say) LD $$@
	@mkdir -p $$(dir $$@)
	$$(Q)$$(CC) $$(LDFLAGS) -o $$@ $$^ $$(LDLIBS) $$(shell pkg-config --libs $(TPKGS))

test-$(1): $(if $(call suite_obj,$(1)),$(BIN)/test-$(1) $(BIN)/pathtracer)
ifeq ($(strip $(call suite_obj,$(1))),)
	@echo "test-$(1): no tests yet"
else
	@echo "== test-$(1)"
	$$(Q)PL_TEST_FILTER='$$(FILTER)' PL_TEST_LIST='$$(LIST)' $(BIN)/test-$(1)
endif
endef
$(foreach s,$(SUITES),$(eval $(call suite_rules,$(s))))

# Every suite runs even when one fails; the target fails if any did. A FILTER need match in one
# suite only: a suite with a match creates $(BUILD)/filter-matched, and the target fails without one.
test:
	@fail=0; matched=$(BUILD)/filter-matched; mkdir -p $(BUILD); rm -f $$matched; \
	 for s in $(SUITES); do PL_TEST_MATCHED=$$matched $(MAKE) --no-print-directory test-$$s || fail=1; done; \
	 if [ -n '$(FILTER)' ] && [ ! -f $$matched ]; then \
	   echo "ERROR: no test of any suite matches FILTER='$(FILTER)' (the tests are listed by \`make test LIST=1\`)"; exit 1; fi; \
	 if [ $$fail = 0 ]; then echo "all suites passed"; else echo "some suites FAILED"; exit 1; fi

clean:
	rm -rf build bin release

include $(wildcard tools/*.mk bench/*.mk tests/*/*.mk fuzz/*.mk)
-include $(shell find build -name '*.d' 2>/dev/null)

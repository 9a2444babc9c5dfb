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
STB     ?= auto  # auto: the system's stb where pkg-config finds it, else third_party/stb; vendored: always third_party/stb
PKGS    := libxml-2.0 stb jansson zlib OpenEXR
TPKGS   := cmocka
# The grader's suite also renders results.json's Markdown as a course platform does (CommonMark's
# reference library), to prove that no markup a submission plants survives.
GRADER_TPKGS := libcmark
# The course's parts: one folder each, parts/partN_<name>/ (a course's release holds the parts it
# chose in course/course.mk, COURSE_PARTS). PART_SUITES: part1 part2 ..., in order.
PART_SUITES := $(sort $(foreach d,$(wildcard parts/part*_*),$(firstword $(subst _, ,$(notdir $(d))))))
# The test suites: tests/<suite>/ each, plus the course's own tools' suite where the tree has course/.
SUITES  := framework grader $(PART_SUITES) $(if $(wildcard course/course.mk),course)

# ---- libraries: pkg-config first, checked before anything compiles ----------------------------
# stb: Homebrew has no formula, so where pkg-config finds no stb the vendored headers are used.
STB := $(strip $(STB))
ifeq ($(STB),auto)
  STB := $(if $(shell pkg-config --exists stb 2>/dev/null && echo yes),system,vendored)
endif
ifeq ($(STB),vendored)
  PKGS     := $(filter-out stb,$(PKGS))
  CPPFLAGS += -Ithird_party/stb
  STB_SRC  := third_party/stb/stb_image.c  # stb_image's implementation (a system stb ships it as libstb)
else ifneq ($(STB),system)
  $(error STB=$(STB): expected auto, system or vendored)
endif
# Every library must be there, and OpenEXR new enough for its C API (openexr.h, OpenEXR 3.1), or the
# build stops with one message saying what to do; `make help` and `make clean` need none of them.
EXR_WAY_OUT := $(if $(filter Darwin,$(shell uname -s)),Run `brew upgrade openexr`.,Ubuntu 22.04 has 2.5: \
  use Ubuntu 24.04 or later, or Debian 12 or later, or the devcontainer in .devcontainer/ (README.md, \
  "Platforms"), or build OpenEXR 3 from source and add its lib/pkgconfig to PKG_CONFIG_PATH.)
ifneq ($(filter-out help clean,$(or $(MAKECMDGOALS),all)),)
  MISSING := $(strip $(foreach p,$(PKGS) $(TPKGS) $(GRADER_TPKGS),$(if $(shell pkg-config --exists $(p) 2>/dev/null && echo y),,$(p))))
  ifneq ($(MISSING),)
    $(error pkg-config finds no $(MISSING): run `sh tools/setup` (README.md, "Platforms"))
  endif
  ifeq ($(shell pkg-config --atleast-version=3.1 OpenEXR && echo y),)
    $(error OpenEXR $(shell pkg-config --modversion OpenEXR) is too old: pathlab needs 3.1 or later (its C API, \
      openexr.h). $(EXR_WAY_OUT))
  endif
endif

# ---- flags ------------------------------------------------------------------------------------
# Feature macros: every file is C11 + POSIX.1-2008, so what builds here builds on macOS (make
# test-portable checks it with gcc and clang). A file that needs more names itself below, with why.
FEATURES := -D_POSIX_C_SOURCE=200809L
# realpath() is POSIX.1-2008, but glibc declares it only with X/Open's interfaces on.
XOPEN_SRC := framework/output.c grader/grade_plan.c
# The autograder's Linux-only sandbox code (namespaces, setgroups, pipe2): glibc's extensions.
LINUX_SRC := grader/grade_run.c grader/grade_sandbox.c grader/sandbox_linux.c grader/probe_main.c
# Their objects in any build folder (build/release, build/san, build/fuzz) take these instead.
$(addprefix %/,$(XOPEN_SRC:.c=.o)): FEATURES += -D_XOPEN_SOURCE=700
$(addprefix %/,$(LINUX_SRC:.c=.o)): FEATURES := -D_GNU_SOURCE
# Apple's headers hide some names (PATH_MAX, RTLD_NEXT, sysconf's _SC_PHYS_PAGES) under a strict
# _POSIX_C_SOURCE that glibc shows; _DARWIN_C_SOURCE shows them again.
ifeq ($(shell uname -s),Darwin)
  FEATURES += -D_DARWIN_C_SOURCE
endif
# A warning turned off only where this compiler knows it. The test asks for the warning itself: gcc
# accepts any -Wno-<name> in silence, then notes "unrecognized command-line option" under every
# warning it prints, so asking for the -Wno- form would always say yes.
cc_warning_off = $(shell $(CC) -Werror -W$(1) -E -x c /dev/null >/dev/null 2>&1 && echo -Wno-$(1))
# -Wno-newline-eof: clang's -Wpedantic wants a final newline, which the vendored lodepng lacks.
WARN     := -Wall -Wextra -Wpedantic -Wshadow -Wno-unused-parameter $(call cc_warning_off,newline-eof)
CPPFLAGS += $(FEATURES) -MMD -MP $(shell pkg-config --cflags $(PKGS))
# The framework calls a part of the second assignment only where the course has it (material.c,
# scene.c, render.c, light.c, main.c, cli.c).
CPPFLAGS += $(foreach n,6 7 8 9,$(if $(filter part$(n),$(PART_SUITES)),-DPL_HAS_PART$(n)))
CFLAGS   += -std=c11 $(OPT) -g $(WARN) -pthread
LDLIBS   += $(shell pkg-config --libs $(PKGS)) -lm -pthread
ifeq ($(WERROR),1)
  CFLAGS  += -Werror
  LDFLAGS += -Werror  # with LTO, some warnings appear only at link time
endif
# One build folder per compiler: gcc's and clang's objects never meet in one link (clang cannot read
# gcc's LTO objects, nor gcc clang's). The default compiler (cc) keeps build/release.
CC_NAME   := $(notdir $(firstword $(CC)))
BUILD_TAG := $(if $(filter cc,$(CC_NAME)),,-$(CC_NAME))
ifeq ($(SAN),1)
  OPT      := -O1
  CFLAGS   += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
  LDFLAGS  += -fsanitize=address,undefined
  BUILD    := build/san$(BUILD_TAG)
  BIN      := bin/san
else
  # Link-time optimisation lets the BVH inline part 1's triangle test across files: ~9% faster renders.
  ifneq ($(strip $(LTO)),0)
    CFLAGS   += -flto=auto
    LDFLAGS  += -flto=auto $(OPT) $(WARN)
  endif
  BUILD    := build/release$(BUILD_TAG)
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
THIRD_SRC     := third_party/lodepng/lodepng.c $(STB_SRC)
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

# ---- builds follow content and flags, not only dates ---------------------------------------------
# Before any rule is read (not for help or clean): a part file whose content changed but whose date
# did not move forward is touched (tools/freshen); every object depends on $(BUILD)/flags, which
# changes when the compiler or its flags do; and bin/ notes the build folder it was linked from, its
# programs removed (to be linked again) when that changes (CC=clang after a gcc build).
# -Werror changes no object, only whether a warning stops the build: left out, so that a build
# without it (the grader's own-tree build runs make in a clean environment) rebuilds nothing.
FLAGS_TEXT := $(subst ','\'',$(CC) $(filter-out -Werror,$(CPPFLAGS) $(CFLAGS) $(LDFLAGS)))
ifneq ($(filter-out help clean,$(or $(MAKECMDGOALS),all)),)
  $(shell [ ! -f tools/freshen ] || sh tools/freshen $(BUILD)/sources.cksum $(wildcard parts/*/*.c parts/*/*.h); \
          mkdir -p $(BUILD); \
          printf '%s\n' '$(FLAGS_TEXT)' > $(BUILD)/flags.new && { cmp -s $(BUILD)/flags.new $(BUILD)/flags || \
          mv $(BUILD)/flags.new $(BUILD)/flags; }; rm -f $(BUILD)/flags.new; \
          mkdir -p $(BIN) && { [ "$$(cat $(BIN)/.build 2>/dev/null)" = "$(BUILD)" ] || \
          { find $(BIN) -maxdepth 1 -type f -perm -u+x -exec rm -f {} +; echo $(BUILD) > $(BIN)/.build; }; })
endif

# Written above before any rule runs; these make them again only when a goal removed them first
# (make clean all).
$(BUILD)/flags:
	@mkdir -p $(dir $@)
	@printf '%s\n' '$(FLAGS_TEXT)' > $@

$(BUILD)/%.o: %.c $(BUILD)/flags
	$(say) CC $<
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

# The code version for the JSON sidecar and the EXR provenance (a student release has no git: its
# VERSION file), "-dirty" when a tracked file differs from the commit at build time. The header is
# written before any rule is read, and only when the version changed: no rule forces it, so a make
# with nothing edited rebuilds nothing (make -q says so; CI checks it after make test).
VERSION := $(shell git describe --always --dirty 2>/dev/null || cat VERSION 2>/dev/null || echo unknown)
CPPFLAGS += -I$(BUILD)/gen
HASH := \#
ifneq ($(filter-out help clean,$(or $(MAKECMDGOALS),all)),)
  $(shell mkdir -p $(BUILD)/gen && echo '$(HASH)define PL_VERSION "$(VERSION)"' > $(BUILD)/gen/version.h.new && \
          { cmp -s $(BUILD)/gen/version.h.new $(BUILD)/gen/version.h || mv $(BUILD)/gen/version.h.new $(BUILD)/gen/version.h; }; \
          rm -f $(BUILD)/gen/version.h.new)
endif
$(BUILD)/gen/version.h:
	@mkdir -p $(dir $@)
	@echo '$(HASH)define PL_VERSION "$(VERSION)"' > $@
$(BUILD)/framework/sidecar.o $(BUILD)/framework/range.o: $(BUILD)/gen/version.h

# ---- tests: one binary per suite, so a crash in one part costs no other -----------------------
$(BUILD)/tests/%.o $(BUILD)/course/%.o: CPPFLAGS += $(shell pkg-config --cflags $(TPKGS))

## test-<suite>: run one suite: $(HELP_SUITES)
## test-part3 FILTER='*hemisphere*': run only the tests whose names match (LIST=1: list them)
define suite_rules
$(BIN)/test-$(1): $(call suite_obj,$(1)) $(COMMON_OBJ) $(LIB_OBJ)
	$$(say) LD $$@
	@mkdir -p $$(dir $$@)
	$$(Q)$$(CC) $$(LDFLAGS) -o $$@ $$^ $$(LDLIBS) $$(shell pkg-config --libs $(TPKGS))

test-$(1): $(BIN)/test-$(1) $(BIN)/pathtracer
	@echo "== test-$(1)"
	$$(Q)PL_TEST_FILTER='$$(FILTER)' PL_TEST_LIST='$$(LIST)' PL_TEST_SUITE=test-$(1) sh tests/common/run_suite.sh test-$(1) $(BIN)/test-$(1)
endef
$(foreach s,$(SUITES),$(eval $(call suite_rules,$(s))))

# ---- a part's objects, inspected as the autograder inspects them, before its suite runs --------
# The grader refuses a part whose compiled objects call what part code may not, or hold what plain
# C does not compile to (grader/grade_inspect.c): test-partN refuses it too, with the grader's words.
# The part's files are compiled once more for it as the grader compiles them: without link-time
# optimisation (so the objects hold machine code) and without the sanitizers.
INSPECT_BUILD  := $(BUILD)/inspect
INSPECT_CFLAGS := $(filter-out -flto% -fsanitize% -fno-sanitize% -fno-omit-frame-pointer -O1,$(CFLAGS)) -O2
$(INSPECT_BUILD)/%.o: %.c $(BUILD)/flags
	$(say) CC "$< (the grader's way)"
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(CPPFLAGS) $(INSPECT_CFLAGS) -c -o $@ $<
# The framework's global names, which a link-time optimised program no longer holds: the compiler's
# nm reads them from the framework's objects (bytecode) through its plugin.
NM_FOR_CC := $(if $(findstring clang,$(CC)),llvm-nm,gcc-nm)
$(BUILD)/framework.names: $(patsubst %.c,$(BUILD)/%.o,$(FRAMEWORK_SRC))
	$(Q){ $(NM_FOR_CC) --defined-only --extern-only --format=just-symbols $^ 2>/dev/null || true; } | \
	    grep -v -e ':$$' -e '^$$' > $@.tmp; mv $@.tmp $@
part_folder = $(firstword $(wildcard parts/$(1)_*))
define inspect_rules
test-$(1): inspect-$(1)
.PHONY: inspect-$(1)
inspect-$(1): $(BIN)/inspect-part $(BIN)/test-$(1) $(BUILD)/framework.names $(patsubst %.c,$(INSPECT_BUILD)/%.o,$(wildcard $(call part_folder,$(1))/*.c))
	$$(Q)$(BIN)/inspect-part $(BIN)/test-$(1) $(BUILD)/framework.names $(call part_folder,$(1)) $(patsubst %.c,$(INSPECT_BUILD)/%.o,$(wildcard $(call part_folder,$(1))/*.c))
endef
$(foreach s,$(PART_SUITES),$(eval $(call inspect_rules,$(s))))

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
# read, in the order read, so a new target documents itself where it is defined. $(HELP_SUITES) in a
# line's text becomes the suites this tree has: a release of five parts lists no part 6.
comma := ,
HELP_SUITES := $(if $(PART_SUITES),test-$(firstword $(PART_SUITES)) .. test-$(lastword $(PART_SUITES))$(comma) )test-framework$(comma) \
               test-grader$(if $(filter course,$(SUITES)),$(comma) test-course)
help:  ## this list
	@echo "pathlab targets (settings: V=1 full commands, WERROR=1, SAN=1, OPT=-O0, STB=vendored):"
	@awk -F'## ' -v suites='$(HELP_SUITES)' \
	     '/^[$$()A-Za-z0-9_.%<>\/-]+:[^=]*## / { split($$1, t, ":"); sub(/^\$$\(BIN\)/, "$(BIN)", t[1]); \
	                                            printf "  make %-22s %s\n", t[1], $$2; next } \
	      /^## [^:]+: / { s = $$2; gsub(/\$$\(HELP_SUITES\)/, suites, s); i = index(s, ": "); \
	                      printf "  make %-22s %s\n", substr(s, 1, i - 1), substr(s, i + 2) }' \
	     $(MAKEFILE_LIST)

# ---- the folders' own targets -----------------------------------------------------------------
# One fragment per folder that has targets. A tree may lack a folder, and then its targets: the
# student release has no course/, a part's grading tree holds only what the part's
# build and tests need.
-include grader/grader.mk
# Framework objects that need others of the framework, for the links that list their objects one
# by one (grader/grader.mk's, through GRADER_FRAMEWORK_OBJ): output.o encodes its files on
# parallel_for_threads (parallel.o, which carries the helpers' work counts: counters.o), and exr.o
# writes through exr_io.o. A prerequisite here joins each link's $^.
$(BIN)/grade $(BIN)/inspect-part $(BIN)/grade-probe: $(addprefix $(BUILD)/framework/,parallel.o counters.o exr_io.o)
-include grader/seam/seam.mk
-include tools/tools.mk
-include handout/handout.mk
-include bench/bench.mk
-include fuzz/fuzz.mk
-include course/course.mk
-include $(shell find build -name '*.d' 2>/dev/null)

# The grader (bin/grade) and its suite. It ships to students (make grade: their own tree, public
# cases) and to the autograder (bin/grade --submission: each part on its own).

# The sandbox's system-call filter needs Debian's libseccomp (libseccomp-dev, in tools/setup's list);
# without it (macOS) grader/sandbox_posix.c stands in, and bin/grade --submission as root refuses to
# grade. grader/probe_main.c is bin/grade-probe, the sandbox's self-test (its own program).
SANDBOX_SRC := $(if $(shell pkg-config --exists libseccomp 2>/dev/null && echo yes),grader/sandbox_linux.c,grader/sandbox_posix.c)
SANDBOX_IMPL := $(if $(filter grader/sandbox_linux.c,$(SANDBOX_SRC)),linux,posix)
GRADER_SRC := $(filter-out grader/grade_main.c grader/probe_main.c grader/inspect_main.c grader/sandbox_linux.c grader/sandbox_posix.c,\
                $(wildcard grader/*.c)) $(SANDBOX_SRC)
GRADER_OBJ := $(patsubst %.c,$(BUILD)/%.o,$(GRADER_SRC))
GRADER_LIBS := $(if $(filter linux,$(SANDBOX_IMPL)),$(shell pkg-config --libs libseccomp))
# The object inspection reads ELF objects with elfutils' libelf (libelf-dev, in tools/setup's list);
# without it (macOS: its objects are Mach-O) the inspection says it is the autograder's, and
# bin/grade --submission as root refuses to grade.
HAVE_LIBELF := $(shell pkg-config --exists libelf 2>/dev/null && echo yes)
GRADER_LIBS += $(if $(HAVE_LIBELF),$(shell pkg-config --libs libelf))
$(BUILD)/grader/grade_inspect.o: CPPFLAGS += $(if $(HAVE_LIBELF),-DPL_HAVE_LIBELF $(shell pkg-config --cflags libelf))
# bin/grade links the framework's file, image and statistics code, never a part: it must not run
# student code in its own process. The command line and the render key (cli.o, range.o and the
# output.o the merge writes through) come along for checking the references (grade_refs.c).
GRADER_FRAMEWORK_OBJ := $(addprefix $(BUILD)/framework/,image.o file.o exr.o film.o status.o stats.o utf8.o clock.o cli.o \
                          range.o output.o) \
                        $(BUILD)/third_party/lodepng/lodepng.o
$(BIN)/grade: $(BUILD)/grader/grade_main.o $(GRADER_OBJ) $(GRADER_FRAMEWORK_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS) $(GRADER_LIBS)

# The graded build's recipes, as data (grader/grade_build.c reads them): the compiler, the flags a
# part's file is compiled with, and each graded program's link line. bin/grade builds a submission
# from them without make or a shell: a submitted name never reaches a command anything interprets.
# Written in the course's own tree, by the course's make, before any student code is seen.
GRADE_RECIPES := $(BUILD)/grade-recipes.txt
comma        := ,
grade_link   = link $(1) $(LDFLAGS) -o $(1) $(2) $(LDLIBS) $(3)
$(GRADE_RECIPES): FORCE
	@mkdir -p $(dir $@)
	@{ echo 'cc $(CC)'; \
	   echo 'objects $(BUILD)'; \
	   echo 'compile $(filter-out -MMD -MP,$(CPPFLAGS)) $(CFLAGS)'; \
	   echo '$(call grade_link,$(BIN)/pathtracer,$(BUILD)/framework/main.o $(LIB_OBJ))'; \
	   $(foreach n,$(patsubst part%,%,$(PART_SUITES)),\
	   echo '$(call grade_link,$(BIN)/test-part$(n),$(call suite_obj,part$(n)) $(COMMON_OBJ) $(LIB_OBJ),$(shell pkg-config --libs $(TPKGS)))'; \
	   echo '$(call grade_link,$(BIN)/subject-part$(n),$(foreach f,$(call part_fns,$(n)),-Wl$(comma)--wrap=$(f)) $(call suite_obj,part$(n)) $(COMMON_OBJ) $(LIB_OBJ) $(call seam_obj,subject,record,$(n)),$(shell pkg-config --libs $(TPKGS)))';) \
	 } >$@.tmp && mv $@.tmp $@

# The object inspection on a student's own tree (make test-partN runs it: Makefile, inspect_rules).
$(BIN)/inspect-part: $(BUILD)/grader/inspect_main.o $(GRADER_OBJ) $(GRADER_FRAMEWORK_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS) $(GRADER_LIBS)

# The sandbox's self-test: tries what the filter forbids, and sweeps folders for secret bytes, as a
# stage of a grading is confined (it links the grader's library for that).
$(BIN)/grade-probe: $(BUILD)/grader/probe_main.o $(GRADER_OBJ) $(GRADER_FRAMEWORK_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS) $(GRADER_LIBS)

# The grader's suite (make test-grader) tests its modules, all but main, so it links them; it runs
# bin/grade itself once (a clean run, leak detection on under SAN=1) and bin/grade-probe under the
# sandbox (order-only: not linked in).
$(BIN)/test-grader: $(GRADER_OBJ) | $(BIN)/grade-probe
$(BIN)/test-grader: LDLIBS += $(GRADER_LIBS) $(shell pkg-config --libs $(GRADER_TPKGS))
$(BUILD)/tests/grader/%.o: CPPFLAGS += $(shell pkg-config --cflags $(GRADER_TPKGS))
test-grader: $(BIN)/grade
# The grader builds with GCC's -Wformat-truncation on: paths go through grade_path (refused, never
# cut) and messages through grade_msg (cut on purpose, marked), both in grader/grade_fmt.c.

.PHONY: grade test-report test-grader-process test-grade-confirm
grade: $(BIN)/grade  ## grade your parts on the public cases (PARTS=3: one part; SEED=N: repeat a run); report in out/grade/
	$(Q)$(BIN)/grade --out out/grade $(if $(PARTS),--parts $(PARTS)) $(if $(SEED),--seed $(SEED))

# The HTML report in a real browser: headless Chromium screenshots it.
test-report: $(BIN)/grade $(BIN)/pathtracer $(BIN)/imgtool  ## the grader's HTML report, screenshotted in headless Chromium
	$(Q)sh tests/grader/report.sh

# A failure chance can explain is confirmed by a second render, and only such a failure
# (tests/grader/confirm.sh: scratch trees whose renderer is wrong on purpose, first or always).
test-grade-confirm: $(BIN)/grade $(BIN)/pathtracer $(BIN)/test-part3  ## a failing case is rendered twice, judged on the second
	$(Q)sh tests/grader/confirm.sh

# The grader's containment at process level (tests/grader/sandbox.sh says what it proves): grades
# part 1 of hostile submissions; as root it also sweeps the file system as student code for secrets
# (STRIP_TOOL, the course's stub maker from course/course.mk, makes its stubbed submission: where
# the tree has none, the sweep is skipped).
test-grader-process: $(BIN)/grade $(BIN)/grade-probe $(BIN)/test-grader $(addprefix $(BIN)/test-,$(PART_SUITES))  ## the grader's containment, at process level
	$(if $(STRIP_TOOL),$(Q)$(MAKE) --no-print-directory $(STRIP_TOOL))
	$(Q)STRIP_TOOL='$(STRIP_TOOL)' sh tests/grader/sandbox.sh


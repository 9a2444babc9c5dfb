# Instructor tooling: the student release (included by the Makefile; students never need it).
#   make release           release/student: the tracked tree with every solution replaced by its stub,
#                          with its GitHub Classroom workflow (.github/workflows/classroom.yml);
#                          release/autograder.zip: the Gradescope autograder bundle (the whole course)
#   make release-check     the same, then proves it sound (tools/make_release says what it checks)
#   make test-autograder   the bundle end to end in Gradescope's layout (tests/autograder/run.sh)

.PHONY: release release-check test-autograder

help::
	@echo "instructors:"
	@echo "  make release-check    cut release/student (solutions -> stubs) and prove it sound"
	@echo "  make mutants          show each catalogued student bug is caught by its part's tests"
	@echo "  make calibrate N=200  each suite's false-failure rate over N fresh seeds, beside its alpha"
	@echo "  make references       render the grading references (SLURM=1: as a Slurm job array)"
	@echo "  make grade-mutants    grade each catalogued bug: it must lose points on its own part"

# The stripper's core is a library so tests/framework/test_strip.c can test its rules directly.
STRIP_OBJ     := $(BUILD)/tools/strip.o
TOOL_LIB_OBJ  := $(BUILD)/framework/image.o $(BUILD)/framework/file.o $(BUILD)/framework/status.o \
                 $(BUILD)/third_party/lodepng/lodepng.o

$(BIN)/strip_solutions: $(BUILD)/tools/strip_solutions.o $(STRIP_OBJ) $(TOOL_LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

# An extra prerequisite lands in the suite rule's $^, so the framework tests link the stripper.
$(BIN)/test-framework: $(STRIP_OBJ)

# bin/release_points: each part's points, read by the grader's own case loader (classroom.yml's steps).
$(BIN)/release_points: $(BUILD)/tools/release_points.o $(BUILD)/tools/grade_cases.o $(BUILD)/framework/status.o
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)
$(BUILD)/tools/release_points.o: CPPFLAGS += $(shell pkg-config --cflags jansson)

release: $(BIN)/strip_solutions $(BIN)/release_points
	$(Q)bash tools/make_release build $(BIN)/strip_solutions $(BIN)/release_points

release-check: release $(BIN)/imgtool
	$(Q)bash tools/make_release check $(BIN)/strip_solutions $(BIN)/imgtool $(BIN)/release_points

# Slow (about 10 minutes on 2 cores): the bundle graded in a temporary Gradescope root, as root.
test-autograder: release
	$(Q)bash tests/autograder/run.sh

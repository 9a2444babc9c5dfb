# The grader (issue 10): the image verdict and its suite, make test-grader. The suite also tests the
# grader's modules (all but main), so it links them.
$(BIN)/test-grader: $(BUILD)/tools/verdict.o $(patsubst %.c,$(BUILD)/%.o,$(filter-out tools/grade_main.c,$(wildcard tools/grade*.c)))
$(BIN)/test-grader: LDLIBS += $(shell pkg-config --libs jansson)
$(BUILD)/tests/grader/%.o: CPPFLAGS += $(shell pkg-config --cflags jansson)

# bin/grade links the framework's file and image code, never a part (it must not run student code).
GRADE_OBJ := $(patsubst %.c,$(BUILD)/%.o,$(wildcard tools/grade*.c)) $(BUILD)/tools/verdict.o \
             $(BUILD)/tests/common/stats.o $(BUILD)/framework/image.o $(BUILD)/framework/file.o \
             $(BUILD)/third_party/lodepng/lodepng.o $(BUILD)/framework/exr.o $(BUILD)/framework/film.o \
             $(BUILD)/framework/status.o
$(BIN)/grade: $(GRADE_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS) $(shell pkg-config --libs jansson)
$(BUILD)/tools/grade%.o: CPPFLAGS += $(shell pkg-config --cflags jansson)
# The grader's paths and messages live in fixed buffers on purpose: a long path is cut in a message
# (or makes a file not found, which fails safe), never overflows. GCC's truncation analysis, which
# sees more at -O1 (SAN=1) than at -O2, would make every such snprintf an error under WERROR=1.
$(BUILD)/tools/grade%.o: CFLAGS += -Wno-format-truncation

.PHONY: grade
# A student's make grade: this tree as it is, public cases, the report under out/grade/
# (PARTS=1,2 grades some parts; SEED=N repeats a grading run exactly).
grade: $(BIN)/grade
	$(Q)$(BIN)/grade --out out/grade $(if $(PARTS),--parts $(PARTS)) $(if $(SEED),--seed $(SEED))

# The HTML report in a real browser (issue 10): headless Chromium screenshots it.
.PHONY: test-report
test-report: $(BIN)/grade $(BIN)/pathtracer $(BIN)/imgtool
	$(Q)sh tests/grader/report.sh

# The grader's containment at process level (tests/grader/sandbox.sh says what it proves): grades
# part 1 of two hostile submissions; as root it also checks what nobody can read.
.PHONY: test-grader-process
test-grader-process: $(BIN)/grade $(BIN)/test-grader $(foreach n,1 2 3 4 5,$(BIN)/test-part$(n))
	$(Q)sh tests/grader/sandbox.sh

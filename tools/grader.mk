# The grader (issue 10): the image verdict and its suite, make test-grader.
$(BIN)/test-grader: $(BUILD)/tools/verdict.o

# bin/grade links the framework's file and image code, never a part (it must not run student code).
GRADE_OBJ := $(patsubst %.c,$(BUILD)/%.o,$(wildcard tools/grade*.c)) $(BUILD)/tools/verdict.o \
             $(BUILD)/tests/common/stats.o $(BUILD)/framework/image.o $(BUILD)/framework/file.o \
             $(BUILD)/framework/status.o
$(BIN)/grade: $(GRADE_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS) $(shell pkg-config --libs jansson)
$(BUILD)/tools/grade%.o: CPPFLAGS += $(shell pkg-config --cflags jansson)

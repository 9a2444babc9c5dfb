# Instructor tooling: the reference images and their Slurm test (the student release leaves this out).

# bin/references: the reference images (make references [FORCE=1] [CASES="part3 spot"] [SLURM=1]).
REF_OBJ := $(BUILD)/tools/references.o $(BUILD)/tools/grade_cases.o $(BUILD)/tools/grade_run.o $(LIB_OBJ)
$(BIN)/references: $(REF_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS) $(shell pkg-config --libs jansson)
$(BUILD)/tools/references.o: CPPFLAGS += $(shell pkg-config --cflags jansson)

.PHONY: references
references: $(BIN)/references $(BIN)/pathtracer
	$(Q)$(BIN)/references $(if $(FORCE),--force) $(if $(SLURM),--slurm $(if $(SBATCH),--sbatch "$(SBATCH)")) $(CASES)

# The Slurm test (issue 12): a real single-node cluster; skips when not root.
.PHONY: test-slurm
test-slurm:
	$(Q)sh tests/slurm/run.sh


# Loader benchmark (issue 7): best-of-BENCH_RUNS load time per scene. Not a test.
.PHONY: bench-load
bench: bench-load

LOAD_SCENES ?= $(wildcard scenes/*.dae) bench/data/cornell_bunny_58k.dae

$(BIN)/load_bench: $(BUILD)/bench/load_bench.o $(LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

bench-load: $(BIN)/load_bench
	@echo "== dae_load, best of $${BENCH_RUNS:-20} runs"
	@$(BIN)/load_bench $(LOAD_SCENES)

# Output benchmark (issue 7): one render's PNG + rate map + sidecar written as a unit. Not a test.
.PHONY: bench-write
bench: bench-write
$(BIN)/write_bench: $(BUILD)/bench/write_bench.o $(LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

bench-write: $(BIN)/write_bench $(BIN)/pathtracer
	@echo "== writing a render's outputs, best of $${BENCH_RUNS:-20} runs"
	@$(BIN)/write_bench

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

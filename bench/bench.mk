# BVH benchmark (part 2): not a test. `make bench` runs it (with the other benchmarks);
# `make bench-bvh` runs it alone and rewrites bench/RESULTS.md.
#   Embree: when its headers are missing, bench-bvh tries `apt-get install libembree-dev` (needs root;
#   without it the Embree columns read "-"). Debian's package ships no pkg-config file, so the header
#   is the test; pkg-config embree3 is used when it exists. Only bin/bvh_bench links Embree.
#   BENCH_RUNS=N (5): runs per figure, median taken. BENCH_SCENES: the fixed list below.
.PHONY: bench-bvh
bench: bench-bvh

BENCH_RUNS   ?= 5
BENCH_SCENES ?= scenes/cornell_bunny.dae bench/data/cornell_bunny_58k.dae proc:10000 proc:100000 proc:1000000 proc:4000000
EMBREE_HDR   := /usr/include/embree3/rtcore.h
embree_flags  = $(if $(wildcard $(EMBREE_HDR)),-DPL_HAVE_EMBREE $(shell pkg-config --cflags embree3 2>/dev/null))
embree_libs   = $(if $(wildcard $(EMBREE_HDR)),$(or $(shell pkg-config --libs embree3 2>/dev/null),-lembree3))

# Built with recursive make after the install step, so the Embree test sees the header.
$(BIN)/bvh_bench: bench/bvh_bench.c $(BUILD)/tests/common/procmesh.o $(LIB_OBJ)
	$(say) CC $<
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(CPPFLAGS) $(CFLAGS) $(embree_flags) -o $@ $^ $(LDLIBS) $(embree_libs)

bench-bvh: $(BIN)/pathtracer
	@if [ ! -f $(EMBREE_HDR) ]; then \
	   echo "bench-bvh: Embree missing: apt-get install libembree-dev (needs root)"; \
	   apt-get install -y -qq libembree-dev >/dev/null 2>&1 || \
	   { apt-get update -qq >/dev/null 2>&1 && apt-get install -y -qq libembree-dev >/dev/null 2>&1; } || \
	   echo "bench-bvh: could not install libembree-dev: Embree columns will be empty"; \
	 fi
	@rm -f $(BIN)/bvh_bench
	@$(MAKE) --no-print-directory $(BIN)/bvh_bench
	@BIN=$(BIN) RUNS=$(BENCH_RUNS) sh bench/bvh_bench.sh $(BENCH_SCENES)

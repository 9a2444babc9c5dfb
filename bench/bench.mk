# Benchmarks: speed figures, never tests. `make bench` runs them all; each prints its figures, and
# none installs anything or writes a tracked file (bench-bvh's table goes to build/bench/bvh/).
# BENCH_RUNS=N: runs per figure (median or best, as each says).
.PHONY: bench bench-bvh bench-references bench-load bench-write bench-transport bench-trace bench-surfaces bench-hotpath bench-env \
        bench-specular
# bench-grade (the solution graded as a submission) is the course's: course/course.mk, where the tree has it.
bench: bench-hotpath bench-bvh $(if $(wildcard course/course.mk),bench-grade) bench-references bench-load bench-write bench-transport bench-trace bench-surfaces $(if $(wildcard parts/part6_*),bench-specular) $(if $(wildcard parts/part8_*),bench-env)  ## every benchmark (figures, not tests; see bench/RESULTS.md)

# ---- BVH (part 2): build time, rays per second, whole render; beside Embree when installed -------
#   Embree (Debian's libembree-dev, used only here) ships no pkg-config file, so its header is the
#   test; install it yourself (apt-get install libembree-dev) for the Embree columns.
BENCH_RUNS   ?= 5
BENCH_SCENES ?= scenes/cornell_bunny.dae bench/data/cornell_bunny_58k.dae proc:10000 proc:100000 proc:1000000 proc:4000000
EMBREE_HDR   := /usr/include/embree3/rtcore.h
embree_flags  = $(if $(wildcard $(EMBREE_HDR)),-DPL_HAVE_EMBREE $(shell pkg-config --cflags embree3 2>/dev/null))
embree_libs   = $(if $(wildcard $(EMBREE_HDR)),$(or $(shell pkg-config --libs embree3 2>/dev/null),-lembree3))

$(BIN)/bvh_bench: bench/bvh_bench.c $(LIB_OBJ)
	$(say) CC $<
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(CPPFLAGS) $(CFLAGS) $(embree_flags) -o $@ $^ $(LDLIBS) $(embree_libs)

bench-bvh: $(BIN)/pathtracer $(BIN)/bvh_bench  ## BVH build time, rays per second and whole-render time (beside Embree)
	@[ -f $(EMBREE_HDR) ] || echo "bench-bvh: Embree not installed (apt-get install libembree-dev): its columns read '-'"
	@BIN=$(BIN) RUNS=$(BENCH_RUNS) sh bench/bvh_bench.sh $(BENCH_SCENES)

# ---- reference throughput: camera samples per second on one core, to size a Slurm array --------
bench-references: $(BIN)/pathtracer  ## camera samples per second per core (sizes a Slurm reference job)
	@echo "== reference throughput, one core (160x120, 256 samples per pixel, one range)"
	@for flags in "--normals" "-m 1 -l 4" "-m 5 -l 1"; do \
	   start=$$(date +%s.%N); \
	   $(BIN)/pathtracer -q -t 1 $$flags -r 160 120 -s 256 --seed 1 scenes/cornell_spheres.dae; \
	   end=$$(date +%s.%N); \
	   awk -v s=$$start -v e=$$end -v f="$$flags" 'BEGIN { printf "  %-12s %8.2f M samples/s/core\n", f, 160*120*256/(e-s)/1e6 }'; \
	 done

# ---- the loader: best-of-N load time per scene ----------------------------------------------------
LOAD_SCENES ?= $(wildcard scenes/*.dae) bench/data/cornell_bunny_58k.dae
$(BIN)/load_bench: $(BUILD)/bench/load_bench.o $(LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

bench-load: $(BIN)/load_bench  ## scene load time, best of BENCH_RUNS
	@echo "== dae_load, best of $${BENCH_RUNS:-20} runs"
	@$(BIN)/load_bench $(LOAD_SCENES)

# ---- output: one render's PNG + rate map + sidecar written as a unit -----------------------------
$(BIN)/write_bench: $(BUILD)/bench/write_bench.o $(LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

bench-write: $(BIN)/write_bench $(BIN)/pathtracer  ## time to write a render's outputs
	@echo "== writing a render's outputs, best of $${BENCH_RUNS:-20} runs"
	@$(BIN)/write_bench

# ---- mirror and glass (part 6, where the course has it): the box beside its diffuse twin ---------
bench-specular: $(BIN)/pathtracer  ## part 6: the mirror-and-glass Cornell box's render time beside the diffuse one's (target: at most 1.5x)
	@BIN=$(BIN) RUNS=$(BENCH_RUNS) sh bench/specular.sh

# ---- the environment light (part 8, where the course has it): tables and time per sample ---------
$(BIN)/env_bench: $(BUILD)/bench/env_bench.o $(LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

bench-env: $(BIN)/env_bench  ## part 8: building the tables, and a sample's time, from 64x32 to 4096x2048 texels
	@$(BIN)/env_bench

# ---- light transport (parts 3-5): Cornell scenes at 480x360, -s 64 -l 4 -m 5, with relMSE --------
bench-transport: $(BIN)/pathtracer $(BIN)/imgtool  ## parts 3-5 render times and relMSE against a converged render
	@BIN=$(BIN) bench/transport.sh

bench-trace: $(BIN)/pathtracer  ## --trace-pixel's cost, and a render with the trace hooks beside one without (BASE=commit)
	$(Q)sh bench/trace.sh

# ---- the hot path: this tree's renders beside a pinned earlier commit's, as ratios -----------------
# Run it before any change to the hot path lands (traversal, counters, the seam's wrappers, the
# trace's hooks, the random streams): a ratio above 1 is time the change added to every render.
# a2f564c is the last commit before the bookkeeping (trace hooks, checks, surface offsets) came.
HOTPATH_BASE ?= a2f564c
bench-hotpath: $(BIN)/pathtracer  ## the course's renders beside HOTPATH_BASE's, as ratios (run before a hot-path change lands)
	@echo "== this tree beside $(HOTPATH_BASE): medians of $(BENCH_RUNS) alternating runs, ratio new / old"
	@sh bench/against.sh $(HOTPATH_BASE) $(BENCH_RUNS) scenes/cornell_bunny.dae -q --cs184-camera -t 2 -r 480 360 -s 64 -l 4 -m 5 -a 32 0.05
	@sh bench/against.sh $(HOTPATH_BASE) $(BENCH_RUNS) scenes/cornell_spheres.dae -q -t 2 -r 480 360 -s 16 -l 4 -m 1
	@sh bench/against.sh $(HOTPATH_BASE) $(BENCH_RUNS) bench/data/cornell_bunny_58k.dae -q --normals -t 2 -r 800 600 -s 1

# ---- leaving surfaces (spawn.h): what the offsets cost a render, beside the commit before them ----
SURFACES_BASE ?= e179730
bench-surfaces: $(BIN)/pathtracer  ## renders with the surface offsets beside renders without them (SURFACES_BASE=commit)
	@echo "== this tree beside $(SURFACES_BASE), the last commit whose rays left surfaces by EPS_F alone"
	@for f in "-m 1 -l 4" "-m 5 -l 1" "-m 5 -l 4"; do \
	   for s in scenes/cornell_spheres.dae scenes/cornell_bunny.dae; do \
	     sh bench/against.sh $(SURFACES_BASE) $(BENCH_RUNS) $$s -q -t 2 -r 200 150 -s 32 $$f; \
	   done; \
	 done

# Grader benchmark (issue 10): grading a correct submission, all five parts isolated (builds, unit
# tests, every case, hidden ones included). Not a test.
.PHONY: bench-grade
bench: bench-grade
bench-grade: $(BIN)/grade
	@echo "== grading the solution as a submission (5 isolated builds, suites, all cases)"
	@rm -rf build/bench-grade && mkdir -p build/bench-grade/sub && cp -a parts build/bench-grade/sub/
	@/usr/bin/time -f "graded in %e s wall, %U s user" $(BIN)/grade --submission build/bench-grade/sub \
	    --out build/bench-grade/out --seed 1 | tail -n 4

# Reference throughput (issue 12): camera samples per second on one core, for sizing a Slurm array
# (a case needs width x height x reference_samples samples). Not a test.
.PHONY: bench-references
bench: bench-references
bench-references: $(BIN)/pathtracer
	@echo "== reference throughput, one core (160x120, 256 samples per pixel, one range)"
	@for flags in "--normals" "-m 1 -l 4" "-m 5 -l 1"; do \
	   start=$$(date +%s.%N); \
	   $(BIN)/pathtracer -q -t 1 $$flags -r 160 120 -s 256 --seed 1 scenes/cornell_spheres.dae; \
	   end=$$(date +%s.%N); \
	   awk -v s=$$start -v e=$$end -v f="$$flags" 'BEGIN { printf "  %-12s %8.2f M samples/s/core\n", f, 160*120*256/(e-s)/1e6 }'; \
	 done

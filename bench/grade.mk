# Grader benchmark (issue 10): grading a correct submission, all five parts isolated (builds, unit
# tests, every case, hidden ones included). Not a test.
.PHONY: bench-grade
bench: bench-grade
bench-grade: $(BIN)/grade
	@echo "== grading the solution as a submission (5 isolated builds, suites, all cases)"
	@rm -rf build/bench-grade && mkdir -p build/bench-grade/sub && cp -a parts build/bench-grade/sub/
	@/usr/bin/time -f "graded in %e s wall, %U s user" $(BIN)/grade --submission build/bench-grade/sub \
	    --out build/bench-grade/out --seed 1 | tail -n 4

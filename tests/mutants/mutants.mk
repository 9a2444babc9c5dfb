# Mutants: realistic student bugs kept as patches of the solution; each must be caught by the suite
# its patch names. `make mutants` applies each to a scratch copy under build/mutants/.
.PHONY: mutants
mutants: all
	@tests/mutants/run.sh

# The grader against the same catalogue: each mutant loses points on its own part (slow: one graded
# submission per mutant).
.PHONY: grade-mutants
grade-mutants: $(BIN)/grade $(BIN)/pathtracer
	$(Q)sh tests/mutants/grade.sh

# Mutants: realistic student bugs kept as patches of the solution; each must be caught by the suite
# its patch names. `make mutants` applies each to a scratch copy under build/mutants/.
.PHONY: mutants
mutants: all
	@tests/mutants/run.sh

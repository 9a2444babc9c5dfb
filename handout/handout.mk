# The handout's figures: every picture handout/part<N>.md asks for, into out/figures/ (figures.sh).
.PHONY: figures
figures: $(BIN)/pathtracer $(BIN)/imgtool  ## every figure the handout asks for (parts 1-5), into out/figures/
	@BIN=$(BIN) handout/figures.sh

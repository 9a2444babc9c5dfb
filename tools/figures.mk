# `make figures`: every figure the handout asks for, parts 1-5, into out/figures/ (handout/figures.sh).
.PHONY: figures
figures: $(BIN)/pathtracer $(BIN)/imgtool
	@BIN=$(BIN) handout/figures.sh

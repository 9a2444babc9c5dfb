# The handout's figures: every picture handout/part<N>.md asks for, into out/figures/ (figures.sh).
.PHONY: figures
figures: $(BIN)/pathtracer $(BIN)/imgtool $(BIN)/acne_figure  ## every figure the handout asks for (every part of the course), into out/figures/
	@BIN=$(BIN) handout/figures.sh

# The shadow-acne figure of handout/part3.md (3.4): raw against spawned shadow rays, side by side.
$(BIN)/acne_figure: $(BUILD)/handout/acne_figure.o $(LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

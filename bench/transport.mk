# Light transport benchmark (parts 3-5) and the handout's figures. Not part of any assignment.
#   make bench-transport   the Cornell bunny and spheres at 480x360, -s 64 -l 4 -m 5, 2 threads,
#                          against the course's compiled reference timings, with relMSE against a
#                          converged render (cached under build/bench/transport/)
#   make figures           every figure of handout/part3.md .. part5.md, into build/figures/
.PHONY: bench-transport figures
bench: bench-transport

$(BIN)/transport_img: $(BUILD)/bench/transport_img.o $(LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

bench-transport: $(BIN)/pathtracer $(BIN)/transport_img
	@BIN=$(BIN) bench/transport.sh

figures: $(BIN)/pathtracer $(BIN)/transport_img
	@BIN=$(BIN) handout/figures.sh

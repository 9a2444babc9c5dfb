# Light transport benchmark (parts 3-5). Not part of any assignment. (`make figures`: tools/figures.mk.)
#   make bench-transport   the Cornell bunny and spheres at 480x360, -s 64 -l 4 -m 5, 2 threads,
#                          against the course's compiled reference timings, with relMSE against a
#                          converged render (cached under build/bench/transport/)
.PHONY: bench-transport
bench: bench-transport

bench-transport: $(BIN)/pathtracer $(BIN)/imgtool
	@BIN=$(BIN) bench/transport.sh

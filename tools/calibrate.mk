# `make calibrate [N=200] [CALIBRATE_SUITES="part3 part4"]`: each suite's false-failure rate over N
# runs with fresh PL_TEST_SEED values, beside its stated alpha (tools/calibrate).
N ?= 200
CALIBRATE_SUITES ?= $(SUITES)
.PHONY: calibrate
calibrate: $(addprefix $(BIN)/test-,$(CALIBRATE_SUITES)) $(BIN)/pathtracer
	$(Q)BIN=$(BIN) tools/calibrate $(N) $(CALIBRATE_SUITES)

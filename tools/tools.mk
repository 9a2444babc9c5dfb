# Student utilities: tools/setup (set up and render) and bin/imgtool, the one image tool the tests,
# the release check, the benchmarks and the handout's figures share (tools/imgtool.c says what it does).
$(BIN)/imgtool: $(BUILD)/tools/imgtool.o $(LIB_OBJ)  ## the image tool: stats, means, relMSE, differences and montages of images
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

# bin/imgtool: the one image tool the tests, the release check, the benchmarks and the handout's
# figures share (tools/imgtool.c says what it does).
$(BIN)/imgtool: $(BUILD)/tools/imgtool.o $(LIB_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

# The film's EXR provenance records the code version.
$(BUILD)/framework/range.o: $(BUILD)/gen/version.h

# The grader (issue 10): the image verdict and its suite, make test-grader.
$(BIN)/test-grader: $(BUILD)/tools/verdict.o

# The split suites (grader/seam/seam.h): the grader runs a part's tests as subject | judge. The
# machinery is the grader's (grader/README.md); the programs it links are test programs (the part's
# suite and tests/common), built by the course's make before any student code is seen.
#
# subject-partN: test-partN's objects with part N's functions wrapped, each call recorded to fd 3.
# judge-partN: the same tests, framework and other parts, with part N's functions replayed from
# stdin: it links no object of part N. The function names come from the part's header, so the
# wrappers cannot miss one the header declares (the seam's table, grader/seam/seam.c, names them too).
# A part's folder (parts/part<N>_<name>/), found by its header.
part_dir    = $(dir $(wildcard parts/*/part$(1).h))
part_obj    = $(patsubst %.c,$(BUILD)/%.o,$(wildcard $(call part_dir,$(1))*.c))
paren      := (
part_fns    = $(shell sed -n 's/^[a-z_0-9]* [*]*\([a-z_0-9]*\)[$(paren)].*/\1/p' $(wildcard parts/*/part$(1).h))
seam_obj    = $(addprefix $(BUILD)/grader/seam/$(1)/,seam.o $(2).o seam_part$(3).o)

# ld --wrap redirects only calls the linker resolves: link-time optimisation resolves calls inside its
# unit first and would bypass the wrappers, so the split binaries need LTO=0 (the grader's builds) or SAN=1.
split_lto_off = $(or $(filter 1,$(SAN)),$(filter 0,$(strip $(LTO))))
split_refuse  = $(if $(split_lto_off),,@echo "ERROR: $@ needs LTO=0 (ld --wrap misses calls that LTO resolves)"; exit 1)

$(BUILD)/grader/seam/subject/%.o: grader/seam/%.c
	$(say) CC "$< (subject)"
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(CPPFLAGS) $(shell pkg-config --cflags $(TPKGS)) $(CFLAGS) -DPL_SEAM_SUBJECT -c -o $@ $<
$(BUILD)/grader/seam/judge/%.o: grader/seam/%.c
	$(say) CC "$< (judge)"
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(CPPFLAGS) $(shell pkg-config --cflags $(TPKGS)) $(CFLAGS) -DPL_SEAM_JUDGE -c -o $@ $<

define split_rules
$(BIN)/subject-part$(1): $(call suite_obj,part$(1)) $(COMMON_OBJ) $(LIB_OBJ) $(call seam_obj,subject,record,$(1))
	$$(split_refuse)
	$$(say) LD $$@
	@mkdir -p $$(dir $$@)
	$$(Q)$$(CC) $$(LDFLAGS) $$(foreach f,$$(call part_fns,$(1)),-Wl,--wrap=$$(f)) -o $$@ $$^ $$(LDLIBS) $$(shell pkg-config --libs $(TPKGS))

$(BIN)/judge-part$(1): $(call suite_obj,part$(1)) $(COMMON_OBJ) $(filter-out $(call part_obj,$(1)),$(LIB_OBJ)) $(call seam_obj,judge,replay,$(1))
	$$(say) LD $$@
	@mkdir -p $$(dir $$@)
	$$(Q)$$(CC) $$(LDFLAGS) -o $$@ $$^ $$(LDLIBS) $$(shell pkg-config --libs $(TPKGS))
endef
# One pair for each part the course has (the Makefile's PART_SUITES: its part folders).
$(foreach n,$(patsubst part%,%,$(PART_SUITES)),$(eval $(call split_rules,$(n))))

# Instructor-only targets: the release and its proof, the autograder bundle and its end-to-end test,
# references (locally or on Slurm), mutants and calibration. The student release leaves course/ out,
# and the Makefile includes this fragment only where it exists.
.PHONY: release release-check test-autograder references test-slurm mutants trace-mutants grade-mutants calibrate test-judge \
        test-portable test-grade-local calibrate-alternatives calibrate-grader

# ---- the course's parts: the one place a course chooses them ---------------------------------------
# The parts its students get: the release (its folders, suites, handout texts, references and the
# documents' <!-- BEGIN PART N --> sections), the autograder bundle (the grader grades the parts whose
# folders it holds) and release-check follow this list. Parts 1-5 are CS184's first path-tracing
# assignment; 6-9 (mirror and glass, microfacet metals, the environment light, the thin lens) the second.
## release COURSE_PARTS="1 2 3 4 5 6 7 8 9": cut a release of these parts (the default, 1 2 3 4 5, is CS184's first assignment)
COURSE_PARTS ?= 1 2 3 4 5
export COURSE_PARTS

COURSE_TOOL_OBJ := $(addprefix $(BUILD)/framework/,image.o file.o status.o) $(BUILD)/third_party/lodepng/lodepng.o

## test-course: the course's own tools' suite (the release stripper's rules, the class grader's escaping)

# ---- the release: release/student (solutions -> stubs) and release/autograder.zip --------------
# The stripper's rules are a library, so the course suite (course/release/test_strip.c) tests them.
STRIP_OBJ := $(BUILD)/course/release/strip.o
# The stub maker, also the grader's process test's (grader/grader.mk).
STRIP_TOOL := $(BIN)/strip_solutions
$(BIN)/strip_solutions: $(BUILD)/course/release/strip_solutions.o $(STRIP_OBJ) $(COURSE_TOOL_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)
$(BIN)/test-course: $(STRIP_OBJ) $(BUILD)/course/class/class_text.o

# bin/release_points: each part's points, read by the grader's own case loader (classroom.yml's steps).
$(BIN)/release_points: $(BUILD)/course/release/release_points.o $(BUILD)/grader/grade_spec.o $(BUILD)/framework/status.o
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS)

release: $(BIN)/strip_solutions $(BIN)/release_points  ## cut release/student and release/autograder.zip
	$(Q)bash course/release/cut $(BIN)/strip_solutions $(BIN)/release_points
	$(Q)bash course/release/bundle $(BIN)/release_points

release-check: release $(BIN)/imgtool  ## cut the release, then prove it sound (course/release/check says what)
	$(Q)bash course/release/check $(BIN)/strip_solutions $(BIN)/imgtool $(BIN)/release_points

# The grader's split suites (grader/seam/seam.h) in a scratch tree: same verdicts as test-partN on the
# solution and the stubs, and nothing gained by the attacks in course/judge/attacks/ (a few minutes).
test-judge:  ## the split suites (subject | judge per test) agree with test-partN and shrug off attacks
	$(Q)sh course/judge/split_check.sh

# Slow (about 10 minutes on 2 cores): the bundle graded in a temporary Gradescope root, as root.
test-autograder: release  ## the autograder bundle end to end in Gradescope's layout (solution, stubs, mutants, adversaries)
	$(Q)bash course/autograder/test.sh

# ---- portability: a student's laptop, imitated here (course/platform/portable.sh says what it proves) -
# About 5 minutes on 2 cores: two full builds of the release and their suites.
test-portable: release  ## the student release, solved, in strict C11 + POSIX with gcc and clang, vendored stb; refusals of old OpenEXR
	$(Q)sh course/platform/portable.sh

# make grade where the machine has no sandbox (a laptop) against the autograder, at one seed.
test-grade-local: release $(BIN)/grade  ## make grade without the sandbox: the autograder's verdicts (the solution, two catalogued bugs)
	$(Q)sh course/platform/grade_local.sh

# ---- references: the solution's renders of every grading case, locally or as a Slurm job array ---
# course/shared/: what the reference maker and the class grader both use (content keys, Slurm arrays).
COURSE_SHARED_OBJ := $(BUILD)/course/shared/key.o $(BUILD)/course/shared/slurm.o
REF_OBJ := $(BUILD)/course/references/references.o $(BUILD)/grader/grade_spec.o $(BUILD)/grader/grade_plan.o $(BUILD)/grader/grade_run.o \
           $(BUILD)/grader/grade_rate.o \
           $(BUILD)/grader/grade_fmt.o $(COURSE_SHARED_OBJ) \
           $(BUILD)/grader/sandbox_$(SANDBOX_IMPL).o $(LIB_OBJ)
$(BIN)/references: $(REF_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS) $(GRADER_LIBS)

references: $(BIN)/references $(BIN)/pathtracer  ## render the grading references (FORCE=1, CASES="part3 spot", SLURM=1 SBATCH="...")
	$(Q)$(BIN)/references $(if $(FORCE),--force) $(if $(SLURM),--slurm $(if $(SBATCH),--sbatch "$(SBATCH)")) $(CASES)

# A real single-node Slurm cluster; skips when not root.
test-slurm:  ## references from a real Slurm job array equal the local ones, byte for byte
	$(Q)sh course/references/slurm_test.sh

# ---- mutants: realistic student bugs, kept as patches of the solution ---------------------------
mutants: all  ## each catalogued student bug is caught by its own part's suite
	@course/mutants/run.sh

trace-mutants: all $(BIN)/strip_solutions $(BIN)/grade  ## each --trace-pixel mark is triggered by a catalogued bug, and none fires on the solution
	@course/mutants/trace.sh

# Slow: one graded submission per mutant.
grade-mutants: $(BIN)/grade $(BIN)/pathtracer  ## grade each catalogued bug: it must lose points on its own part only
	$(Q)sh course/mutants/grade.sh

# ---- calibration: each suite's false-failure rate over fresh seeds, and the grader's ------------
N ?= 200
ALT_SEEDS ?= 3
GRADE_RUNS ?= 200
CALIBRATE_SUITES ?= $(filter-out course,$(SUITES))
calibrate: $(addprefix $(BIN)/test-,$(CALIBRATE_SUITES)) $(BIN)/pathtracer $(BIN)/grade  ## suites' false-failure rates (N=200 seeds), then every correct alternative graded (ALT_SEEDS=3)
	$(Q)BIN=$(BIN) course/calibrate $(N) $(CALIBRATE_SUITES)
	$(Q)ALT_SEEDS=$(ALT_SEEDS) sh course/alternatives/grade.sh

# Slow (one graded submission per alternative and seed): each must get full marks every time.
calibrate-alternatives: $(BIN)/grade $(BIN)/pathtracer  ## grade every correct alternative in course/alternatives at ALT_SEEDS=3 fresh seeds
	$(Q)ALT_SEEDS=$(ALT_SEEDS) sh course/alternatives/grade.sh

# Slow (grading/CALIBRATION.md has the figures and their cost): the solution's false failures per case.
calibrate-grader: $(BIN)/grade $(BIN)/pathtracer  ## grade the solution GRADE_RUNS=200 times per case at fresh seeds (PARTS=3, CASES=a,b)
	$(Q)$(BIN)/grade --calibrate $(GRADE_RUNS) --out build/calibrate-grader $(if $(PARTS),--parts $(PARTS)) $(if $(CASES),--cases $(CASES))

# ---- the grader's speed: a correct submission graded whole (5 isolated builds, suites, every case) --
# Part of make bench (bench/bench.mk) where the tree has course/: a student tree has no solution.
.PHONY: bench-grade
bench-grade: $(BIN)/grade  ## time to grade the solution as a submission, all five parts
	@echo "== grading the solution as a submission (5 isolated builds, suites, all cases)"
	@rm -rf build/bench-grade && mkdir -p build/bench-grade/sub && cp -a parts build/bench-grade/sub/
	@/usr/bin/time -f "graded in %e s wall, %U s user" $(BIN)/grade --submission build/bench-grade/sub \
	    --out build/bench-grade/out --seed 1 | tail -n 4

# A student's everyday loop: a file copied in with an old date is rebuilt; CC=clang never meets gcc's objects.
.PHONY: test-fresh-build
test-fresh-build:  ## builds follow content and compiler: a part dated in the past is rebuilt, CC=clang after gcc links
	$(Q)sh course/platform/fresh_build.sh

# ---- a whole class graded (course/class/README.md): locally or as a Slurm job array ---------------
# bin/grade-class links libarchive (zip and folder reading) and libcrypto (the seeds' HMAC), which
# the student never needs: `make grade-class` and `make test-grade-class` install them (as root,
# Debian's libarchive-dev and libssl-dev) before building it (course/class/need.sh).
CLASS_OBJ := $(patsubst %.c,$(BUILD)/%.o,$(filter-out course/class/test_%,$(wildcard course/class/*.c))) $(COURSE_SHARED_OBJ) \
             $(BUILD)/grader/grade_spec.o $(BUILD)/grader/grade_plan.o $(BUILD)/grader/grade_run.o \
             $(BUILD)/grader/grade_fmt.o $(BUILD)/grader/sandbox_$(SANDBOX_IMPL).o $(LIB_OBJ)
CLASS_LIBS = $(shell pkg-config --libs libarchive libcrypto)
$(BUILD)/course/class/%.o: CPPFLAGS += $(shell pkg-config --cflags libarchive libcrypto 2>/dev/null)
$(BIN)/grade-class: $(CLASS_OBJ)
	$(say) LD $@
	@mkdir -p $(dir $@)
	$(Q)$(CC) $(LDFLAGS) -o $@ $^ $(LDLIBS) $(GRADER_LIBS) $(CLASS_LIBS)
# nftw (removing a grading's folders without following links) is an X/Open interface.
$(BUILD)/course/class/class_unit.o: FEATURES += -D_XOPEN_SOURCE=700
class_comma := ,
class_space := $(subst ,, )
CLASS_PARTS = $(or $(PARTS),$(subst $(class_space),$(class_comma),$(strip $(COURSE_PARTS))))
.PHONY: grade-class test-grade-class
## grade-class SUBMISSIONS=DIR OUT=DIR: grade every submission of DIR (a folder or .zip each) into OUT/gradebook.csv and OUT/report/ (ROSTER=, SECRET=, PARTS=1,2, JOBS=, SLURM=1 SBATCH="...")
grade-class:
	$(Q)sh course/class/need.sh
	$(Q)$(MAKE) --no-print-directory $(BIN)/grade-class $(BIN)/grade $(BIN)/pathtracer
	$(Q)$(BIN)/grade-class --submissions '$(SUBMISSIONS)' --out '$(OUT)' --parts $(CLASS_PARTS) $(if $(ROSTER),--roster '$(ROSTER)') \
	    $(if $(SECRET),--secret '$(SECRET)') $(if $(JOBS),--jobs $(JOBS)) $(if $(SLURM),--slurm $(if $(SBATCH),--sbatch '$(SBATCH)'))

# A small class (the solution, catalogued bugs and alternatives, hostile submissions) graded locally,
# killed half way and resumed, re-graded after a case changed, on a real Slurm cluster, and its
# report read in headless Chromium; as root (the sandbox, the cluster). About 4 minutes.
test-grade-class:  ## the class grader end to end: resume, re-grade, Slurm equal to local byte for byte, the report in Chromium
	$(Q)sh course/class/need.sh
	$(Q)$(MAKE) --no-print-directory $(BIN)/grade-class $(BIN)/grade $(BIN)/pathtracer
	$(Q)bash course/class/test.sh

/* Grader machinery: not part of any assignment.
 * The build stage of a submission: the pipeline's first untrusted stage. Whatever a build runs,
 * names or writes while it reads student files is not trusted afterwards, so:
 *
 *   compile    each .c alone, with one fixed argument vector (the course's flags, from the recipes
 *              the course's own make wrote: the plan holds it), as the sandbox's user, under limits,
 *              in a scratch folder that holds the part's files and the framework's and parts' headers
 *              and nothing else: no other part's sources or objects, no build folder. In a mount
 *              namespace it sees the machine read-only but for its output folder, with its own /tmp
 *              and a /dev of three devices (grade_run.c); everywhere, nothing secret is readable by its
 *              user. It stops at the first file that fails.
 *   take out   only <name>.o and <name>.d for each submitted <name>.c come out, regular files under
 *              the size limit, copied by the grader into a tree the sandbox's user cannot write.
 *   inspect    the objects against the allow-list (grade_inspect.c) before anything reads them as
 *              a program: machine code only, the symbols a part may use, no constructor.
 *   link       as the grader, bounded, from the course's prebuilt objects of everything else (the
 *              framework's always: a submission cannot change a framework object) and those objects.
 *
 * The manifest (grade_manifest.c, the spec stage) read the folder as data first, and the plan
 * (grade_plan.c) made every path and command used here. The build returns its facts: built or not,
 * why not, and the compiler's lines about the student's own files. */
#include "grade_build.h"
#include "grade_diag.h"
#include "grade_inspect.h"
#include "grade_run.h"
#include "grade_tree.h"
#include "../framework/file.h"
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- files between the trees --------------------------------------------------------------- */

/* Copies from/name to to/name through the grader (a regular file, at most max bytes), 0644. */
static bool copy_file(const char *from, const char *to, const char *name, long max)
{
    grade_path_buf src, dst;
    char *data = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    bool ok = grade_join(from, name, src, sizeof src) && grade_join(to, name, dst, sizeof dst) &&
              file_read_all(src, name, (size_t)max, &data, &len, &diag) == PL_OK &&
              file_write_atomic(dst, data, len, &diag) == PL_OK && chmod(dst, 0644) == 0;
    free(data);
    return ok;
}

/* Every header of from (a course folder) into to, made when missing. */
static bool copy_headers(const grade_plan_copy *c)
{
    DIR *d = opendir(c->from);
    bool ok = d && (mkdir(c->to, 0755) == 0 || errno == EEXIST);
    for (struct dirent *e; ok && (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n > 2 && !strcmp(e->d_name + n - 2, ".h")) ok = copy_file(c->from, c->to, e->d_name, GRADE_SOURCE_BYTES);
    }
    if (d) closedir(d);
    return ok;
}

static bool run_trusted(char *const argv[], const char *log)
{
    grade_run_opts o = {.wall_seconds = GRADE_LINK_SECONDS, .log_path = log, .log_max = GRADE_LOG_MAX};
    grade_run_result rr = grade_run(argv, &o);
    return rr.exited && rr.status == 0;
}

/* The compile's source folder: the framework's headers, every part's headers, and the submitted
 * files of the part, the course's headers over any of the same name (the contract is the course's).
 * Root's, readable by the sandbox's user; the output folder the sandbox user's own. */
static bool lay_out_sources(const grade_plan *plan, const grade_manifest *m, const grade_sandbox *sandbox)
{
    grade_tree_remove(plan->scratch);
    bool ok = mkdir(plan->scratch, 0755) == 0 && mkdir(plan->scratch_src, 0755) == 0 && mkdir(plan->scratch_parts, 0755) == 0;
    for (int k = 0; ok && k < plan->num_header_dirs; k++) ok = copy_headers(&plan->header_dirs[k]);
    ok = ok && (mkdir(plan->scratch_part, 0755) == 0 || errno == EEXIST);
    for (int i = 0; ok && i < m->count; i++) ok = copy_file(plan->submitted, plan->scratch_part, m->names[i], GRADE_SOURCE_BYTES);
    return ok && mkdir(plan->scratch_out, 0700) == 0 &&
           (!sandbox->as_other_user || chown(plan->scratch_out, sandbox->uid, sandbox->gid) == 0);
}

/* The part's tree from the course's built tree: what its suite and renders read at run time
 * (framework, tests, scenes, ...) and the course's objects, less the part's; every part's headers
 * (the course's); the other parts' object folders closed to everyone but the grader. */
static bool lay_out_tree(const grade_plan *plan)
{
    grade_tree_remove(plan->tree);
    char *mk[] = {"mkdir", "-p", (char *)plan->tree_bin, NULL};
    bool ok = run_trusted(mk, NULL);
    for (int k = 0; ok && k < plan->num_tree_pieces; k++) {
        struct stat st;
        char *cp[] = {"cp", "-a", (char *)plan->tree_pieces[k].from, (char *)plan->tree, NULL};
        if (stat(plan->tree_pieces[k].from, &st) == 0) ok = run_trusted(cp, plan->tree_log);
    }
    for (int k = 0; ok && k < plan->num_tree_headers; k++) {
        char *mkp[] = {"mkdir", "-p", (char *)plan->tree_headers[k].to, NULL};
        ok = run_trusted(mkp, NULL) && copy_headers(&plan->tree_headers[k]);
    }
    /* The part's objects are the submission's, and only they: the course's go. */
    char *rm[] = {"rm", "-rf", (char *)plan->objects, NULL}, *mko[] = {"mkdir", "-p", (char *)plan->objects, NULL};
    ok = ok && run_trusted(rm, NULL) && run_trusted(mko, NULL);
    for (int k = 0; ok && k < plan->num_other_objects; k++)
        ok = chmod(plan->other_objects[k], 0700) == 0 || errno == ENOENT;
    return ok;
}

/* ---- compile and link ------------------------------------------------------------------------ */

/* Whether the compiler's log says it ran out of memory (cc1 reports it; the kernel's kill is a signal). */
static bool out_of_memory(const char *log)
{
    char tail[4096];
    grade_log_tail(log, 20, tail, sizeof tail);
    return strstr(tail, "out of memory") || strstr(tail, "memory exhausted") || strstr(tail, "Killed signal");
}

/* Why a step failed, as a fact: the deadline, its own limit, its output, its memory, or the code. */
static grade_why step_failed(const grade_run_result *rr, grade_step step, const char *file, double limit, const char *log)
{
    grade_why w = grade_why_of(rr->out_of_time ? GRADE_WHY_BUILD_OUT_OF_TIME
                               : rr->timed_out ? GRADE_WHY_BUILD_TIMED_OUT
                               : rr->output_cut ? GRADE_WHY_BUILD_OUTPUT
                               : out_of_memory(log) || !rr->exited ? GRADE_WHY_BUILD_MEMORY : GRADE_WHY_BUILD_FAILS);
    w.step = step;
    w.limit = (long)limit;
    w.run = *rr;
    snprintf(w.file, sizeof w.file, "%s", file ? file : "");
    return w;
}

/* Appends the file at from to the one at to (the build log the diagnostics are read from). */
static void append_log(const char *from, const char *to)
{
    char *data = NULL;
    size_t len = 0;
    pl_diag diag = pl_diag_default();
    FILE *f = file_read_all(from, "log", GRADE_LOG_MAX + 64, &data, &len, &diag) == PL_OK ? fopen(to, "ab") : NULL;
    if (f) fwrite(data, 1, len, f), fclose(f);
    free(data);
}

/* Each submitted .c compiled alone, confined, two at a time, stopping at the first that fails;
 * false with why (the first file that failed, in the manifest's order). */
static bool compile_all(const grade_plan *plan, const grade_sandbox *sandbox, grade_why *why)
{
    char *const *argvs[GRADE_SOURCE_FILES];
    grade_run_opts opts[GRADE_SOURCE_FILES];
    grade_run_result results[GRADE_SOURCE_FILES];
    char *envv[] = {(char *)plan->tmpdir_env, NULL};
    for (int k = 0; k < plan->num_sources; k++) {
        argvs[k] = plan->sources[k].compile.argv;
        opts[k] = (grade_run_opts){.wall_seconds = GRADE_COMPILE_SECONDS, .deadline = plan->deadline,
                                   .cwd = plan->scratch_src, .log_path = plan->sources[k].log, .log_max = GRADE_LOG_MAX,
                                   .env = envv, .untrusted = true, .compiler = true, .writable = plan->scratch_out,
                                   .sandbox = sandbox};
    }
    grade_run_jobs(plan->num_sources, argvs, opts, results, true);
    for (int k = 0; k < plan->num_sources; k++) {
        append_log(plan->sources[k].log, plan->build_log);
        if (!results[k].exited || results[k].status != 0) {
            *why = step_failed(&results[k], GRADE_STEP_COMPILE, plan->sources[k].name, GRADE_COMPILE_SECONDS,
                               plan->sources[k].log);
            return false;
        }
    }
    return true;
}

/* Takes <name>.o and <name>.d of each submitted .c out of the compile's folder into the tree's object
 * folder: regular files only (the compile's user may have left links), under the file limit. */
static bool take_objects(const grade_plan *plan, grade_why *why)
{
    for (int i = 0; i < plan->num_sources; i++) {
        const grade_plan_source *s = &plan->sources[i];
        const char *made[2] = {s->compiled_obj, s->compiled_dep}, *kept[2] = {s->obj, s->dep};
        for (int k = 0; k < 2; k++) {
            struct stat st;
            char *data = NULL;
            size_t len = 0;
            pl_diag diag = pl_diag_default();
            bool ok = lstat(made[k], &st) == 0 && S_ISREG(st.st_mode) &&
                      file_read_all(made[k], "object", GRADE_FILE_BYTES, &data, &len, &diag) == PL_OK &&
                      file_write_atomic(kept[k], data, len, &diag) == PL_OK && chmod(kept[k], 0644) == 0;
            free(data);
            if (!ok) {
                *why = grade_why_of(GRADE_WHY_NO_OBJECT);
                snprintf(why->file, sizeof why->file, "%s", s->name);
                return false;
            }
        }
    }
    return true;
}

/* The renderer and the split suite's subject, linked side by side in the tree as the grader,
 * bounded (the linker reads objects a confined compiler wrote); false with why. */
static bool link_all(const grade_plan *plan, grade_why *why)
{
    static const grade_step steps[GRADE_PLAN_LINKS] = {GRADE_STEP_LINK_RENDERER, GRADE_STEP_LINK_SUITE};
    char *const *argvs[GRADE_PLAN_LINKS];
    grade_run_opts opts[GRADE_PLAN_LINKS];
    grade_run_result results[GRADE_PLAN_LINKS];
    for (int k = 0; k < GRADE_PLAN_LINKS; k++) {
        argvs[k] = plan->links[k].link.argv;
        opts[k] = (grade_run_opts){.wall_seconds = GRADE_LINK_SECONDS, .deadline = plan->deadline, .cwd = plan->tree,
                                   .log_path = plan->links[k].log, .log_max = GRADE_LOG_MAX, .bounded = true};
    }
    grade_run_jobs(GRADE_PLAN_LINKS, argvs, opts, results, false);
    for (int k = 0; k < GRADE_PLAN_LINKS; k++) {
        append_log(plan->links[k].log, plan->build_log);
        if (!results[k].exited || results[k].status != 0) {
            *why = step_failed(&results[k], steps[k], NULL, GRADE_LINK_SECONDS, plan->links[k].log);
            return false;
        }
    }
    return true;
}

/* A layout the grader could not make: its own problem, never the student's. */
static bool grader_problem(grade_why *why, const char *what)
{
    *why = grade_why_of(GRADE_WHY_GRADER);
    snprintf(why->detail, sizeof why->detail, "%s", what);
    return false;
}

void grade_build_submission(const grade_plan *plan, const grade_manifest *m, const grade_sandbox *sandbox,
                            grade_build_facts *out)
{
    memset(out, 0, sizeof *out);
    unlink(plan->build_log);
    grade_why *why = &out->why;
    /* The compile: a scratch folder of headers and the submitted files, an output folder of the
     * sandbox user's own; nothing else of the grading is there. */
    bool ok = lay_out_sources(plan, m, sandbox) || grader_problem(why, "cannot lay out the compile's folder");
    ok = ok && compile_all(plan, sandbox, why);
    /* The tree: the course's pieces, then the objects the compile made, then the link. */
    ok = ok && (lay_out_tree(plan) || grader_problem(why, "cannot lay out the part's tree"));
    ok = ok && take_objects(plan, why);
    grade_tree_remove(plan->scratch);  /* nothing the compile wrote stays */
    for (int i = 0; ok && i < plan->num_sources; i++)  /* the sources, beside their objects */
        ok = copy_file(plan->submitted, plan->tree_sources, plan->sources[i].name, GRADE_SOURCE_BYTES) ||
             grader_problem(why, "cannot copy the part's sources into its tree");
    /* The objects against the allow-list, before the linker reads them as the grader. */
    ok = ok && grade_inspect_part(plan, sandbox, why);
    ok = ok && link_all(plan, why);
    out->built = ok;
    if (!ok) grade_diagnostics(plan->build_log, plan->folder, GRADE_DIAG_LINES, out->diagnostics, sizeof out->diagnostics);
}

void grade_build_own_tree(const grade_plan *plan, grade_build_facts *out)
{
    memset(out, 0, sizeof *out);
    grade_run_opts o = {.wall_seconds = GRADE_COURSE_BUILD_SECONDS, .deadline = plan->deadline,
                        .log_path = plan->build_log, .log_max = GRADE_LOG_MAX};
    grade_run_result rr = grade_run(plan->own_build.argv, &o);
    out->built = rr.exited && rr.status == 0;
    if (out->built) return;
    out->why = grade_why_of(GRADE_WHY_OWN_BUILD);
    out->why.run = rr;
    grade_diagnostics(plan->build_log, plan->folder, GRADE_DIAG_LINES, out->diagnostics, sizeof out->diagnostics);
}

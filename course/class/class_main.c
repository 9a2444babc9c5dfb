/* Instructor tooling: not part of any assignment.
 * bin/grade-class: grades every submission of a folder as the autograder grades one, into a grade
 * book and a class report (course/class/README.md). Run as root from the course's root (bin/grade's
 * sandbox runs student code as `nobody`), after `make bin/grade bin/pathtracer`.
 *
 *   bin/grade-class --submissions DIR --out DIR [--roster FILE] [--secret FILE] [--parts 1,2,3]
 *                   [--jobs N] [--threads N] [--timeout S] [--force] [--slurm [--sbatch "ARGS"]]
 *   bin/grade-class --report-only ...   the grade book and report from the records (the Slurm array's
 *                                       final job; also after a run was stopped)
 *   bin/grade-class --task I:KEY ...    one Slurm array task: student I of the folder (KEY: its name's)
 *
 * OUT holds gradebook.csv, report/index.html, students/STUDENT/ (record.json and one folder per
 * graded part) and work/ (staging and gradings in progress). One run at a time per OUT (a lock). */
#include "class.h"
#include "../shared/key.h"
#include "../shared/slurm.h"
#include "../../grader/grade_plan.h"
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <locale.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static int usage(const char *why)
{
    fprintf(stderr, "grade-class: %s\nusage: grade-class --submissions DIR --out DIR [--roster FILE] [--secret FILE] "
                    "[--parts 1,2,3] [--jobs N] [--threads N] [--timeout S] [--force] [--slurm [--sbatch \"ARGS\"]]\n"
                    "       grade-class --report-only | --task I:KEY  (the same options)\n", why);
    return 2;
}

/* ---- the options ------------------------------------------------------------------------------ */

/* Gradings at once: one a core, as many as the memory holds (CLASS_MEMORY_PER_GRADING each). */
static int default_jobs(void)
{
    long cores = sysconf(_SC_NPROCESSORS_ONLN), pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    long by_memory = pages > 0 && page > 0 ? (long)((double)pages * page / CLASS_MEMORY_PER_GRADING) : cores;
    long jobs = cores < by_memory ? cores : by_memory;
    return jobs < 1 ? 1 : jobs > 64 ? 64 : (int)jobs;
}

/* The course's parts: each with a folder parts/part<N>_* and cases in grading/cases.json. */
static void course_parts(char *out, size_t size)
{
    grade_spec spec;
    pl_diag diag = pl_diag_default();
    size_t n = 0;
    out[0] = '\0';
    if (grade_spec_load(GRADE_CASES, NULL, &spec, &diag) != PL_OK) return;
    for (int k = 1; k <= GRADE_MAX_PART && n + 3 < size; k++) {
        char folder[256];
        if (spec.parts[k - 1].part == k && grade_plan_part_folder(".", k, folder, sizeof folder))
            n += (size_t)snprintf(out + n, size - n, "%s%d", n ? "," : "", k);
    }
    grade_spec_free(&spec);
}

static const char *parse_parts(const char *v, char *out, size_t size)
{
    size_t n = 0;
    for (const char *c = v; *c; c++) {
        if (*c == ',') continue;
        if (*c < '1' || *c > '9' || (c[1] && c[1] != ',') || n + 3 > size) return "--parts: expected part numbers such as 1,3";
        n += (size_t)snprintf(out + n, size - n, "%s%c", n ? "," : "", *c);
    }
    return n ? NULL : "--parts: no part given";
}

static const char *parse_args(int argc, char **argv, class_options *o, char *secret, size_t size)
{
    /* Defaults: the secret in the user's configuration, one grading a core, the class deadline. */
    const char *home = getenv("HOME");
    snprintf(secret, size, "%s/.config/pathlab/class-secret", home ? home : "/root");
    *o = (class_options){.secret = secret, .jobs = default_jobs(), .timeout = CLASS_TIMEOUT, .sbatch_args = ""};
    const char *bad = NULL;
    for (int i = 1; i < argc && !bad; i++) {
        const char *f = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(f, "--slurm")) o->slurm = true;
        else if (!strcmp(f, "--report-only")) o->report_only = true;
        else if (!strcmp(f, "--force")) o->force = true;
        else if (!v) bad = "an option without its value";
        else if (i++, !strcmp(f, "--submissions")) o->submissions = v;
        else if (!strcmp(f, "--out")) o->out = v;
        else if (!strcmp(f, "--roster")) o->roster = v;
        else if (!strcmp(f, "--secret")) o->secret = v;
        else if (!strcmp(f, "--parts")) bad = parse_parts(v, o->parts, sizeof o->parts);
        else if (!strcmp(f, "--jobs")) o->jobs = atoi(v);
        else if (!strcmp(f, "--threads")) o->threads = atoi(v);
        else if (!strcmp(f, "--timeout")) o->timeout = atoi(v);
        else if (!strcmp(f, "--sbatch")) o->sbatch_args = v;
        else if (!strcmp(f, "--task")) o->task = v;
        else bad = "unknown option";
    }
    /* Checks once every option is read: the folders, the ranges, the parts. */
    if (bad) return bad;
    if (!o->submissions || !o->out) return "--submissions and --out are required";
    if (o->jobs < 1 || o->jobs > 64 || o->threads < 0 || o->threads > 64 || o->timeout < 1) return "--jobs, --threads or --timeout out of range";
    if (o->task) o->jobs = 1;  /* a Slurm task grades its student's parts one after another */
    /* Render threads: the cores a grading has to itself (a Slurm task: bin/grade's default, 2). */
    int share = (int)(sysconf(_SC_NPROCESSORS_ONLN) / o->jobs);
    if (!o->threads) o->threads = o->task ? 2 : share > 0 ? share : 1;
    if (!o->parts[0]) course_parts(o->parts, sizeof o->parts);
    return o->parts[0] ? NULL : "this tree has no part with cases (run from the course's root)";
}

/* ---- the output folder -------------------------------------------------------------------------- */

static bool make_dir(const char *path) { return mkdir(path, 0755) == 0 || errno == EEXIST; }

/* One run per OUT at a time: a lock on OUT/work/lock, released when this process ends however it
 * ends. Slurm tasks take none (each writes only its own student's files). */
static bool lock_out(const char *work)
{
    char path[1300];
    snprintf(path, sizeof path, "%s/lock", work);
    int fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    struct flock l = {.l_type = F_WRLCK, .l_whence = SEEK_SET};
    if (fd >= 0 && fcntl(fd, F_SETLK, &l) == 0) return true;  /* fd stays open: the lock lives with us */
    fprintf(stderr, "grade-class: another grade-class runs on this --out (%s is locked)\n", path);
    return false;
}

/* Removes what a run on this host left in dir ("HOST.PID.*" names) when that process is gone. */
static void remove_leftovers(const char *dir, const char *host)
{
    DIR *d = opendir(dir);
    size_t len = strlen(host);
    for (struct dirent *e; d && (e = readdir(d));) {
        if (strncmp(e->d_name, host, len) || e->d_name[len] != '.') continue;
        long pid = strtol(e->d_name + len + 1, NULL, 10);
        char path[1600];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (pid > 0 && pid != getpid() && kill((pid_t)pid, 0) != 0 && errno == ESRCH) class_remove_tree(path);
    }
    if (d) closedir(d);
}

/* OUT, OUT/students, OUT/work (root's alone: submissions are staged there), its units/ and stage/,
 * this process's staging folder, and what an earlier run on this host left behind. */
static bool open_out(class_run *r)
{
    char host[64] = "host", path[1300];
    gethostname(host, sizeof host - 1);
    host[strcspn(host, "./")] = '\0';
    snprintf(r->work, sizeof r->work, "%s/work", r->o->out);
    snprintf(path, sizeof path, "%s/students", r->o->out);
    bool ok = make_dir(r->o->out) && make_dir(path) && make_dir(r->work) && chmod(r->work, 0700) == 0;
    snprintf(path, sizeof path, "%s/units", r->work);
    ok = ok && make_dir(path);
    if (ok && !r->o->task) remove_leftovers(path, host);
    snprintf(path, sizeof path, "%s/stage", r->work);
    ok = ok && make_dir(path);
    if (ok && !r->o->task) remove_leftovers(path, host);
    snprintf(r->stage, sizeof r->stage, "%s/%s.%d", path, host, (int)getpid());
    if (!ok || !make_dir(r->stage)) fprintf(stderr, "grade-class: cannot create the folders of %s\n", r->o->out);
    return ok && (r->o->task || lock_out(r->work));
}

/* ---- the students ---------------------------------------------------------------------------------- */

/* Stages student i (its part folders in STAGE/STUDENT), keys its units and reads its record. */
static void prepare(class_run *r, int i)
{
    class_student *s = &r->students[i];
    char dest[1400];
    snprintf(dest, sizeof dest, "%s/%s", r->stage, s->folder);
    class_unpack(r, s, dest);
    if (strcmp(s->status, "ok")) return;
    for (const char *c = r->o->parts; *c; c++)
        if (*c >= '1' && *c <= '9') s->units[s->num_units++].part = *c - '0';
    class_key_units(r, s, dest);
    if (!r->o->force || r->o->report_only) class_record_read(r, s);  /* --force: grade again, never report nothing */
}

/* --task I:KEY: the student at index I, whose submission's name has key KEY; -1 when the folder
 * changed since the array was submitted (then nothing is graded: the instructor submits again). */
static int task_student(const class_run *r)
{
    char *end;
    long i = strtol(r->o->task, &end, 10);
    char hex[17];
    if (*end != ':' || i < 0 || i >= r->num_students) return -1;
    key_hex(key_str(KEY_START, r->students[i].entry), hex);
    return strcmp(hex, end + 1) ? -1 : (int)i;
}

/* Whether a student is graded and has a part that is not current. */
static bool has_todo(const class_student *s)
{
    bool todo = false;
    for (int u = 0; u < s->num_units; u++) todo |= !s->units[u].current;
    return todo && !strcmp(s->status, "ok");
}

/* ---- Slurm: one array task per student with a part to grade, the report once they all ended ---- */

/* argv of this command with the mode's flags replaced by `mode` (and its value). */
static void command_for(int argc, char **argv, const char *mode, const char *value, char **out)
{
    /* The task runs this very command but for its mode: the same folders, secret, parts, deadline,
     * --force (--jobs goes: a task grades its parts one after another). */
    int n = 0;
    out[n++] = "bin/grade-class";
    out[n++] = (char *)mode;
    if (value) out[n++] = (char *)value;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--slurm")) continue;
        if (!strcmp(argv[i], "--sbatch") || !strcmp(argv[i], "--jobs")) { i++; continue; }
        out[n++] = argv[i];
    }
    out[n] = NULL;
}

static int submit_slurm(class_run *r, int argc, char **argv)
{
    char dir[1300], task[64];
    char **cmd = calloc((size_t)argc + 6, sizeof *cmd);
    slurm_array array;
    snprintf(dir, sizeof dir, "%s/slurm", r->work);
    if (!cmd || !slurm_begin(&array, dir)) return free(cmd), 1;
    /* One task a student with a part to grade, named by index and by its name's key. */
    for (int i = 0; i < r->num_students; i++) {
        const class_student *s = &r->students[i];
        if (!has_todo(s)) continue;
        char hex[17];
        key_hex(key_str(KEY_START, s->entry), hex);
        snprintf(task, sizeof task, "%d:%s", i, hex);
        command_for(argc, argv, "--task", task, cmd);
        if (!slurm_add(&array, cmd)) return free(cmd), 1;
    }
    command_for(argc, argv, "--report-only", NULL, cmd);
    slurm_ids ids;
    bool ok = slurm_submit(&array, "pl-class", cmd, "pl-class-report", r->o->sbatch_args, &ids);
    free(cmd);
    if (!ok) return 1;
    printf("submitted %d student(s) as job array %s, and the grade book and report as job %s\n", array.count,
           ids.array_id[0] ? ids.array_id : "(none)", ids.final_id);
    return 0;
}

/* The course's objects built once before any grading (bin/grade --prebuild, as the autograder's
 * setup.sh does): each grading then copies them instead of building the course again (~6 s a part). */
static bool prebuild(const class_run *r)
{
    char log[1300];
    snprintf(log, sizeof log, "%s/prebuild.log", r->work);
    char *argv[] = {"bin/grade", "--prebuild", NULL};
    grade_run_opts o = {.wall_seconds = GRADE_COURSE_BUILD_SECONDS, .log_path = log, .log_max = GRADE_LOG_MAX};
    grade_run_result rr = grade_run(argv, &o);
    if (!rr.exited || rr.status != 0) fprintf(stderr, "grade-class: bin/grade --prebuild failed (the course's build): see %s\n", log);
    return rr.exited && rr.status == 0;
}

/* ---- main ------------------------------------------------------------------------------------------ */

/* What a run ends with: the grade book and the class report, from every student's record. */
static int write_outputs(const class_run *r)
{
    if (!class_book_write(r) || !class_report_write(r)) return 1;
    printf("grade-class: wrote %s/gradebook.csv and %s/report/index.html\n", r->o->out, r->o->out);
    return 0;
}

/* Students with a part to grade. */
static int todo_count(const class_run *r)
{
    int n = 0;
    for (int i = 0; i < r->num_students; i++) n += has_todo(&r->students[i]);
    return n;
}

/* Counts for the first line: students to grade, up to date, refused. */
static void announce(const class_run *r)
{
    int todo = 0, current = 0, refused = 0;
    for (int i = 0; i < r->num_students; i++) {
        const class_student *s = &r->students[i];
        bool all = true;
        for (int u = 0; u < s->num_units; u++) all &= s->units[u].current;
        if (strcmp(s->status, "ok")) refused++;
        else if (all) current++;
        else todo++;
    }
    fprintf(stderr, "grade-class: %d submission(s): %d to grade, %d up to date, %d not graded (see the report); parts %s\n",
            r->num_students, todo, current, refused, r->o->parts);
}

static int run(class_run *r, int argc, char **argv)
{
    if (access("bin/grade", X_OK) != 0 || access(GRADE_CASES, R_OK) != 0)
        return usage("run from the course's root, after make bin/grade bin/pathtracer");
    if (!open_out(r) || !class_intake(r) || !class_seed_all(r) || !class_key_course(r)) return 2;
    /* A Slurm task: its one student, staged and keyed here on the node, graded as a local run would. */
    if (r->o->task) {
        r->only = task_student(r);
        if (r->only < 0) return fprintf(stderr, "grade-class: --task %s: the submissions folder changed since the "
                                                "array was submitted; submit again\n", r->o->task), 1;
        prepare(r, r->only);
        return class_pool_run(r) ? 0 : 1;
    }
    /* Every submission staged and keyed: which parts are current is known before anything runs. */
    for (int i = 0; i < r->num_students; i++) prepare(r, i);
    /* A student whose parts were all there when a run was stopped: their record, now. */
    for (int i = 0; i < r->num_students; i++)
        if (!strcmp(r->students[i].status, "ok") && class_record_complete(&r->students[i])) class_record_write(r, &r->students[i]);
    announce(r);
    if (r->o->report_only) return write_outputs(r);
    if (todo_count(r) && !prebuild(r)) return 1;
    if (r->o->slurm) return submit_slurm(r, argc, argv);
    bool graded = class_pool_run(r);
    int code = write_outputs(r);
    return graded ? code : 1;
}

int main(int argc, char **argv)
{
    /* Zip entry names flagged UTF-8 reach us as they are only in a UTF-8 locale (libarchive converts
     * names to the locale's charset); other names pass as raw bytes either way, shown escaped. */
    if (!setlocale(LC_CTYPE, "C.UTF-8")) setlocale(LC_CTYPE, "en_US.UTF-8");
    static char secret[1024];
    class_options o;
    const char *bad = parse_args(argc, argv, &o, secret, sizeof secret);
    if (bad) return usage(bad);
    class_run r = {.o = &o, .only = -1};
    int code = run(&r, argc, argv);
    if (r.stage[0]) class_remove_tree(r.stage);
    free(r.students);
    return code;
}

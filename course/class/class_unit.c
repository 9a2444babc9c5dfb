/* Instructor tooling: not part of any assignment.
 * A unit: part P of one student, graded by the autograder's own command,
 *   bin/grade --submission STAGE --out TMP --parts P --seed SEED --threads T
 * as root, with the sandbox (the staging folder holds the part folders as run_autograder copies
 * them; class_unpack.c). It runs in a folder of this process's (work/units/HOST.PID.STUDENT.partP)
 * and becomes students/STUDENT/partP-KEY by one rename when it ended, so a unit is there whole or
 * not at all; the student's record, written once all their units are there, is what makes it count
 * (class_record.c). What a unit keeps: results.json and report/ (the student's, as the autograder
 * makes them), facts.json (staff only: what the class report is made from), grade.log (bin/grade's
 * own lines); the grader's scratch (work/, ~60 MB) is removed.
 * Outcomes: graded (bin/grade's facts.json, whatever the score); timed_out (over --timeout: the
 * grading is stopped, the part scores 0, as run_autograder does when the platform's time runs out);
 * grader_failed (bin/grade ended without its facts: graded again on the next run). bin/grade's exit
 * status 2 or 3 is the course's own problem (its cases, references or set-up), and so is a bin/grade
 * that could not be run (126, 127: rebuilt or removed meanwhile): the class run stops there, and no
 * student is given anything for it. */
#include "class.h"
#include "../../framework/file.h"
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <jansson.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#define UNIT_LOG_BYTES (64L << 20)  /* bin/grade's own output: a table and a line a stage, ~10 KB */

static int remove_one(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st, (void)flag, (void)ftw;
    remove(path);
    return 0;
}

void class_remove_tree(const char *path)
{
    nftw(path, remove_one, 16, FTW_DEPTH | FTW_PHYS);  /* FTW_PHYS: a link is removed, never followed */
}

void class_unit_folder(const class_run *r, const class_student *s, const class_unit *u, char *out, size_t size)
{
    snprintf(out, size, "%s/students/%s/part%d-%s", r->o->out, s->folder, u->part, u->key);
}

/* The child: its own process group (the pool stops it whole), stopped with this process (Linux:
 * a class run killed outright takes its gradings with it, and their janitors clean up), its
 * output to the log. Never returns. */
static void child_exec(char *const argv[], const char *log, pid_t parent)
{
    setpgid(0, 0);
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(126);  /* the class run died before the line above: no grading */
#endif
    struct rlimit fsize = {UNIT_LOG_BYTES, UNIT_LOG_BYTES};
    int in = open("/dev/null", O_RDONLY), out = open(log, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (in < 0 || out < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(out, 2) < 0) _exit(126);
    setrlimit(RLIMIT_FSIZE, &fsize);
    execv(argv[0], argv);
    _exit(127);
}

bool class_unit_start(const class_run *r, const class_student *s, int u, const char *stage, class_job *job)
{
    /* The folder is named by host and process: Slurm tasks on several nodes share OUT, and a later
     * run on this host removes what a dead process left (class_main.c). */
    char host[64] = "host", seed[32], part[8], threads[8], log[1500];
    gethostname(host, sizeof host - 1);
    host[strcspn(host, "./")] = '\0';
    snprintf(job->tmp, sizeof job->tmp, "%s/units/%s.%d.%s.part%d", r->work, host, (int)getpid(), s->folder, s->units[u].part);
    snprintf(log, sizeof log, "%s.log", job->tmp);
    snprintf(seed, sizeof seed, "%llu", (unsigned long long)s->seed);
    snprintf(part, sizeof part, "%d", s->units[u].part);
    snprintf(threads, sizeof threads, "%d", r->o->threads);
    class_remove_tree(job->tmp);
    char *argv[] = {"bin/grade", "--submission", (char *)stage, "--out", job->tmp, "--parts", part,
                    "--seed", seed, "--threads", threads, NULL};
    /* Nothing buffered is written twice by the child. */
    fflush(NULL);
    pid_t parent = getpid();
    job->pid = fork();
    if (job->pid == 0) child_exec(argv, log, parent);
    if (job->pid > 0) setpgid(job->pid, job->pid);  /* from both sides: no race with a first kill */
    return job->pid > 0;
}

/* The part's entry of a facts.json bin/grade wrote (a new reference), or NULL when the file is
 * missing or not what it should be: schema pathlab-grade-facts/1, exactly this part, a score. */
static json_t *facts_part(const char *path, int part)
{
    /* Read bounded and checked: bin/grade wrote it, but a unit folder may be an older run's. */
    char *text;
    size_t len;
    if (file_read_all(path, "facts", CLASS_FACTS_MAX, &text, &len, NULL) != PL_OK) return NULL;
    json_t *root = json_loadb(text, len, JSON_REJECT_DUPLICATES, NULL);
    free(text);
    json_t *p = json_array_get(json_object_get(root, "parts"), 0);
    const char *schema = json_string_value(json_object_get(root, "schema"));
    bool ok = schema && !strcmp(schema, "pathlab-grade-facts/1") && json_array_size(json_object_get(root, "parts")) == 1 &&
              json_integer_value(json_object_get(p, "part")) == part && json_is_number(json_object_get(p, "score")) &&
              json_is_number(json_object_get(p, "max_score"));
    if (ok) json_incref(p);
    json_decref(root);
    return ok ? p : NULL;
}

json_t *class_unit_facts(const class_run *r, const class_student *s, const class_unit *u)
{
    char path[1600];
    class_unit_folder(r, s, u, path, sizeof path);
    strcat(path, "/facts.json");
    return strcmp(u->status, "graded") ? NULL : facts_part(path, u->part);
}

/* The outcome of the ended grading into u; false when it is the course's problem. */
static bool outcome(const class_run *r, class_unit *u, const class_job *job, int status, bool timed_out)
{
    char facts[1500];
    snprintf(facts, sizeof facts, "%s/facts.json", job->tmp);
    u->why[0] = '\0';
    u->score = 0.0;
    u->max_score = r->part_max[u->part - 1];
    bool exited = WIFEXITED(status);
    json_t *p;
    if (timed_out) {
        snprintf(u->status, sizeof u->status, "timed_out");
        snprintf(u->why, sizeof u->why, "its grading ran past %d s (--timeout) and was stopped", r->o->timeout);
    }
    else if (exited && (WEXITSTATUS(status) == 2 || WEXITSTATUS(status) == 3 || WEXITSTATUS(status) >= 126))
        return false;  /* the course's cases or set-up, or bin/grade could not be run at all (126, 127) */
    else if (exited && WEXITSTATUS(status) <= 1 && (p = facts_part(facts, u->part))) {
        snprintf(u->status, sizeof u->status, "graded");
        u->score = json_number_value(json_object_get(p, "score"));
        u->max_score = json_number_value(json_object_get(p, "max_score"));
        json_decref(p);
    }
    else {
        snprintf(u->status, sizeof u->status, "grader_failed");
        if (exited) snprintf(u->why, sizeof u->why, "bin/grade exited with status %d without its facts.json", WEXITSTATUS(status));
        else snprintf(u->why, sizeof u->why, "bin/grade was killed by signal %d", WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    }
    return true;
}

bool class_unit_finish(const class_run *r, class_student *s, int u, class_job *job, int status, bool timed_out)
{
    class_unit *unit = &s->units[u];
    char path[1500], final[1500], log[1500];
    snprintf(log, sizeof log, "%s.log", job->tmp);
    if (!outcome(r, unit, job, status, timed_out)) {
        fprintf(stderr, "\ngrade-class: bin/grade stopped on the course's own problem (exit %d) grading %s part %d; "
                        "nothing is recorded for it. Its output: %s\n", WEXITSTATUS(status), s->shown, unit->part, log);
        return false;
    }
    /* The grader's scratch goes; its log joins the unit; the unit moves into place whole. */
    snprintf(path, sizeof path, "%s/work", job->tmp);
    class_remove_tree(path);
    mkdir(job->tmp, 0700);  /* a grading stopped before it made its folder */
    snprintf(path, sizeof path, "%s/grade.log", job->tmp);
    rename(log, path);
    if (!class_record_unit_write(unit, job->tmp)) fprintf(stderr, "\ngrade-class: cannot write %s/unit.json\n", job->tmp);
    snprintf(path, sizeof path, "%s/students/%s", r->o->out, s->folder);
    mkdir(path, 0755);
    class_unit_folder(r, s, unit, final, sizeof final);
    class_remove_tree(final);  /* the same key, graded before its record was written */
    if (rename(job->tmp, final) != 0) {
        fprintf(stderr, "\ngrade-class: cannot move %s to %s: %s\n", job->tmp, final, strerror(errno));
        unit->status[0] = '\0';
        class_remove_tree(job->tmp);
        return true;
    }
    unit->current = strcmp(unit->status, "grader_failed") != 0;
    return true;
}

/* Instructor tooling: not part of any assignment.
 * The pool: every unit that is not current, `jobs` gradings at a time, in the students' order (so
 * records are written as the run goes), with a progress line on stderr:
 *   grade-class: 12/40 students (1 failed), 27 left, 4 running; 3 min gone, about 8 min to go
 * A student's record is written as soon as their last unit ended. A grading over --timeout gets
 * SIGTERM (bin/grade's janitor stops its stages and removes its sandbox), and SIGKILL for its whole
 * process group 30 s later. Ctrl-C, SIGTERM or SIGHUP stop the run the same way: every grading
 * running is stopped and left out (graded on the next run), every record already written stays. */
#include "class.h"
#include "../../framework/clock.h"
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define POOL_GRACE 30.0    /* seconds between SIGTERM and SIGKILL: bin/grade's janitor cleans up */

static volatile sig_atomic_t pool_stop;
static void on_stop(int sig) { pool_stop = sig; }

typedef struct {
    int student, unit;
    class_job job;
    bool timed_out;
    double term_at;        /* when SIGTERM was sent (0: not yet) */
} slot;

typedef struct {
    class_run *r;
    int (*todo)[2];        /* (student, unit) pairs to grade */
    int num_todo, next, running, units_done;
    int students_total, students_done, students_failed;
    slot *slots;
    double start;
    bool course_failed;
} pool;

/* ---- the progress line ---------------------------------------------------------------------- */

static void progress(const pool *p)
{
    /* Time to go: the mean time a part took so far, times the parts left (started ones included). */
    double gone = clock_seconds() - p->start;
    double to_go = p->units_done ? gone / p->units_done * (p->num_todo - p->units_done) : 0.0;
    bool tty = isatty(2);
    fprintf(stderr, "%sgrade-class: %d/%d students (%d failed), %d left, %d running; %.0f min gone, about %.0f min to go%s",
            tty ? "\r" : "", p->students_done, p->students_total, p->students_failed,
            p->students_total - p->students_done, p->running, gone / 60.0, to_go / 60.0, tty ? "\033[K" : "\n");
}

/* ---- the queue -------------------------------------------------------------------------------- */

static bool student_failed(const class_student *s)
{
    for (int u = 0; u < s->num_units; u++)
        if (strcmp(s->units[u].status, "graded")) return true;
    return false;
}

/* The units to grade: each student's units that are not current, students in order. */
static bool queue(pool *p)
{
    /* A Slurm task queues its own student only (r->only); a refused student has no unit. */
    class_run *r = p->r;
    int n = 0;
    p->todo = malloc((size_t)r->num_students * GRADE_MAX_PART * sizeof *p->todo);
    if (!p->todo) return false;
    for (int i = 0; i < r->num_students; i++) {
        const class_student *s = &r->students[i];
        if ((r->only >= 0 && i != r->only) || strcmp(s->status, "ok")) continue;
        int before = n;
        for (int u = 0; u < s->num_units; u++)
            if (!s->units[u].current) p->todo[n][0] = i, p->todo[n++][1] = u;
        p->students_total += n > before;
    }
    p->num_todo = n;
    return true;
}

/* ---- the gradings ----------------------------------------------------------------------------- */

static void start_next(pool *p)
{
    for (int k = 0; k < p->r->o->jobs && p->next < p->num_todo; k++) {
        /* A free slot takes the next unit; its student's part folders are staged already (prepare). */
        slot *sl = &p->slots[k];
        if (sl->job.pid > 0) continue;
        memset(sl, 0, sizeof *sl);
        sl->student = p->todo[p->next][0], sl->unit = p->todo[p->next][1];
        p->next++;
        class_student *s = &p->r->students[sl->student];
        char stage[1400];
        snprintf(stage, sizeof stage, "%s/%s", p->r->stage, s->folder);
        if (!class_unit_start(p->r, s, sl->unit, stage, &sl->job)) {
            fprintf(stderr, "\ngrade-class: cannot start bin/grade: %s\n", strerror(errno));
            p->course_failed = true;
            return;
        }
        sl->job.start = clock_seconds();
        p->running++;
    }
}

/* A grading over its time, or every grading when the run is stopped: SIGTERM, then SIGKILL. */
static void enforce(pool *p, double now)
{
    for (int k = 0; k < p->r->o->jobs; k++) {
        slot *sl = &p->slots[k];
        if (sl->job.pid <= 0) continue;
        if (!sl->term_at && (pool_stop || now - sl->job.start > p->r->o->timeout)) {
            sl->timed_out = !pool_stop;
            sl->term_at = now;
            kill(sl->job.pid, SIGTERM);
        }
        else if (sl->term_at && now - sl->term_at > POOL_GRACE)
            kill(-sl->job.pid, SIGKILL);
    }
}

/* A grading ended: its unit, and the student's record when it was their last. */
static void ended(pool *p, slot *sl, int status)
{
    class_student *s = &p->r->students[sl->student];
    p->running--;
    sl->job.pid = 0;
    if (pool_stop) {  /* stopped from outside: left for the next run */
        class_remove_tree(sl->job.tmp);
        return;
    }
    if (!class_unit_finish(p->r, s, sl->unit, &sl->job, status, sl->timed_out)) p->course_failed = true;
    p->units_done++;
    if (class_record_complete(s)) {
        class_record_write(p->r, s);
        p->students_done++;
        p->students_failed += student_failed(s);
        progress(p);
    }
}

/* Waits for the next grading to end (polling: timeouts are checked between). */
static void reap(pool *p)
{
    /* Every child of this process is a grading: any that ended is one of the slots'. */
    int status;
    pid_t pid = waitpid(-1, &status, WNOHANG);
    if (pid <= 0) {
        nanosleep(&(struct timespec){0, 100000000}, NULL);
        enforce(p, clock_seconds());
        return;
    }
    for (int k = 0; k < p->r->o->jobs; k++)
        if (p->slots[k].job.pid == pid) ended(p, &p->slots[k], status);
}

bool class_pool_run(class_run *r)
{
    pool p = {.r = r, .start = clock_seconds()};
    p.slots = calloc((size_t)r->o->jobs, sizeof *p.slots);
    if (!p.slots || !queue(&p)) return free(p.slots), false;
    /* A stop request only sets a flag (no SA_RESTART: the poll's sleep returns); the loop stops the
     * gradings, waits for them, and leaves with what was recorded. */
    struct sigaction sa = {.sa_handler = on_stop}, old[3];
    const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
    for (int i = 0; i < 3; i++) sigaction(sigs[i], &sa, &old[i]);
    fprintf(stderr, "grade-class: %d part(s) of %d student(s) to grade, %d at a time\n", p.num_todo, p.students_total,
            r->o->jobs);
    /* After the course's own failure nothing new starts; the gradings running end as they would. */
    while (p.running > 0 || (p.next < p.num_todo && !pool_stop && !p.course_failed)) {
        if (!pool_stop && !p.course_failed) start_next(&p);
        reap(&p);
    }
    if (p.num_todo && isatty(2)) fputc('\n', stderr);
    for (int i = 0; i < 3; i++) sigaction(sigs[i], &old[i], NULL);
    free(p.slots);
    free(p.todo);
    if (pool_stop) fprintf(stderr, "grade-class: stopped by signal %d: what was graded is kept; run again to grade the rest\n",
                           (int)pool_stop);
    return !pool_stop && !p.course_failed;
}

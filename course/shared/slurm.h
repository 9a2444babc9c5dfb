/* Instructor tooling: not part of any assignment.
 * A Slurm job array with one command per task and a final job that runs once every task has
 * succeeded: how bin/references renders its ranges and merges them, and how bin/grade-class grades
 * a class and writes its grade book. Each task's command is a line of DIR/tasks.txt, every argument
 * quoted for the shell (a name with a quote or a `$` in it is passed as it is, never run), read by
 * DIR/array.sh for its SLURM_ARRAY_TASK_ID; the final command is DIR/final.sh. Both jobs start in
 * the current folder, which the cluster's nodes must share. */
#ifndef PL_COURSE_SLURM_H
#define PL_COURSE_SLURM_H
#include <stdbool.h>
#include <stdio.h>

typedef struct {
    char dir[600];        /* DIR: tasks.txt, array.sh, final.sh and the jobs' logs */
    FILE *tasks;          /* tasks.txt while tasks are added */
    int count;            /* tasks added */
} slurm_array;

typedef struct {
    char array_id[64];    /* the array's job id, "" when it had no task */
    char final_id[64];    /* the final job's id */
} slurm_ids;

/* Makes dir (and its parents) and starts its tasks.txt; false with a line on stderr. */
bool slurm_begin(slurm_array *a, const char *dir);
/* Adds one task: the command argv (NULL-terminated). */
bool slurm_add(slurm_array *a, char *const argv[]);
/* Submits the tasks as the array `name` (none: no array) and final_argv as the job `final_name`,
 * which waits for every task to succeed; sbatch_args (the instructor's, as typed, may be "") go to
 * both sbatch calls. Closes tasks.txt. False with a line on stderr when sbatch failed. */
bool slurm_submit(slurm_array *a, const char *name, char *const final_argv[], const char *final_name,
                  const char *sbatch_args, slurm_ids *ids);
/* Prints what the scheduler still holds of the jobs named names ("a,b"): pending or running tasks. */
void slurm_print_queue(const char *names);
/* Writes s to f quoted for a POSIX shell: '...' with every ' as '\''. */
void slurm_quote(FILE *f, const char *s);
#endif

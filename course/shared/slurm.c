/* Instructor tooling: not part of any assignment. A Slurm job array and its final job (slurm.h). */
#include "slurm.h"
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void slurm_quote(FILE *f, const char *s)
{
    /* Inside single quotes nothing is special but the quote itself, which ends, is escaped, reopens. */
    fputc('\'', f);
    for (; *s; s++)
        if (*s == '\'') fputs("'\\''", f);
        else fputc(*s, f);
    fputc('\'', f);
}

/* mkdir -p: each missing folder of path, in turn. */
static bool make_dirs(const char *path)
{
    char p[600];
    snprintf(p, sizeof p, "%s", path);
    for (char *s = p + 1; *s; s++)
        if (*s == '/') {
            *s = '\0';
            if (mkdir(p, 0755) != 0 && errno != EEXIST) return false;
            *s = '/';
        }
    return mkdir(p, 0755) == 0 || errno == EEXIST;
}

bool slurm_begin(slurm_array *a, const char *dir)
{
    memset(a, 0, sizeof *a);
    snprintf(a->dir, sizeof a->dir, "%s", dir);
    char tasks[700];
    snprintf(tasks, sizeof tasks, "%s/tasks.txt", dir);
    if (!make_dirs(dir) || !(a->tasks = fopen(tasks, "w"))) {
        fprintf(stderr, "slurm: cannot write %s\n", tasks);
        return false;
    }
    return true;
}

/* One command line: each argument quoted, so that a task runs exactly the argv it was given. */
static void write_command(FILE *f, char *const argv[])
{
    for (int i = 0; argv[i]; i++) {
        if (i) fputc(' ', f);
        slurm_quote(f, argv[i]);
    }
    fputc('\n', f);
}

bool slurm_add(slurm_array *a, char *const argv[])
{
    write_command(a->tasks, argv);
    a->count++;
    return !ferror(a->tasks);
}

/* Runs one sbatch command line and keeps the job id it prints (--parsable: "id" or "id;cluster"). */
static bool sbatch(const char *line, char id[64])
{
    /* The line is ours, every value quoted; the instructor's own sbatch arguments go as typed. */
    FILE *p = popen(line, "r");
    id[0] = '\0';
    if (!p || !fgets(id, 64, p)) {
        if (p) pclose(p);
        fprintf(stderr, "slurm: sbatch failed: %s\n", line);
        return false;
    }
    id[strcspn(id, ";\n")] = '\0';
    return pclose(p) == 0 && id[0];
}

/* A shell script of ours: the header written here, the body by the caller, then close_script. */
static FILE *open_script(const char *path, const char *what)
{
    FILE *f = fopen(path, "w");
    if (f) fprintf(f, "#!/bin/sh\n# Written by a pathlab course tool (course/shared/slurm.c): %s.\n", what);
    return f;
}

static bool close_script(FILE *f, const char *path) { return fclose(f) == 0 && chmod(path, 0755) == 0; }

/* "sbatch --parsable --chdir=CWD --job-name=NAME --output=LOG" then the rest, each value quoted. */
static char *sbatch_line(const char *cwd, const char *name, const char *log, const char *extra, const char *args,
                         const char *script)
{
    /* Built in memory: the course root's and the folder's paths may be long. */
    char *line = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&line, &size);
    if (!f) return NULL;
    fputs("sbatch --parsable --chdir=", f), slurm_quote(f, cwd);
    fputs(" --job-name=", f), slurm_quote(f, name);
    fputs(" --output=", f), slurm_quote(f, log);
    fprintf(f, " %s %s ", extra, args);
    slurm_quote(f, script);
    fclose(f);
    return line;
}

bool slurm_submit(slurm_array *a, const char *name, char *const final_argv[], const char *final_name,
                  const char *sbatch_args, slurm_ids *ids)
{
    char cwd[1024], path[700], tasks[700], log[700], extra[160];
    /* tasks.txt complete (a short write fails the submission), and the folder the jobs start in. */
    memset(ids, 0, sizeof *ids);
    bool ok = fclose(a->tasks) == 0;
    a->tasks = NULL;
    if (!ok || !getcwd(cwd, sizeof cwd)) return false;
    /* The array: each task runs its line of tasks.txt. */
    if (a->count > 0) {
        /* SLURM_ARRAY_TASK_ID counts from 0, sed's lines from 1. */
        snprintf(path, sizeof path, "%s/array.sh", a->dir);
        snprintf(tasks, sizeof tasks, "%s/tasks.txt", a->dir);
        FILE *f = open_script(path, "one task's command, its line of tasks.txt");
        if (!f) return false;
        fputs("line=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" ", f);
        slurm_quote(f, tasks);
        fputs(")\neval \"exec $line\"\n", f);
        snprintf(log, sizeof log, "%s/task-%%a.log", a->dir);
        snprintf(extra, sizeof extra, "--array=0-%d", a->count - 1);
        char *line = close_script(f, path) ? sbatch_line(cwd, name, log, extra, sbatch_args, path) : NULL;
        ok = line && sbatch(line, ids->array_id);
        free(line);
        if (!ok) return false;
    }
    /* The final job, once every task succeeded. */
    snprintf(path, sizeof path, "%s/final.sh", a->dir);
    FILE *f = open_script(path, "runs after every task");
    if (!f) return false;
    fputs("exec ", f);
    write_command(f, final_argv);
    if (!close_script(f, path)) return false;
    /* afterok: the final job runs only if every task succeeded; with no task it runs at once. */
    snprintf(log, sizeof log, "%s/final.log", a->dir);
    snprintf(extra, sizeof extra, "%s%s", ids->array_id[0] ? "--dependency=afterok:" : "", ids->array_id);
    char *line = sbatch_line(cwd, final_name, log, extra, sbatch_args, path);
    ok = line && sbatch(line, ids->final_id);
    free(line);
    return ok;
}

void slurm_print_queue(const char *names)
{
    if (system("command -v squeue >/dev/null 2>&1") != 0) return;
    printf("queued on Slurm (job, task, state):\n");
    fflush(stdout);
    char line[400];
    snprintf(line, sizeof line, "squeue -h -n '%s' -o '  %%i %%j %%T' 2>/dev/null", names);
    if (system(line) != 0) printf("  (squeue failed: no cluster reachable)\n");
}

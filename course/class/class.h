/* Instructor tooling: not part of any assignment.
 * bin/grade-class: a whole class graded the way the autograder grades one submission, on this
 * machine or as a Slurm job array, into a grade book (CSV) and a class report (HTML).
 * course/class/README.md maps the modules in the order data flows through them:
 *   intake  (class_intake.c)  the submissions folder and the roster: one student per folder or .zip
 *   unpack  (class_unpack.c)  a submission's part folders copied or extracted, every entry checked
 *   seed    (class_seed.c)    the course secret and each student's seed
 *   keys    (class_key.c)     what each graded part was made from: the rule that decides a re-grade
 *   units   (class_unit.c)    one part of one student graded by bin/grade, kept whole or not at all
 *   pool    (class_pool.c)    units N at a time with a progress line; Ctrl-C and kill stop cleanly
 *   record  (class_record.c)  a student's record: the units that make their grade
 *   book    (class_book.c)    the grade book, Canvas's import layout
 *   report  (class_report.c)  the class report: distributions, failure shares, first causes
 *   text    (class_text.c)    hostile bytes made safe to show: escaped names, HTML, CSV cells
 * Everything a submission names (a folder, a zip entry, a roster line) is hostile: it is shown only
 * escaped, never used as a path but through a folder name this tool made (class_intake.c). */
#ifndef PL_CLASS_H
#define PL_CLASS_H
#include "../../grader/grade_limits.h"
#include "../../grader/grade_run.h"
#include "../../grader/grade_spec.h"
#include <jansson.h>
#include <stdbool.h>
#include <stdint.h>

/* ---- limits, each with its reason ----------------------------------------------------------- */
#define CLASS_MAX_STUDENTS 4096          /* submissions in one folder: a large course has ~1,000 */
#define CLASS_NAME_MAX 256               /* bytes of a submission's name: NAME_MAX, and the folder's */
#define CLASS_ID_MAX 128                 /* bytes of a student's id (a roster's or a folder's name) */
#define CLASS_SHOWN_MAX (4 * CLASS_NAME_MAX + 1)  /* a name escaped: at most 4 characters a byte */
#define CLASS_ROSTER_LINE 4096           /* bytes of one roster line */
#define CLASS_ENTRIES 20000              /* entries listed in one submission: a repository clone has
                                            ~700, a zip with more is refused before anything is read */
#define CLASS_DEPTH 24                   /* folders deep: the course's deepest path has 4 */
#define CLASS_PATH_MAX 1024              /* bytes of one entry's path inside a submission */
#define CLASS_EXTRACT_BYTES (64L << 20)  /* bytes copied out of one submission (its part folders): the
                                            grader takes 32 files of 1 MiB a part, the course's are 150 KB */
#define CLASS_FILE_BYTES (2L << 20)      /* one file copied: twice the grader's own limit, which refuses it
                                            in its own words (grade.h, GRADE_SOURCE_BYTES) */
#define CLASS_FACTS_MAX (8L << 20)       /* a facts.json read back: a part's is ~30 KB */
#define CLASS_TIMEOUT 1200               /* seconds one part's grading may take: the slowest part takes
                                            ~30 s; a submission that hangs in every case takes ~15 min
                                            (bin/grade's own limits) */
#define CLASS_MEMORY_PER_GRADING (1L << 30)  /* what one grading may need: the largest case's render
                                                ~600 MB, the grader and the judge beside it */

/* ---- a student: one submission of the folder ------------------------------------------------ */
typedef struct {
    int part;                  /* 1..9 */
    char key[17];              /* what it is graded from (class_key.c), in hex */
    char status[16];           /* "graded", "timed_out", "grader_failed"; "" not graded yet */
    char why[160];             /* for a status other than graded: the class grader's own words */
    double score, max_score;
    bool current;              /* the record holds this key: nothing to grade */
} class_unit;

typedef struct {
    char entry[CLASS_NAME_MAX];      /* its name in the submissions folder, raw bytes */
    bool is_zip;
    char id[CLASS_ID_MAX];           /* the id the grade book uses (raw: shown only escaped) */
    char shown[CLASS_SHOWN_MAX];     /* the id escaped: valid UTF-8, no control characters */
    char name[CLASS_SHOWN_MAX];      /* the roster's name for the student, escaped; "" without one */
    char entry_shown[CLASS_SHOWN_MAX];  /* entry, escaped */
    char folder[80];                 /* its folder under students/: made by this tool, never the id */
    char status[24];                 /* "ok", or why it is not graded (class_intake.c lists them) */
    char why[600];                   /* the refusal in the class grader's words (names escaped) */
    char left_out[300];              /* entries not copied (links, devices), or "" */
    uint64_t seed;
    int num_units;
    class_unit units[GRADE_MAX_PART];
} class_student;

/* ---- the run's settings, filled once from the command line (class_main.c) ------------------- */
typedef struct {
    const char *submissions;   /* the folder of submissions */
    const char *out;           /* the results: gradebook.csv, report/, students/, work/ */
    const char *roster;        /* "SUBMISSION,ID[,NAME]" lines, or NULL: the id is the folder's name */
    const char *secret;        /* the course secret's file */
    char parts[2 * GRADE_MAX_PART + 1];  /* "1,2,3" */
    int jobs, threads;         /* gradings at once; each grading's render threads */
    int timeout;               /* seconds for one part's grading */
    bool slurm;
    const char *sbatch_args;
    const char *task;          /* --task INDEX:KEY (a Slurm array's task), or NULL */
    bool report_only;          /* --report-only: the grade book and report from the records */
    bool force;                /* grade every part again (a new key round) */
} class_options;

/* A class: the options, every student of the folder in name order, the course's keys per part. */
typedef struct {
    const class_options *o;
    class_student *students;
    int num_students;
    char ignored[600];                   /* entries of the folder that are no submission, escaped */
    uint64_t course_key[GRADE_MAX_PART]; /* class_key.c: the course's inputs of each part */
    double part_max[GRADE_MAX_PART];     /* each part's points, from grading/cases.json */
    grade_task tasks[GRADE_MAX_PART][GRADE_MAX_TASKS];  /* each part's tasks, for the book's columns */
    int num_tasks[GRADE_MAX_PART];
    char work[1200], stage[1300];        /* OUT/work and this process's staging folder */
    int only;                            /* a Slurm task's one student (its index), or -1: all */
} class_run;

/* ---- modules ---------------------------------------------------------------------------------- */
/* class_intake.c: reads the submissions folder (and the roster) into r->students; false with a
 * line on stderr when the folder or the roster cannot be read at all. */
bool class_intake(class_run *r);
/* class_unpack.c: copies (a folder) or extracts (a .zip) the student's part folders into
 * STAGE/parts/, every entry checked first; sets s->status and s->why when the submission is
 * refused. dest is created. */
void class_unpack(const class_run *r, class_student *s, const char *dest);
/* class_seed.c: the secret (created when missing), and every student's seed from it. */
bool class_seed_all(class_run *r);
/* class_key.c: the course's key per part (r->course_key), then each unit's key. */
bool class_key_course(class_run *r);
void class_key_units(const class_run *r, class_student *s, const char *stage);
/* class_unit.c: grades one unit (part u of student s, staged in stage) and puts it in place; false
 * when the course's own set-up failed (the run stops: never a student's 0). */
typedef struct { int pid; char tmp[1400]; double start; } class_job;
bool class_unit_start(const class_run *r, const class_student *s, int u, const char *stage, class_job *job);
bool class_unit_finish(const class_run *r, class_student *s, int u, class_job *job, int wait_status, bool timed_out);
void class_unit_folder(const class_run *r, const class_student *s, const class_unit *u, char *out, size_t size);
/* The graded unit's part entry of its facts.json (a new reference: json_decref it), or NULL. */
json_t *class_unit_facts(const class_run *r, const class_student *s, const class_unit *u);
/* Removes path and everything under it, never following a link. */
void class_remove_tree(const char *path);
/* class_pool.c: every unit not current, `jobs` at a time; false when stopped or the course failed. */
bool class_pool_run(class_run *r);
/* class_record.c: each unit's outcome (unit.json in its folder) and the student's record,
 * students/<folder>/record.json, written once all their units are there. */
void class_record_read(const class_run *r, class_student *s);
bool class_record_write(const class_run *r, const class_student *s);
bool class_record_complete(const class_student *s);
/* A unit's outcome into folder/unit.json (class_unit.c, before the folder moves into place). */
bool class_record_unit_write(const class_unit *u, const char *folder);
/* class_book.c, class_report.c: the grade book and the class report from the records and facts. */
bool class_book_write(const class_run *r);
bool class_report_write(const class_run *r);
#endif
